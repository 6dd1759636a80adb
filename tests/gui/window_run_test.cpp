// A run started in the window is recorded: it writes a run folder as `grainlab run` does (run.h5
// and one series.csv per test) under the runs folder, never over another run, holding the
// experiment as edited in the Parameters tab; Stop leaves it resumable; Save experiment as…
// writes that same experiment text, which the experiment-file reader reads back.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <gtest/gtest.h>

#include "chart_index.h"
#include "cli/run_output.h"
#include "common/atomic_file.h"
#include "grainlab/csv_series.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/parameters_panel.h"
#include "grainlab/ui/scene_view.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

QStringList runFolders(const QString& runs) {
    return QDir(runs).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
}

RunState state(MainWindow& w) {
    return w.controller().status().state;
}

using testing::chartIndex;

/// Pixels of chart `chart`'s plot area (not its legend, whose swatch has the colours too) within
/// `tolerance` (sum over the channels) of `colour`, drawn as shown now.
int plotPixelsOf(ChartsPanel& charts, int chart, QColor colour, int tolerance) {
    const QImage image = charts.chartView(chart)->grab().toImage();
    const QRect plot = charts.chartView(chart)
                           ->mapFromScene(charts.chartView(chart)->chart()->plotArea())
                           .boundingRect()
                           .intersected(image.rect());
    if (plot.isEmpty()) {
        ADD_FAILURE() << "chart " << chart << " has no plot area on screen";
        return 0;
    }
    int n = 0;
    for (int y = plot.top(); y <= plot.bottom(); ++y) {
        for (int x = plot.left(); x <= plot.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                     std::abs(c.blue() - colour.blue()) <
                 tolerance;
        }
    }
    return n;
}

TEST(WindowRun, IsRecordedInANewRunFolderWithTheEditedExperiment) {
    // Only the runs folder's variable and the window's controls: this test builds on the old
    // window too, where it finds no run folder.
    const QString runs = freshRunsFolder(QStringLiteral("recorded"));
    MainWindow w;
    showWith(w, smallExperiment());
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

TEST(WindowRun, AConstantVolumeTestChosenInTheParametersRunsAndDrawsItsStressPath) {
    const QString runs = freshFolder(QStringLiteral("constant-volume"));
    MainWindow w;
    w.setRunsFolder(runs);
    showWith(w, smallExperiment(0.004));
    ParametersPanel* p = w.parametersPanel();
    // The slope is for a stress path only.
    EXPECT_FALSE(p->pathSlopeEdit()->isEnabled());
    p->testKindEdit()->setCurrentIndex(p->testKindEdit()->findData(QStringLiteral("stress_path")));
    EXPECT_TRUE(p->pathSlopeEdit()->isEnabled());
    p->pathSlopeEdit()->setValue(-0.5);
    EXPECT_NE(w.editedExperimentText().toStdString().find("\"slope\": -0.5"), std::string::npos)
        << w.editedExperimentText().toStdString();
    p->testKindEdit()->setCurrentIndex(
        p->testKindEdit()->findData(QStringLiteral("constant_volume")));
    EXPECT_FALSE(p->pathSlopeEdit()->isEnabled());
    // Extension is a tick away, and written as the test's direction.
    ASSERT_TRUE(p->extensionEdit()->isEnabled());
    p->extensionEdit()->setChecked(true);
    EXPECT_NE(w.editedExperimentText().toStdString().find("\"direction\": \"extension\""),
              std::string::npos)
        << w.editedExperimentText().toStdString();
    EXPECT_TRUE(p->applied().tests.at(0).extension);
    p->extensionEdit()->setChecked(false);
    ASSERT_TRUE(p->valid());
    ASSERT_EQ(p->applied().tests.size(), 1u);
    EXPECT_EQ(p->applied().tests[0].kind, LoadingPath::Kind::ConstantVolume);
    EXPECT_FALSE(p->applied().tests[0].extension);
    // What Save experiment as… writes reads back as the constant-volume test.
    const ExperimentConfig saved =
        parseExperimentText(w.editedExperimentText().toStdString(), "saved.json");
    ASSERT_EQ(saved.tests.size(), 1u);
    EXPECT_EQ(saved.tests[0].kind, LoadingPath::Kind::ConstantVolume);

    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Finished; }, 120000))
        << w.controller().status().error;
    w.refresh();
    const std::string test = "p015kPa-constant-volume";
    ASSERT_FALSE(w.sceneView()->snapshot()->series.empty());
    EXPECT_EQ(w.sceneView()->snapshot()->series.back().test, test);
    // The run file records the test's rows under its kind, at constant volume.
    const std::string runFile =
        QDir(w.runFolder()).filePath(QStringLiteral("run.h5")).toStdString();
    const SeriesTable t = readSeries(runFile, test);
    int rows = 0;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        if (t.stageKinds[k] == "constant_volume") {
            ++rows;
            EXPECT_LE(std::fabs(t.rows[k][std::size_t(t.column("epsv"))]), 1e-12);
        }
    }
    EXPECT_GE(rows, 10);

    // The stress-path chart: its points, and its curve drawn in the test's colour (pixels).
    ChartsPanel* charts = w.chartsPanel();
    const int chart = chartIndex(*charts, QStringLiteral("q_vs_p"));
    ASSERT_GE(chart, 0);
    EXPECT_EQ(charts->curvePoints(chart, test, "q").size(), rows);
    charts->showPage(QStringLiteral("Stress paths"));
    QTest::qWait(100);
    const int coloured = plotPixelsOf(*charts, chart, charts->testColour(test), 30);
    std::printf("stress path chart: %d pixels of the test colour\n", coloured);
    EXPECT_GT(coloured, 50) << "the stress path is not drawn";
}

// A cyclic test at constant volume run in the window: its q - eps1 loops reverse (the chart's
// points turn back and forth in eps1), its live cycle is drawn bold over them (pixels of the
// darker colour), and the chart of p'/p0 per cycle gets a point for each cycle ended.
TEST(WindowRun, ACyclicTestRunsAndDrawsItsLoopsLiveCycleAndPressurePerCycle) {
    const QString runs = freshFolder(QStringLiteral("cyclic"));
    MainWindow w;
    w.setRunsFolder(runs);
    showWith(w, smallExperiment(0.005, {{"kind", "cyclic"},
                                        {"drainage", "constant_volume"},
                                        {"amplitude", 1e-3},
                                        {"cycles", 3}}));
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return state(w) == RunState::Finished; }, 180000))
        << w.controller().status().error;
    w.refresh();
    const std::string test = "p015kPa-cyclic";
    ChartsPanel* charts = w.chartsPanel();
    const int loops = chartIndex(*charts, QStringLiteral("q_vs_eps1"));
    const int perCycle = chartIndex(*charts, QStringLiteral("p_per_cycle"));
    ASSERT_GE(loops, 0);
    ASSERT_GE(perCycle, 0);
    const auto points = charts->curvePoints(loops, test, "q");
    ASSERT_GT(points.size(), 20);
    int turns = 0;
    for (int k = 1; k + 1 < points.size(); ++k) {
        const double in = points[k].x() - points[k - 1].x(),
                     out = points[k + 1].x() - points[k].x();
        turns += in * out < 0;
    }
    EXPECT_GE(turns, 5) << "3 cycles reverse eps1 at least 5 times between their ends";
    const auto live = charts->liveCyclePoints(loops, test);
    ASSERT_FALSE(live.isEmpty());
    EXPECT_LT(live.size(), points.size());
    EXPECT_EQ(live.back(), points.back());
    EXPECT_GE(charts->curvePoints(perCycle, test, "p_over_p0").size(), 3); // start and 2+ ends

    charts->showPage(QStringLiteral("Stress paths"));
    QTest::qWait(100);
    const int boldPixels = plotPixelsOf(*charts, loops, charts->testColour(test).darker(130), 20);
    EXPECT_GT(boldPixels, 50) << "the live cycle is not drawn";
}

} // namespace
} // namespace grainlab::ui
