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

std::string writeStabilityFiguresHeadless(const std::string& folder, const StabilityMapSpec& spec,
                                          const std::vector<StabilityCellResult>& results) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    const QString figures =
        QString::fromStdString((std::filesystem::path(folder) / "figures").string());
    ui::writeStabilityFigures(figures, spec, results, &error);
    return error.toStdString();
}

std::string writeServoFiguresHeadless(const std::string& folder, const ServoMapSpec& spec,
                                      const std::vector<ServoCellResult>& results) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    ui::writeServoFigures(
        QString::fromStdString((std::filesystem::path(folder) / "figures").string()), spec, results,
        kMaxServoGain, &error);
    return error.toStdString();
}

std::string writeGeometryFiguresHeadless(const std::string& folder, const GeometryMapSpec& spec,
                                         const std::vector<GeometryLevel>& levels) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    ui::writeGeometryFigures(
        QString::fromStdString((std::filesystem::path(folder) / "figures").string()), spec, levels,
        StabilityParameters{}.maxOverlapFraction, &error);
    return error.toStdString();
}

} // namespace grainlab
