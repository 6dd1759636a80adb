#include "stability/stability_figures_writer.h"

#include <filesystem>
#include <memory>

#include <QGuiApplication>

#include "grainlab/ui/figure_export.h"

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

} // namespace grainlab
