// A run started in the window is recorded: it writes a run folder as `grainlab run` does (run.h5
// and one series.csv per test) under the runs folder, never over another run, holding the
// experiment as edited in the Parameters tab; Stop leaves it resumable; Save experiment as…
// writes that same experiment text, which the experiment-file reader reads back.
#include <filesystem>

#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <gtest/gtest.h>

#include "common/atomic_file.h"
#include "cli/run_output.h"
#include "grainlab/csv_series.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"
#include "grainlab/ui/parameters_panel.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using window_tests::click;
using window_tests::smallExperiment;
using window_tests::waitFor;

/// An empty folder test-runs/<name> in the working folder.
QString freshFolder(const QString& name) {
    QDir dir(QDir::current().filePath(QStringLiteral("test-runs/") + name));
    dir.removeRecursively();
    return dir.path();
}

QStringList runFolders(const QString& runs) {
    return QDir(runs).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
}

RunState state(MainWindow& w) {
    return w.controller().status().state;
}

TEST(WindowRun, IsRecordedInANewRunFolderWithTheEditedExperiment) {
    // Only the runs folder's variable and the window's controls: this test builds on the old
    // window too, where it finds no run folder.
    const QString runs = freshFolder(QStringLiteral("recorded"));
    qputenv("GRAINLAB_RUNS_DIR", runs.toUtf8());
    MainWindow w;
    w.setExperiment(smallExperiment());
    w.resize(1400, 900);
    w.show();
    w.parametersPanel()->frictionEdit()->setValue(0.3);
    w.parametersPanel()->strainTargetEdit()->setValue(0.4);
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Finished; }, 180000))
        << w.controller().status().error;

    const QStringList folders = runFolders(runs);
    ASSERT_EQ(folders.size(), 1) << folders.join(QStringLiteral(", ")).toStdString();
    const QString folder = QDir(runs).filePath(folders.front());
    const std::string runFile = QDir(folder).filePath(QStringLiteral("run.h5")).toStdString();
    ASSERT_TRUE(std::filesystem::exists(runFile)) << runFile;

    // The stored experiment is the edited one, and the reader accepts it.
    const ExperimentConfig stored = parseExperimentText(readExperimentText(runFile), runFile);
    EXPECT_EQ(stored.shear.friction, 0.3);
    EXPECT_EQ(stored.shear.targetAxialStrain, 0.004);
    EXPECT_EQ(stored.assembly.grainCount, 120);
    EXPECT_EQ(stored.compaction.pressures, (std::vector<double>{15e3}));

    // Its series are the window's, in the run file and in the CSVs.
    const SnapshotPtr live = w.controller().latestSnapshot();
    ASSERT_TRUE(live);
    const auto tests = listTests(runFile);
    ASSERT_EQ(tests.size(), live->series.size());
    for (const SeriesTable& shown : live->series) {
        const SeriesTable file = readSeries(runFile, shown.test);
        ASSERT_EQ(file.rows.size(), shown.rows.size()) << shown.test;
        EXPECT_EQ(file.rows, shown.rows) << shown.test;
        EXPECT_EQ(file.stages, shown.stages) << shown.test;
        const SeriesTable csv =
            readSeriesCsv(QDir(folder)
                              .filePath(QString::fromStdString(shown.test) + "/series.csv")
                              .toStdString());
        ASSERT_EQ(csv.rows.size(), shown.rows.size()) << shown.test;
        const int eps1 = csv.column("eps1"), step = csv.column("step");
        ASSERT_GE(eps1, 0);
        for (std::size_t r = 0; r < csv.rows.size(); ++r) {
            ASSERT_EQ(csv.rows[r][step], shown.rows[r][shown.column("step")]);
            ASSERT_NEAR(csv.rows[r][eps1], shown.rows[r][shown.column("eps1")], 1e-12);
        }
    }
    const SeriesTable shear = readSeries(runFile, "p015kPa");
    EXPECT_NEAR(shear.rows.back()[shear.column("eps1")], 0.004, 1e-5);

    // A second run gets a folder of its own: the first one is not touched.
    const auto firstSize = std::filesystem::file_size(runFile);
    const auto firstTime = std::filesystem::last_write_time(runFile);
    ASSERT_TRUE(waitFor([&] { return w.startAction()->isEnabled(); }));
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return runFolders(runs).size() == 2; }));
    QString second = QDir(runs).filePath(runFolders(runs).back());
    if (second == folder) {
        second = QDir(runs).filePath(runFolders(runs).front());
    }
    // (The folder is made by the new run, after its step count was reset.)
    ASSERT_TRUE(waitFor([&] { return w.controller().status().stepsDone > 2000; }));
    click(w, w.stopAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Idle; }));
    EXPECT_EQ(std::filesystem::file_size(runFile), firstSize);
    EXPECT_EQ(std::filesystem::last_write_time(runFile), firstTime);

    // Stopped, the second run is resumable headless from its interrupted checkpoint (what
    // `grainlab run --resume FOLDER` reads), and runs to the end.
    const std::string secondFile = QDir(second).filePath(QStringLiteral("run.h5")).toStdString();
    const auto checkpoints = listCheckpoints(secondFile);
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_NE(checkpoints.back().find("interrupted"), std::string::npos) << checkpoints.back();
    const ExperimentConfig again = parseExperimentText(readExperimentText(secondFile), secondFile);
    ResumePoint point = RunOutputFolder::readResumePoint(second.toStdString());
    RunOutputFolder output(second.toStdString(), again.sourceText, true);
    ExperimentRunner resumed(again, std::move(point), &output);
    while (resumed.advance(5000)) {
    }
    const SeriesTable resumedShear = readSeries(secondFile, "p015kPa");
    EXPECT_NEAR(resumedShear.rows.back()[resumedShear.column("eps1")], 0.004, 1e-5);
    qunsetenv("GRAINLAB_RUNS_DIR");
}

TEST(WindowRun, SaveExperimentAsWritesWhatTheRunRecords) {
    const QString runs = freshFolder(QStringLiteral("saved"));
    MainWindow w;
    w.setRunsFolder(runs);
    const ExperimentConfig base = smallExperiment();
    w.setExperiment(base);
    w.show();

    // Nothing edited: the file's own text.
    const QString unedited = QDir(runs).filePath(QStringLiteral("unedited.json"));
    QDir().mkpath(runs);
    QString error;
    ASSERT_TRUE(w.saveExperimentAs(unedited, &error)) << error.toStdString();
    EXPECT_EQ(readWholeFile(unedited.toStdString()), base.sourceText);

    ParametersPanel* p = w.parametersPanel();
    p->grainCountEdit()->setValue(150);
    p->frictionEdit()->setValue(0.25);
    p->strainTargetEdit()->setValue(0.3);
    ASSERT_TRUE(p->valid());
    const QString saved = QDir(runs).filePath(QStringLiteral("edited.json"));
    ASSERT_TRUE(w.saveExperimentAs(saved, &error)) << error.toStdString();
    const ExperimentConfig read = readExperimentFile(saved.toStdString());
    const ExperimentConfig edited = p->applied();
    EXPECT_EQ(read.assembly.grainCount, 150);
    EXPECT_EQ(read.shear.friction, edited.shear.friction);
    EXPECT_EQ(read.shear.targetAxialStrain, edited.shear.targetAxialStrain);
    EXPECT_EQ(read.shear.pressures, edited.shear.pressures);
    // Everything else is the base experiment's.
    EXPECT_EQ(read.name, base.name);
    EXPECT_EQ(read.assembly.seed, base.assembly.seed);
    EXPECT_EQ(read.assembly.widths, base.assembly.widths);
    EXPECT_EQ(read.compaction.pressures, base.compaction.pressures);
    EXPECT_EQ(read.parameters.timeStep, base.parameters.timeStep);
    EXPECT_EQ(read.parameters.threads, base.parameters.threads);
    EXPECT_EQ(read.record.strainInterval, base.record.strainInterval);
    EXPECT_EQ(read.shear.axialStrainPerStep, base.shear.axialStrainPerStep);

    // A folder that holds files is refused, and left as it was.
    const QString taken = QDir(runs).filePath(QStringLiteral("taken"));
    QDir().mkpath(taken);
    const std::string keep = QDir(taken).filePath(QStringLiteral("notes.txt")).toStdString();
    writeFileAtomically(keep, "mine\n");
    w.setNextRunFolder(taken);
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Failed; }));
    EXPECT_NE(w.controller().status().error.find("not empty"), std::string::npos)
        << w.controller().status().error;
    EXPECT_EQ(QDir(taken).entryList(QDir::Files), QStringList{QStringLiteral("notes.txt")});
    EXPECT_EQ(readWholeFile(keep), "mine\n");

    // The run into a folder picked for it stores the saved text, byte for byte.
    const QString picked = QDir(runs).filePath(QStringLiteral("picked run"));
    w.setNextRunFolder(picked);
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().progress.step > 0; }));
    EXPECT_EQ(w.runFolder(), picked);
    w.refresh(); // the label follows the status on the window's timer
    EXPECT_TRUE(w.runFolderLabel()->text().contains(QDir::toNativeSeparators(picked)));
    click(w, w.stopAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Idle; }));
    const std::string runFile = QDir(picked).filePath(QStringLiteral("run.h5")).toStdString();
    EXPECT_EQ(readExperimentText(runFile), readWholeFile(saved.toStdString()));
    EXPECT_EQ(w.editedExperimentText().toStdString(), readWholeFile(saved.toStdString()));
    // The next run goes to a dated folder under the runs folder again.
    EXPECT_TRUE(w.runFolderLabel()->text().contains(QDir::toNativeSeparators(picked)));
}

} // namespace
} // namespace grainlab::ui
