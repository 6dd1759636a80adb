// Format versions of the run file: a file of format 2 (the layout before contacts, void-cell
// polygons and peak checkpoints) still reads, without what it lacks; it is not continued; a
// newer format is refused by name.
#include <H5Cpp.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"
#include "grainlab/void_cells.h"
#include "refusal.h"
#include "scratch_folder.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kExperiment = "{\"name\": \"format\", \"seed\": 5}";

fs::path scratch(const std::string& name) {
    return test::scratchFolder("format", name);
}

/// A run file with one series and one full checkpoint (contacts, void cells, outlines).
std::string writeRunFile(const fs::path& dir, SimulationState& state) {
    const std::string path = (dir / "run.h5").string();
    RunFile file(path, kExperiment);
    SeriesTable t;
    t.test = "p015kPa";
    t.columns = {{"step", "-"}, {"q_over_p", "-"}};
    for (int k = 0; k < 5; ++k) {
        t.rows.push_back({100.0 * k, 0.1 * k});
        t.stages.push_back("shear 15 kPa");
        t.stageKinds.push_back("shear");
        t.stagePressures.push_back(15e3);
    }
    file.record(t);
    scenes::CompactedSceneSpec spec;
    spec.grains = 100;
    spec.aspectRatio = 0.6;
    spec.pressure = 5e4;
    const Simulation sim(scenes::compactedState(spec)); // dense: void cells
    state = sim.state();
    const ContactNetwork network = sim.contactNetwork();
    const VoidCellSet cells = computeVoidCells(network);
    CheckpointData data;
    data.name = "000001-shear-15-kPa-step600";
    data.state = &state;
    data.runnerState = "{\"phase\": 2}";
    data.identity.kind = "shear";
    data.identity.test = "p015kPa";
    data.identity.pressure = 15e3;
    data.identity.thetaAtTestStart = state.grains.theta;
    data.network = &network;
    data.voidCells = &cells;
    file.checkpoint(data);
    return path;
}

void setVersion(H5::H5File& file, std::int32_t version) {
    H5::Group root = file.openGroup("/");
    root.removeAttr("format_version");
    root.createAttribute("format_version", H5::PredType::STD_I32LE, H5::DataSpace(H5S_SCALAR))
        .write(H5::PredType::NATIVE_INT32, &version);
}

TEST(RunFileFormat, FormatTwoFilesStillRead) {
    const fs::path dir = scratch("two");
    SimulationState state;
    const std::string path = writeRunFile(dir, state);
    const std::string name = "000001-shear-15-kPa-step600";
    ASSERT_FALSE(readContacts(path, name).first.empty());
    {
        // What format 3 added, taken away: the layout of format 2.
        H5::H5File file(path, H5F_ACC_RDWR);
        H5::Group cp = file.openGroup(checkpointGroup(name));
        for (const char* link : {"contacts", "shape_outline1", "shape_outline2"}) {
            cp.unlink(link);
        }
        cp.removeAttr("peak");
        H5::Group cells = cp.openGroup("void_cells");
        for (const char* link : {"second_moment11", "second_moment22", "second_moment12",
                                 "vertices1", "vertices2", "vertex_offsets"}) {
            cells.unlink(link);
        }
        setVersion(file, 2);
    }
    const std::vector<CheckpointInfo> infos = listCheckpointInfo(path);
    ASSERT_EQ(infos.size(), 1u);
    EXPECT_EQ(infos[0].stageKind, "shear");
    EXPECT_FALSE(infos[0].peak);
    EXPECT_TRUE(identicalDynamics(readState(path, checkpointGroup(name)), state));
    EXPECT_EQ(readRunnerState(path, checkpointGroup(name)), "{\"phase\": 2}");
    EXPECT_EQ(readSeries(path, "p015kPa").rows.size(), 5u);
    EXPECT_TRUE(readContacts(path, name).first.empty());
    const StoredVoidCells v = readVoidCells(path, name);
    EXPECT_EQ(v.valence.size(), computeVoidCells(Simulation(state).contactNetwork()).cells.size());
    EXPECT_FALSE(v.valence.empty());
    EXPECT_TRUE(v.vertices1.empty());
    EXPECT_TRUE(v.secondMoment11.empty());
    // Not continued: its checkpoints have no running peak of q/p to continue.
    ASSERT_NO_FATAL_FAILURE(test::expectRefusedNaming(
        [&] { RunFile file(path, kExperiment, RunFile::Mode::Resume); },
        {path, "version 2", "continues version 3 only"}, "a format 2 file was continued"));
    fs::remove_all(dir);
}

TEST(RunFileFormat, NewerFormatsAreRefusedByName) {
    const fs::path dir = scratch("four");
    SimulationState state;
    const std::string path = writeRunFile(dir, state);
    {
        H5::H5File file(path, H5F_ACC_RDWR);
        setVersion(file, 4);
    }
    ASSERT_NO_FATAL_FAILURE(test::expectRefusedNaming([&] { listCheckpointInfo(path); },
                                                      {"version 4", "reads versions 2 to 3"},
                                                      "a format 4 file was read"));
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
