#include "stability/stability_figures_writer.h"

#include <filesystem>
#include <memory>

#include <QGuiApplication>

#include "grainlab/ui/stability_figures.h"

namespace grainlab {

std::string writeStabilityFiguresHeadless(const std::string& folder, const StabilityMapSpec& spec,
                                          const std::vector<StabilityCellResult>& results) {
    std::unique_ptr<QGuiApplication> app;
    if (!QCoreApplication::instance()) {
        // Figures need fonts, not a screen: the offscreen platform works everywhere.
        qputenv("QT_QPA_PLATFORM", "offscreen");
        static int argc = 1;
        static char name[] = "grainlab";
        static char* argv[] = {name, nullptr};
        app = std::make_unique<QGuiApplication>(argc, argv);
    }
    QString error;
    const QString figures =
        QString::fromStdString((std::filesystem::path(folder) / "figures").string());
    ui::writeStabilityFigures(figures, spec, results, &error);
    return error.toStdString();
}

} // namespace grainlab
