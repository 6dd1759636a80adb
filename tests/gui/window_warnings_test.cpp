// The run's warnings in the window (issue 16): a shear faster than the measured quasi-static
// limit shows in the status bar while the run goes on, every warning in its tooltip, the same
// list as the run file holds; an opened run file shows its own; a failing run names the last
// good checkpoint its folder keeps.
#include <QDir>

#include <gtest/gtest.h>

#include "grainlab/loading_rate.h"
#include "grainlab/run_file.h"
#include "grainlab/ui/warning_label.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

/// The small experiment sheared at twice the quasi-static inertial number.
ExperimentConfig fastExperiment() {
    const ExperimentConfig small = smallExperiment(0.003);
    auto j = nlohmann::ordered_json::parse(small.sourceText);
    j["shear"]["max_strain_rate"] = 20.0;
    j["shear"]["axial_strain_per_step"] = 2.0 * kQuasiStaticInertialNumber /
                                          shearInertialNumber(small, 15e3) *
                                          small.shear.axialStrainPerStep;
    return parseExperimentText(j.dump(2), small.sourcePath);
}

TEST(WindowWarnings, AFastShearIsWarnedAboutInTheStatusBarAndTheRunFileHasTheSame) {
    const QString runs = freshRunsFolder(QStringLiteral("warnings"));
    MainWindow w;
    showWith(w, fastExperiment());
    WarningLabel* label = w.warningLabel();
    ASSERT_NE(label, nullptr);
    EXPECT_FALSE(label->isVisible()); // nothing to warn about before the run
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return !label->warnings().empty(); }, 180000))
        << w.controller().status().error;
    EXPECT_TRUE(label->isVisible());
    EXPECT_TRUE(label->line().contains(QStringLiteral("inertial number")))
        << label->line().toStdString();
    EXPECT_TRUE(label->toolTip().contains(QStringLiteral("shear.axial_strain_per_step")))
        << label->toolTip().toStdString();
    ASSERT_TRUE(
        waitFor([&] { return w.controller().status().state == RunState::Finished; }, 180000))
        << w.controller().status().error;

    const QString folder = QString::fromStdString(w.controller().status().runFolder);
    const std::string runFile = QDir(folder).filePath(QStringLiteral("run.h5")).toStdString();
    const std::vector<RunWarning> stored = readWarnings(runFile);
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(label->warnings(), stored);

    // A run file opened in a new window shows its warnings.
    MainWindow other;
    other.show();
    EXPECT_TRUE(other.warningLabel()->warnings().empty());
    QString error;
    ASSERT_TRUE(other.openRunFolder(folder, &error)) << error.toStdString();
    EXPECT_EQ(other.warningLabel()->warnings(), stored);
    EXPECT_TRUE(other.warningLabel()->isVisible());
}

TEST(WindowWarnings, AFailingRunNamesTheLastGoodCheckpointOfItsFolder) {
    const QString runs = freshRunsFolder(QStringLiteral("failing"));
    auto j = nlohmann::ordered_json::parse(smallExperiment().sourceText);
    j["stability"]["max_overlap_fraction"] = 1e-4; // no compaction can respect it
    j["record"]["snapshot_step_interval"] = 200;
    MainWindow w;
    w.setExperiment(parseExperimentText(j.dump(2), "failing.json"));
    w.show();
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state == RunState::Failed; }, 180000));
    const RunStatus status = w.controller().status();
    const std::string runFile = QDir(QString::fromStdString(status.runFolder))
                                    .filePath(QStringLiteral("run.h5"))
                                    .toStdString();
    const std::vector<std::string> checkpoints = listCheckpoints(runFile);
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_NE(status.error.find("overlap"), std::string::npos) << status.error;
    EXPECT_NE(status.error.find("its last good checkpoint " + checkpoints.back()),
              std::string::npos)
        << status.error;
    EXPECT_NE(status.error.find("grainlab run --resume"), std::string::npos) << status.error;
}

} // namespace
} // namespace grainlab::ui
