#include "report/checkpoint_picture.h"

#include <filesystem>

#include <QGuiApplication>
#include <QPainter>
#include <QString>

#include <fmt/format.h>

#include "common/run_file_view.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/scene_renderer.h"

namespace grainlab {

namespace fs = std::filesystem;

int runCheckpointPictureCommand(const CheckpointPictureOptions& o) {
    const fs::path runFile = fs::is_directory(o.run) ? fs::path(o.run) / "run.h5" : fs::path(o.run);
    if (!fs::exists(runFile)) {
        fmt::print(stderr, "grainlab export picture: {}: no run file\n", runFile.string());
        return 2;
    }
    if (fs::exists(o.out)) {
        fmt::print(stderr,
                   "grainlab export picture: --out {}: the file exists; give a new name (nothing "
                   "is overwritten)\n",
                   o.out);
        return 2;
    }
    ui::SceneOptions scene;
    if (o.colouring == "rotation") {
        scene.colouring = ui::GrainColouring::Rotation;
    } else if (o.colouring == "size") {
        scene.colouring = ui::GrainColouring::Size;
    } else if (o.colouring == "coordination") {
        scene.colouring = ui::GrainColouring::Coordination;
    } else if (o.colouring == "load-bearing") {
        scene.colouring = ui::GrainColouring::LoadBearing;
    } else {
        scene.colouring = ui::GrainColouring::Uniform;
    }
    scene.forceChains = o.chains == "all"      ? ui::ForceChains::All
                        : o.chains == "strong" ? ui::ForceChains::Strong
                                               : ui::ForceChains::Off;
    scene.voidCells = o.voidCells == "valence" ? ui::VoidCellShading::Valence
                      : o.voidCells == "area"  ? ui::VoidCellShading::Area
                                               : ui::VoidCellShading::Off;
    scene.rotationRange = o.rotationRange;

    const auto app = ui::headlessApplicationIfNone();
    ui::RunFileView file;
    try {
        file = ui::openRunFile(runFile.string());
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab export picture: {}\n", e.what());
        return 2;
    }
    const std::string name = runFile.filename().string() + ": " + o.test;
    const int index = ui::nearestCheckpoint(file, name, o.strain);
    if (index < 0) {
        std::string tests;
        for (const SeriesTable& t : file.series) {
            tests += (tests.empty() ? "" : ", ") + t.test.substr(t.test.find(": ") + 2);
        }
        fmt::print(stderr,
                   "grainlab export picture: {}: no checkpoint of test '{}' (its tests: {})\n",
                   runFile.string(), o.test, tests);
        return 2;
    }
    ui::SceneRenderer renderer;
    renderer.options() = scene;
    const SnapshotPtr snapshot = ui::runFileSnapshot(file, std::size_t(index));
    renderer.setSnapshot(snapshot);
    const QSize size(o.size, o.size);
    renderer.fitToCell(size);
    QString error;
    if (!ui::exportFigure(
            QString::fromStdString(o.out), size,
            [&](QPainter& p, QSize s) { renderer.render(p, s); }, &error)) {
        fmt::print(stderr, "grainlab export picture: {}\n", error.toStdString());
        return 1;
    }
    fmt::print("grainlab export picture: {} at eps1 = {:.6g} ({}), {} x {} pixels: {}\n", o.test,
               snapshot->axialStrain, file.checkpoints[std::size_t(index)], o.size, o.size, o.out);
    return 0;
}

} // namespace grainlab
