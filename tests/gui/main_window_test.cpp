// The main window on a small real experiment (120 ovals, one confining pressure, shear to
// 0.5 %): start, pause and step through the toolbar; a click at a void cell's centroid while
// paused shows its valence and area in the inspector; the figure set is written from the window;
// parameters are validated before a run. With GRAINLAB_WRITE_SCREENSHOTS=1 the last test also
// writes the user guide's screenshots into docs/images/.
#include <chrono>
#include <cmath>

#include <QComboBox>
#include <QDir>
#include <QImageReader>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QProgressBar>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QToolBar>

#include <array>

#include <gtest/gtest.h>

#include "chart_index.h"
#include "grainlab/experiment_file.h"
#include "grainlab/run_file.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/inspector_panel.h"
#include "grainlab/ui/parameters_panel.h"
#include "grainlab/ui/scene_options_bar.h"
#include "grainlab/ui/scene_view.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

struct Fixture {
    MainWindow window;
    Fixture() { showWith(window, smallExperiment()); }
    RunState state() { return window.controller().status().state; }
    SnapshotPtr shown() { return window.sceneView()->snapshot(); }
};

/// True when the cell's (wrapped) centroid, in one of its periodic images, lies inside the
/// cell's polygon (even-odd rule, brute force over the edges).
bool centroidInside(const VoidCellView& cell, const std::array<double, 4>& h) {
    const std::size_t n = cell.x1.size();
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            const double p1 = cell.centroid1 + h[0] * i + h[2] * j;
            const double p2 = cell.centroid2 + h[1] * i + h[3] * j;
            bool inside = false;
            for (std::size_t a = 0, b = n - 1; a < n; b = a++) {
                const bool crosses = (cell.x2[a] > p2) != (cell.x2[b] > p2);
                if (crosses && p1 < cell.x1[a] + (p2 - cell.x2[a]) * (cell.x1[b] - cell.x1[a]) /
                                                     (cell.x2[b] - cell.x2[a])) {
                    inside = !inside;
                }
            }
            if (inside) {
                return true;
            }
        }
    }
    return false;
}

TEST(MainWindow, StartPauseStepStop) {
    Fixture f;
    MainWindow& w = f.window;
    EXPECT_FALSE(w.pauseAction()->isEnabled());
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] {
        return f.state() == RunState::Running && f.shown() &&
               w.controller().status().publications >= 5;
    }));
    EXPECT_FALSE(w.parametersPanel()->isEnabled());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().stepsPerSecond > 0; }));
    QTest::qWait(50);
    EXPECT_TRUE(w.speedLabel()->text().contains(QStringLiteral("steps/s")));

    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return f.state() == RunState::Paused; }));
    w.refresh();
    const std::int64_t paused = f.shown()->step;
    QTest::qWait(150);
    w.refresh();
    EXPECT_EQ(f.shown()->step, paused);
    EXPECT_EQ(w.startAction()->text(), QStringLiteral("Resume"));

    w.stepSizeEdit()->setValue(37);
    click(w, w.stepAction());
    ASSERT_TRUE(waitFor([&] {
        w.refresh();
        return f.shown()->step != paused;
    }));
    EXPECT_EQ(f.shown()->step, paused + 37);
    EXPECT_EQ(f.state(), RunState::Paused);

    click(w, w.stopAction());
    ASSERT_TRUE(waitFor([&] { return f.state() == RunState::Idle; }));
    w.refresh();
    EXPECT_TRUE(w.parametersPanel()->isEnabled());
    EXPECT_FALSE(w.stopAction()->isEnabled());
}

TEST(MainWindow, ClickAVoidCellWhilePausedAndExportTheFigureSet) {
    Fixture f;
    MainWindow& w = f.window;
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return f.shown() && f.shown()->voidCells.size() >= 20; }));
    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return f.state() == RunState::Paused; }));
    w.refresh();
    QComboBox* voids = w.sceneOptionsBar()->voidCellsBox();
    voids->setCurrentIndex(1); // void cells by valence
    const SnapshotPtr held = f.shown();
    const Snapshot& s = *held;
    // The largest cell whose centroid lies inside it: early in a compaction, when the machine is
    // loaded, the pause can come while the packing is loose, and a large non-convex cell's
    // centroid then lies in a neighbouring cell.
    int chosen = -1;
    for (std::size_t v = 0; v < s.voidCells.size(); ++v) {
        if (centroidInside(s.voidCells[v], s.network.cell) &&
            (chosen < 0 || s.voidCells[v].area > s.voidCells[chosen].area)) {
            chosen = static_cast<int>(v);
        }
    }
    ASSERT_GE(chosen, 0);
    const VoidCellView& cell = s.voidCells[chosen];
    QTest::mouseClick(w.sceneView(), Qt::LeftButton, Qt::NoModifier,
                      w.sceneView()->toWidget(cell.centroid1, cell.centroid2));
    EXPECT_EQ(w.inspector()->title(), QStringLiteral("Void cell %1").arg(chosen));
    EXPECT_EQ(w.inspector()->value(QStringLiteral("valence")), QString::number(cell.valence));
    EXPECT_EQ(w.inspector()->value(QStringLiteral("area [mm²]")),
              QString::number(cell.area * 1e6, 'g', 4));
    EXPECT_TRUE(w.inspector()->isVisible());

    QDir dir(QStringLiteral("test-images/window-figure-set"));
    dir.removeRecursively();
    QString error;
    const QStringList files = w.exportFigureSet(dir.path(), &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    EXPECT_GE(files.size(), 3 * 7);
    QImageReader scene(dir.filePath(QStringLiteral("scene.png")));
    EXPECT_EQ(scene.size(), QSize(1200, 1200));
    QImageReader chart(dir.filePath(QStringLiteral("q_over_p.png")));
    EXPECT_EQ(chart.size(), QSize(1200, 800));
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("fabric.svg"))));
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("void_cells.pdf"))));
}

/// Pixels of the scene widget drawn in the grains' fill colours (not background, not cell fill).
int grainPixels(SceneView* scene) {
    const QImage image = scene->grab().toImage();
    const SceneOptions& o = scene->renderer().options();
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            const auto near = [&](const QColor& a) {
                return std::abs(c.red() - a.red()) + std::abs(c.green() - a.green()) +
                           std::abs(c.blue() - a.blue()) <
                       12;
            };
            n += !near(o.background) && !near(o.cellFill);
        }
    }
    return n;
}

TEST(MainWindow, ShowsTheGeneratedAssemblyBeforeStart) {
    // A newcomer sees the experiment as soon as it is loaded: the grid the run starts from, with
    // the loaded grain count, drawn; an edit of the parameters regenerates it, and Start then
    // shows the run itself.
    Fixture f;
    MainWindow& w = f.window;
    ASSERT_TRUE(waitFor([&] { return QTest::qWaitForWindowExposed(&w); }));
    ASSERT_NE(f.shown(), nullptr) << "the scene is empty before Start";
    EXPECT_EQ(f.shown(), w.startingAssembly());
    EXPECT_EQ(f.shown()->x1.size(), 120u);
    EXPECT_EQ(f.shown()->step, 0);
    EXPECT_EQ(f.state(), RunState::Idle);
    // Grains do not touch on the generated grid.
    EXPECT_TRUE(f.shown()->network.contacts.empty());
    const int drawn = grainPixels(w.sceneView());
    EXPECT_GT(drawn, 2000) << "the generated assembly is not drawn";

    w.parametersPanel()->grainCountEdit()->setValue(300);
    ASSERT_TRUE(waitFor([&] { return f.shown() && f.shown()->x1.size() == 300u; }, 10000));
    EXPECT_EQ(f.shown(), w.startingAssembly());
    EXPECT_GT(grainPixels(w.sceneView()), 2000);

    // The same grid as the run's own first picture: Start replaces it with the run's snapshots.
    const SnapshotPtr before = f.shown();
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] {
        w.refresh();
        return f.shown() != before && f.shown()->step > 0;
    }));
    EXPECT_EQ(f.shown()->x1.size(), 300u);
    click(w, w.stopAction());
    ASSERT_TRUE(waitFor([&] { return f.state() == RunState::Idle; }));
}

TEST(MainWindow, ParametersAreValidatedBeforeARun) {
    Fixture f;
    MainWindow& w = f.window;
    ParametersPanel* p = w.parametersPanel();
    EXPECT_TRUE(p->valid());
    EXPECT_EQ(p->compactionPressuresLabel()->text(), QStringLiteral("15"));
    p->shearPressuresEdit()->setText(QStringLiteral("15, abc"));
    EXPECT_FALSE(p->valid());
    EXPECT_TRUE(p->problem().contains(QStringLiteral("abc")));
    EXPECT_FALSE(w.startAction()->isEnabled());
    // 25 kPa is no compaction stage of this experiment: refused, not added as one.
    p->shearPressuresEdit()->setText(QStringLiteral("15, 25"));
    EXPECT_FALSE(p->valid());
    EXPECT_TRUE(p->problem().contains(QStringLiteral("one of the compaction pressures")));
    EXPECT_FALSE(w.startAction()->isEnabled());
    p->shearPressuresEdit()->setText(QStringLiteral("15"));
    p->grainCountEdit()->setValue(200);
    p->frictionEdit()->setValue(0.3);
    p->strainTargetEdit()->setValue(2.0);
    ASSERT_TRUE(p->valid());
    EXPECT_TRUE(w.startAction()->isEnabled());
    const ExperimentConfig c = p->applied();
    EXPECT_EQ(c.compaction.pressures, (std::vector<double>{15e3}));
    EXPECT_EQ(c.shear.pressures, (std::vector<double>{15e3}));
    EXPECT_EQ(c.assembly.grainCount, 200);
    EXPECT_DOUBLE_EQ(c.shear.friction, 0.3);
    EXPECT_DOUBLE_EQ(c.shear.targetAxialStrain, 0.02);
}

TEST(MainWindow, RunsToTheEndAndWritesScreenshots) {
    Fixture f;
    MainWindow& w = f.window;
    // Relative, so that the status bar of the screenshot names a folder like the default one.
    QDir(QStringLiteral("GrainLab runs")).removeRecursively();
    w.setRunsFolder(QStringLiteral("GrainLab runs"));
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return f.state() == RunState::Finished; }, 120000))
        << w.controller().status().error;
    w.refresh();
    EXPECT_EQ(w.progressBar()->value(), 1000);
    const int q = 0;
    const auto points = w.chartsPanel()->curvePoints(q, f.shown()->series.back().test, "q_over_p");
    EXPECT_GT(points.size(), 10);
    EXPECT_NEAR(points.back().x(), 0.5, 0.05); // shear to 0.5 %, shown in percent

    if (qEnvironmentVariable("GRAINLAB_WRITE_SCREENSHOTS") != QLatin1String("1")) {
        GTEST_SKIP() << "set GRAINLAB_WRITE_SCREENSHOTS=1 to write docs/images/";
    }
    const QDir images(QStringLiteral(GRAINLAB_SOURCE_DIR "/docs/images"));
    ASSERT_TRUE(QDir().mkpath(images.path()));
    w.sceneOptionsBar()->forceChainsBox()->setCurrentIndex(1); // strong force chains
    w.sceneOptionsBar()->voidCellsBox()->setCurrentIndex(1);   // void cells by valence
    const Snapshot& s = *f.shown();
    int chosen = 0;
    for (std::size_t v = 0; v < s.voidCells.size(); ++v) {
        if (s.voidCells[v].area > s.voidCells[chosen].area) {
            chosen = static_cast<int>(v);
        }
    }
    QTest::mouseClick(
        w.sceneView(), Qt::LeftButton, Qt::NoModifier,
        w.sceneView()->toWidget(s.voidCells[chosen].centroid1, s.voidCells[chosen].centroid2));
    QTest::qWait(50);
    EXPECT_TRUE(w.grab().save(images.filePath(QStringLiteral("main-window.png"))));
    w.sceneOptionsBar()->colouringBox()->setCurrentIndex(3);   // load-bearing vs rattlers
    w.sceneOptionsBar()->forceChainsBox()->setCurrentIndex(2); // all forces
    w.sceneOptionsBar()->voidCellsBox()->setCurrentIndex(0);
    QTest::qWait(20);
    EXPECT_TRUE(w.sceneView()->grab().save(images.filePath(QStringLiteral("scene-forces.png"))));
    EXPECT_TRUE(w.chartsPanel()->grab().save(images.filePath(QStringLiteral("charts.png"))));
    EXPECT_TRUE(w.chartsPanel()->exportChart(
        0, images.filePath(QStringLiteral("chart-q-over-p.png")), QSize(900, 600)));
}

TEST(MainWindow, HoveringAChartShowsTheLiveRunsKeptSnapshotUntilTheHoverEnds) {
    const ExperimentConfig config = smallExperiment(0.02); // long enough to pause during the shear
    MainWindow w;
    showWith(w, config);
    click(w, w.startAction());
    // Some records into the shear (one every 0.02 %): the history keeps a snapshot of each one,
    // or of every n-th when they cost the engine too much.
    ASSERT_TRUE(waitFor([&] {
        const RunStatus status = w.controller().status();
        return status.progress.axialStrain >= 0.005 || status.state == RunState::Finished ||
               status.state == RunState::Failed;
    }));
    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state != RunState::Running; }));
    ASSERT_GE(w.controller().history().size(), 6u);
    w.refresh();
    const SnapshotPtr live = w.sceneView()->snapshot();
    ASSERT_EQ(live, w.controller().latestSnapshot());
    const SeriesTable& series = live->series.back();
    ASSERT_EQ(series.test, live->test);

    // An early kept record (the history numbers the shear records from 0; it may keep only
    // every n-th) and the point of the q/p chart drawn from it.
    const std::vector<std::int64_t> kept = w.controller().history().records();
    const std::int64_t record = kept[kept.size() / 4];
    std::vector<std::size_t> shearRows;
    for (std::size_t r = 0; r < series.rows.size(); ++r) {
        if (series.stages[r].rfind("shear", 0) == 0) {
            shearRows.push_back(r);
        }
    }
    ASSERT_LT(static_cast<std::size_t>(record), shearRows.size());
    const std::vector<double>& row = series.rows[shearRows[record]];
    const auto recordStep = static_cast<std::int64_t>(row[series.column("step")]);
    const double recordStrain = row[series.column("eps1")];
    ASSERT_GT(recordStep, 0);
    ASSERT_LT(recordStep, live->step);
    const QPointF point(100.0 * recordStrain, row[series.column("q_over_p")]);
    EXPECT_TRUE(w.chartsPanel()->curvePoints(0, live->test, "q_over_p").contains(point));

    // The cursor over that point of the chart (a synthetic move, as in charts_panel_test).
    HoverChartView* chart = w.chartsPanel()->chartView(0);
    const QPointF local = chart->mapFromScene(chart->chart()->mapToPosition(point));
    QMouseEvent move(QEvent::MouseMove, local, chart->viewport()->mapToGlobal(local), Qt::NoButton,
                     Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(chart->viewport(), &move);
    EXPECT_TRUE(w.showsLiveHistory());
    const SnapshotPtr earlier = w.sceneView()->snapshot();
    ASSERT_NE(earlier, live);
    EXPECT_EQ(earlier->step, recordStep);
    EXPECT_EQ(earlier->axialStrain, recordStrain);
    EXPECT_EQ(earlier->test, live->test);
    // Its rotation counts from the same start of the test as the live snapshot's.
    ASSERT_EQ(earlier->rotation.size(), live->rotation.size());
    for (std::size_t g = 0; g < earlier->rotation.size(); ++g) {
        ASSERT_NEAR(earlier->theta[g] - earlier->rotation[g], live->theta[g] - live->rotation[g],
                    1e-12);
    }
    // What is drawn is the earlier scene: it differs from the live one, and the timer does not
    // replace it while the hover lasts.
    const QImage earlierImage = w.sceneView()->grab().toImage();
    QTest::qWait(100);
    EXPECT_EQ(w.sceneView()->snapshot(), earlier);

    // The cursor leaves the chart: back to the live run.
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(chart, &leave);
    EXPECT_FALSE(w.showsLiveHistory());
    EXPECT_EQ(w.sceneView()->snapshot(), live);
    const QImage now = w.sceneView()->grab().toImage();
    ASSERT_EQ(earlierImage.size(), now.size());
    int differing = 0;
    for (int y = 0; y < now.height(); ++y) {
        for (int x = 0; x < now.width(); ++x) {
            differing += earlierImage.pixel(x, y) != now.pixel(x, y);
        }
    }
    EXPECT_GT(differing, 1000);
}

/// A run file of the small experiment written headless by the engine, as `grainlab run` does,
/// into test-images/`name`, with checkpoints every 0.1 % of shear (to `shearTarget`).
QString writeSmallRunFile(const QString& name, double shearTarget = 0.005) {
    const QString path = QDir::current().filePath(QStringLiteral("test-images/") + name);
    QDir().mkpath(QStringLiteral("test-images"));
    ExperimentConfig config = smallExperiment();
    config.shear.targetAxialStrain = shearTarget;
    config.record.snapshotStepInterval = 10000;
    config.record.snapshotStrainInterval = 0.001;
    RunFile file(path.toStdString(), config.sourceText);
    ExperimentRunner runner(config, &file);
    while (runner.advance(5000)) {
    }
    return path;
}

TEST(MainWindow, OpensARunFileAndScrubsItsCheckpoints) {
    const QString path = writeSmallRunFile(QStringLiteral("small-run.h5"));
    Fixture f;
    MainWindow& w = f.window;
    QString error;
    ASSERT_TRUE(w.openRunFile(path, &error)) << error.toStdString();
    QSlider* slider = w.runFileSlider();
    const auto checkpoints = listCheckpoints(path.toStdString());
    ASSERT_GE(checkpoints.size(), 3u);
    EXPECT_TRUE(slider->isVisible());
    EXPECT_EQ(slider->maximum(), static_cast<int>(checkpoints.size()) - 1);
    const std::int64_t last = f.shown()->step;
    EXPECT_EQ(last, readState(path.toStdString(), checkpointGroup(checkpoints.back())).step);
    slider->setValue(1);
    const SnapshotPtr second = f.shown();
    EXPECT_EQ(second->step, readState(path.toStdString(), checkpointGroup(checkpoints[1])).step);
    EXPECT_LT(second->step, last);
    // The timer does not replace the file's scene with the (idle) live run's.
    QTest::qWait(50);
    EXPECT_EQ(f.shown(), second);
    // The file's shear series is in the charts under the file's name.
    bool charted = false;
    for (const SeriesTable& t : second->series) {
        charted |= !w.chartsPanel()->curvePoints(0, t.test, "q_over_p").isEmpty();
        EXPECT_EQ(t.test.rfind("small-run.h5: ", 0), 0u) << t.test;
    }
    EXPECT_TRUE(charted);
    // Its compaction series is on the charts' compaction page, against step.
    const int pressureChart = testing::chartIndex(*w.chartsPanel(), QStringLiteral("compaction_p"));
    ASSERT_GE(pressureChart, 0);
    const SeriesTable compaction = readSeries(path.toStdString(), "compaction");
    const auto pressure =
        w.chartsPanel()->curvePoints(pressureChart, "small-run.h5: compaction", "p");
    ASSERT_EQ(pressure.size(), static_cast<qsizetype>(compaction.rows.size()));
    EXPECT_EQ(pressure.back().x(), compaction.rows.back()[compaction.column("step")]);

    // Hovering a chart at eps1 = 0.2 % moves the scene to the shear checkpoint nearest to it.
    slider->setValue(slider->maximum());
    const std::string test = f.shown()->test;
    ASSERT_FALSE(test.empty());
    emit w.chartsPanel()->hoveredAxialStrain(0.002);
    EXPECT_NEAR(f.shown()->axialStrain, 0.002, 0.0006);
    EXPECT_EQ(f.shown()->test, test);
    EXPECT_FALSE(w.openRunFile(QStringLiteral("/nonexistent.h5"), &error));
    EXPECT_FALSE(error.isEmpty());
}

TEST(MainWindow, RunFileCheckpointsColourTheRotationSinceTheirTestStarted) {
    const QString path = writeSmallRunFile(QStringLiteral("rotation-run.h5"), 0.02);
    Fixture f;
    MainWindow& w = f.window;
    QString error;
    ASSERT_TRUE(w.openRunFile(path, &error)) << error.toStdString();
    const auto checkpoints = listCheckpoints(path.toStdString());
    int testStart = -1;
    for (std::size_t k = 0; k < checkpoints.size() && testStart < 0; ++k) {
        if (checkpoints[k].find("equilibration") != std::string::npos) {
            testStart = static_cast<int>(k);
        }
    }
    ASSERT_GE(testStart, 0);
    const SimulationState start =
        readState(path.toStdString(), checkpointGroup(checkpoints[testStart]));

    // The last checkpoint (the end of the shear): rotation = theta - theta at the test's first
    // checkpoint, where the live run counts it from too.
    const SnapshotPtr last = f.shown();
    ASSERT_EQ(last->rotation.size(), start.grains.theta.size());
    double largest = 0.0;
    for (std::size_t g = 0; g < last->rotation.size(); ++g) {
        ASSERT_EQ(last->rotation[g], last->theta[g] - start.grains.theta[g]) << "grain " << g;
        largest = std::max(largest, std::fabs(last->rotation[g]));
    }
    EXPECT_GT(largest, 0.05);

    // Drawn: coloured by rotation, the grains that turned are not the colour of no rotation.
    w.sceneOptionsBar()->colouringBox()->setCurrentIndex(1); // rotation
    const QImage image = w.sceneView()->grab().toImage();
    const SceneRenderer& r = w.sceneView()->renderer();
    int turned = 0, drawn = 0;
    for (std::size_t g = 0; g < last->rotation.size(); ++g) {
        if (std::fabs(last->rotation[g]) < 0.05) {
            continue;
        }
        ++turned;
        const QRgb pixel = image.pixel(w.sceneView()->toWidget(last->x1[g], last->x2[g]));
        const QColor expected = r.grainColour(static_cast<int>(g));
        const QColor none = divergingColour(0.0);
        const bool coloured = std::abs(expected.red() - none.red()) +
                                  std::abs(expected.green() - none.green()) +
                                  std::abs(expected.blue() - none.blue()) >
                              30;
        drawn += coloured && std::abs(qRed(pixel) - expected.red()) <= 3 &&
                 std::abs(qGreen(pixel) - expected.green()) <= 3 &&
                 std::abs(qBlue(pixel) - expected.blue()) <= 3;
    }
    EXPECT_GE(turned, 10);
    EXPECT_GE(drawn, turned * 8 / 10) << drawn << " of " << turned;

    // At the test's first checkpoint nothing has turned yet.
    w.runFileSlider()->setValue(testStart);
    for (double rotation : f.shown()->rotation) {
        ASSERT_EQ(rotation, 0.0);
    }
}

} // namespace
} // namespace grainlab::ui
