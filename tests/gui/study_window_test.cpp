// The Study window on the tiny study (resources/studies/tiny.json: 3 settings x 2 seeds), run
// through the real grainlab executable: started, stopped once a run has finished (exit 130,
// the finished runs kept), started again to the end; then the error-against-cost chart holds
// one point per setting, drawn at toPixel() of each (pixels of the rendered chart); hovering a
// point shows its setting; clicking one opens an existing run folder in the main window; the
// figures export and recommended.json loads as the main window's experiment. The study runs
// once for the whole binary's test (about 20 s on two busy cores).
#include <chrono>
#include <set>

#include <QComboBox>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/ui/plot_view.h"
#include "gui/main_window.h"
#include "gui/study_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

const QString kTinyStudy = QStringLiteral(GRAINLAB_SOURCE_DIR "/resources/studies/tiny.json");

using window_tests::waitFor;

bool near(QColor a, QColor b, int tolerance = 10) {
    return std::abs(a.red() - b.red()) <= tolerance &&
           std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

/// Every run log of a study folder (runs/*/run.log and the like), for a failure's message.
std::string runLogs(const QString& folder) {
    std::string text;
    QDirIterator it(folder, {QStringLiteral("*.log")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        QFile file(it.next());
        if (file.open(QIODevice::ReadOnly)) {
            text += "\n--- " + file.fileName().toStdString() + "\n" +
                    file.readAll().right(2000).toStdString();
        }
    }
    return text;
}

int finished(const StudyWindow& s) {
    return s.folderState() ? s.folderState()->finishedCount() : 0;
}

TEST(StudyWindow, RefusesABadStudyFileAndAFolderHoldingSomethingElse) {
    StudyWindow s(nullptr, QStringLiteral(GRAINLAB_EXE));
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.json");
    QFile f(bad);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"name": "bad", "base": ")" GRAINLAB_SOURCE_DIR
            R"(/resources/experiments/tiny.json", "knobs": {"no_such_knob": [1]}})");
    f.close();
    QString error;
    EXPECT_FALSE(s.openStudy(bad, &error));
    EXPECT_TRUE(error.contains("bad.json") && error.contains("no_such_knob"))
        << error.toStdString();
    EXPECT_FALSE(s.start(&error));
    EXPECT_FALSE(s.startButton()->isEnabled());
    // A good one: 3 settings x 2 seeds; the folder named after the study beside the file.
    ASSERT_TRUE(s.openStudy(kTinyStudy, &error)) << error.toStdString();
    EXPECT_EQ(s.plan().runs.size(), 6u);
    EXPECT_EQ(s.folderPath(), QStringLiteral(GRAINLAB_SOURCE_DIR "/resources/studies/tiny"));
    EXPECT_TRUE(s.startButton()->isEnabled());
    // A folder that holds something else: the study refuses it, and the window says why.
    const QString other = dir.filePath("other");
    ASSERT_TRUE(QDir().mkpath(other));
    QFile stray(QDir(other).filePath("notes.txt"));
    ASSERT_TRUE(stray.open(QIODevice::WriteOnly));
    stray.close();
    s.setStudyFolder(other);
    ASSERT_TRUE(s.start(&error)) << error.toStdString();
    ASSERT_TRUE(waitFor([&] { return !s.running(); }, 60000));
    EXPECT_EQ(s.lastExitStatus().value_or(-99), 1);
    EXPECT_TRUE(s.statusLabel()->text().contains("not empty"))
        << s.statusLabel()->text().toStdString();
    EXPECT_FALSE(QFileInfo::exists(QDir(other).filePath("study.json")));
}

TEST(StudyWindow, RunsTheTinyStudyAndChartsOnePointPerSetting) {
    MainWindow w;
    StudyWindow* s = w.studyWindow();
    ASSERT_EQ(s, w.studyWindow()); // one Study window per main window
    s->setExecutable(QStringLiteral(GRAINLAB_EXE));
    s->setPollInterval(200);
    QString error;
    ASSERT_TRUE(s->openStudy(kTinyStudy, &error)) << error.toStdString();
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString folder = dir.filePath("tiny");
    s->setStudyFolder(folder);
    s->resize(1100, 720);
    w.showStudyWindow();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(s));
    const int total = int(s->plan().runs.size());
    const int settings = int(s->plan().settings.size());

    // Start, then Stop once a run has finished: the study ends with 130 and keeps its runs.
    QSignalSpy ended(s, &StudyWindow::studyEnded);
    std::set<int> counts; // the finished runs seen as the folder was read: it fills in
    QObject::connect(s, &StudyWindow::progressChanged, s, [&] { counts.insert(finished(*s)); });
    ASSERT_TRUE(s->start(&error)) << error.toStdString();
    EXPECT_TRUE(s->running());
    EXPECT_FALSE(s->startButton()->isEnabled());
    EXPECT_TRUE(s->stopButton()->isEnabled());
    ASSERT_TRUE(waitFor([&] { return finished(*s) >= 1 || !s->running(); }, 300000));
    ASSERT_TRUE(s->running()) << "the study ended before Stop: exit "
                              << s->lastExitStatus().value_or(-99);
    const int beforeStop = finished(*s);
    EXPECT_EQ(s->progressBar()->value(), beforeStop);
    EXPECT_EQ(s->progressBar()->maximum(), total);
    if (beforeStop < total) {
        s->stop();
        ASSERT_TRUE(waitFor([&] { return !s->running(); }, 120000));
        EXPECT_EQ(s->lastExitStatus().value_or(-99), 130);
        ASSERT_TRUE(waitFor([&] { return finished(*s) >= beforeStop; }, 10000));
        EXPECT_LT(finished(*s), total);
    }

    // Start again: the study continues to its end.
    ASSERT_TRUE(s->start(&error)) << error.toStdString();
    ASSERT_TRUE(waitFor([&] { return !s->running(); }, 600000));
    ASSERT_EQ(s->lastExitStatus().value_or(-99), 0)
        << s->statusLabel()->text().toStdString() << runLogs(folder);
    ASSERT_TRUE(waitFor([&] { return finished(*s) == total; }, 20000));
    EXPECT_EQ(s->progressBar()->value(), total);
    EXPECT_GE(counts.size(), 3u) << "the runs' results came in all at once";
    QTest::qWait(50);

    // One point per setting, each labelled with its setting, drawn where toPixel() says.
    const PlotView* chart = s->chart();
    const PlotPainter& plot = chart->plot();
    ASSERT_EQ(int(plot.points.size()), settings);
    std::set<int> seen;
    for (int k = 0; k < settings; ++k) {
        seen.insert(s->settingOfPoint(k));
    }
    EXPECT_EQ(int(seen.size()), settings);
    EXPECT_EQ(seen.count(-1), 0u);
    const QImage image = const_cast<PlotView*>(chart)->grab().toImage();
    if (qEnvironmentVariableIsSet("GRAINLAB_STUDY_WINDOW_SHOT")) {
        s->grab().save(qEnvironmentVariable("GRAINLAB_STUDY_WINDOW_SHOT"));
    }
    std::vector<QPoint> pixels;
    for (const PlotPoint& p : plot.points) {
        pixels.push_back(plot.toPixel(p.x, p.y, chart->plotRect()).toPoint());
    }
    std::vector<int> isolated;
    for (int k = 0; k < settings; ++k) {
        ASSERT_TRUE(chart->rect().contains(pixels[std::size_t(k)]));
        // The point's own colour, or (points drawn on top of each other) that of a later one.
        bool match = false;
        bool alone = true;
        for (int j = 0; j < settings; ++j) {
            const QPoint d = pixels[std::size_t(j)] - pixels[std::size_t(k)];
            // Drawn over by point j: its disk and ring, or its error bars through its centre.
            const bool close = d.manhattanLength() <= 14;
            const bool overlaps = close || std::abs(d.x()) <= 2 || std::abs(d.y()) <= 2;
            if (j != k && close) {
                alone = false;
            }
            // Within 2 px of the centre: the point's own colour, or, where a later point is
            // drawn over it (its fill, outline, error bars or ring, blended), a dark pixel,
            // unlike the white background, the grey noise band and the light grid.
            for (int dx = -2; dx <= 2; ++dx) {
                for (int dy = -2; dy <= 2; ++dy) {
                    const QColor at = image.pixelColor(pixels[std::size_t(k)] + QPoint(dx, dy));
                    if (j == k ? near(at, plot.points[std::size_t(j)].colour)
                               : j > k && overlaps && at.lightness() < 150) {
                        match = true;
                    }
                }
            }
        }
        EXPECT_TRUE(match) << plot.points[std::size_t(k)].label.toStdString() << " at "
                           << pixels[std::size_t(k)].x() << ", " << pixels[std::size_t(k)].y()
                           << ": " << image.pixelColor(pixels[std::size_t(k)]).name().toStdString();
        if (alone) {
            isolated.push_back(k);
        }
    }
    ASSERT_FALSE(isolated.empty()) << "every point overlaps another";

    // Hovering a point shows its setting; clicking it opens its first finished run here.
    QSignalSpy opened(s, &StudyWindow::openRunFolderRequested);
    EXPECT_FALSE(w.runFileSlider()->isVisibleTo(&w));
    for (int k : isolated) {
        // The point's label names its setting (errorCostPlot), independently of the window.
        const std::string id = plot.points[std::size_t(k)].label.toStdString();
        EXPECT_EQ(s->plan().settings[std::size_t(s->settingOfPoint(k))].id, id);
        QTest::mouseMove(s->chart(), pixels[std::size_t(k)] + QPoint(1, 1));
        EXPECT_TRUE(s->details()->text().contains(QString::fromStdString("<b>" + id + "</b>")))
            << id << ": " << s->details()->text().toStdString();
        QTest::mouseClick(s->chart(), Qt::LeftButton, {}, pixels[std::size_t(k)]);
        ASSERT_FALSE(opened.isEmpty());
        const QString run = opened.last().at(0).toString();
        EXPECT_EQ(
            run.toStdString(),
            QDir(folder).filePath(QString::fromStdString("runs/" + id + "-seed1")).toStdString());
        EXPECT_TRUE(QFileInfo::exists(QDir(run).filePath("run.h5"))) << run.toStdString();
    }
    EXPECT_EQ(opened.size(), int(isolated.size()));
    EXPECT_TRUE(w.runFileSlider()->isVisibleTo(&w)); // the run file's checkpoints to scrub

    // The figures, and the recommendation loaded as the main window's experiment.
    QTemporaryDir figures;
    const QStringList files = s->exportFigures(figures.path(), &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    EXPECT_FALSE(files.isEmpty());
    for (const QString& f : files) {
        EXPECT_GT(QFileInfo(f).size(), 0) << f.toStdString();
    }
    // The finished folder opened afresh (no Start) shows the same chart.
    StudyWindow again(nullptr, QStringLiteral(GRAINLAB_EXE));
    ASSERT_TRUE(again.openStudy(kTinyStudy, &error));
    again.setStudyFolder(folder);
    ASSERT_TRUE(waitFor([&] { return finished(again) == total; }, 20000));
    EXPECT_EQ(again.chart()->plot().points.size(), plot.points.size());

    ASSERT_TRUE(s->recommendedButton()->isEnabled());
    QSignalSpy experiment(s, &StudyWindow::openExperimentRequested);
    QTest::mouseClick(s->recommendedButton(), Qt::LeftButton);
    ASSERT_EQ(experiment.size(), 1);
    EXPECT_TRUE(w.windowTitle().contains("recommended.json")) << w.windowTitle().toStdString();
}

} // namespace
} // namespace grainlab::ui
