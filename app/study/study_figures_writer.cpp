#include "study/study_figures_writer.h"

#include <filesystem>
#include <memory>

#include <QGuiApplication>

#include "grainlab/ui/figure_export.h"

#include "grainlab/ui/study_figures.h"

namespace grainlab {

std::string writeStudyFiguresHeadless(const std::string& studyFolder, const StudySpec& spec,
                                      const StudyPlan& plan, const std::vector<RunResult>& results,
                                      const StudySummary& summary) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    const QString folder =
        QString::fromStdString((std::filesystem::path(studyFolder) / "figures").string());
    ui::writeStudyFigures(folder, spec, plan, results, summary, &error);
    return error.toStdString();
}

} // namespace grainlab
