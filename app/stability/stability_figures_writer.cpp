#include "stability/stability_figures_writer.h"

#include <filesystem>
#include <memory>

#include <QGuiApplication>

#include "grainlab/experiment_limits.h"
#include "grainlab/simulation_state.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/geometry_figures.h"
#include "grainlab/ui/servo_figures.h"

#include "grainlab/ui/stability_figures.h"

namespace grainlab {

namespace {

/// Calls `write(figures, &error)` for the folder <folder>/figures with a Qt application running
/// (the offscreen one when none is); the error it sets, empty when none.
template <class Write>
std::string writeFiguresHeadless(const std::string& folder, Write write) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    write(QString::fromStdString((std::filesystem::path(folder) / "figures").string()), &error);
    return error.toStdString();
}

} // namespace

std::string writeStabilityFiguresHeadless(const std::string& folder, const StabilityMapSpec& spec,
                                          const std::vector<StabilityCellResult>& results) {
    return writeFiguresHeadless(folder, [&](const QString& figures, QString* error) {
        ui::writeStabilityFigures(figures, spec, results, error);
    });
}

std::string writeServoFiguresHeadless(const std::string& folder, const ServoMapSpec& spec,
                                      const std::vector<ServoCellResult>& results) {
    return writeFiguresHeadless(folder, [&](const QString& figures, QString* error) {
        ui::writeServoFigures(figures, spec, results, kMaxServoGain, error);
    });
}

std::string writeGeometryFiguresHeadless(const std::string& folder, const GeometryMapSpec& spec,
                                         const std::vector<GeometryLevel>& levels) {
    return writeFiguresHeadless(folder, [&](const QString& figures, QString* error) {
        ui::writeGeometryFigures(figures, spec, levels, StabilityParameters{}.maxOverlapFraction,
                                 error);
    });
}

} // namespace grainlab
