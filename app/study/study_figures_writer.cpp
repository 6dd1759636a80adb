#include "study/study_figures_writer.h"

#include <filesystem>
#include <memory>

#include <QGuiApplication>

#include "grainlab/ui/study_figures.h"

namespace grainlab {

std::string writeStudyFiguresHeadless(const std::string& studyFolder, const StudySpec& spec,
                                      const StudyPlan& plan, const std::vector<RunResult>& results,
                                      const StudySummary& summary) {
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
    const QString folder =
        QString::fromStdString((std::filesystem::path(studyFolder) / "figures").string());
    ui::writeStudyFigures(folder, spec, plan, results, summary, &error);
    return error.toStdString();
}

} // namespace grainlab
