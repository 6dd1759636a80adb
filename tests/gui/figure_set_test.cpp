// Export > Figure set into a folder… holds the report's figures (those of `grainlab report`: every
// figure as PNG, SVG and PDF with its CSV, and the void-cell pictures) in its report/, written by
// a `grainlab report` process: of the window's run once it has finished, and of a run file opened
// in the window. While the run is going they are left out, and the window says so.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include "common/atomic_file.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/statistics.h"
#include "grainlab/ui/scene_view.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

/// A CSV file's rows of cells (quoted cells unquoted).
std::vector<std::vector<std::string>> readCsv(const QString& path) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(readWholeFile(path.toStdString()));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells(1);
        bool quoted = false;
        for (char c : line) {
            if (c == '"') {
                quoted = !quoted;
            } else if (c == ',' && !quoted) {
                cells.emplace_back();
            } else {
                cells.back() += c;
            }
        }
        rows.push_back(std::move(cells));
    }
    return rows;
}

int columnOf(const std::vector<std::string>& header, const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    return at == header.end() ? -1 : int(at - header.begin());
}

/// Pixels (every second one each way) neither white, black nor grey: the valence colours.
int colouredPixels(const QImage& image) {
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) {
            const QColor c = image.pixelColor(x, y);
            const int spread =
                std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()});
            coloured += spread > 40 ? 1 : 0;
        }
    }
    return coloured;
}

/// Every file of the report's figures in `figures` (report/figures of a figure set).
void expectTheReportsFigures(const QDir& figures) {
    QStringList stems{QStringLiteral("05_p015kPa_start"), QStringLiteral("05_p015kPa_peak"),
                      QStringLiteral("05_p015kPa_10pc")};
    for (const char* name :
         {"01_q", "01_q_over_p", "02_phi_peak", "03_epsv", "03_DI", "04_Z", "04_Z_eff", "04_S",
          "04_Z_and_Z_eff", "06_Nv_over_Nvi", "06_Z_eff_vs_Nv_over_Nvi", "07_Hdev", "07_Hsdev",
          "07_Hwdev", "08_q_over_p_vs_Hratio", "08_q_over_p_vs_Hsratio"}) {
        stems << QString::fromLatin1(name);
    }
    for (const QString& stem : stems) {
        for (const char* format : {".csv", ".png", ".svg", ".pdf"}) {
            const QFileInfo file(figures.filePath(stem + QLatin1String(format)));
            EXPECT_TRUE(file.exists() && file.size() > 0) << file.filePath().toStdString();
        }
    }
}

TEST(FigureSet, HoldsTheReportsFiguresOfTheRunAndOfAnOpenRunFile) {
    QDir runs(QDir::current().filePath(QStringLiteral("test-runs/figure-set")));
    runs.removeRecursively();
    qputenv("GRAINLAB_RUNS_DIR", runs.path().toUtf8());
    QDir out(QDir::current().filePath(QStringLiteral("test-images/figure-set")));
    out.removeRecursively();

    MainWindow w;
    w.setGrainlabExecutable(QStringLiteral(GRAINLAB_EXE));
    showWith(w, smallExperiment(0.01));
    QSignalSpy written(&w, &MainWindow::figureSetWritten);

    // While the run is going: the scene, the charts and the series as far as it got, and a
    // message that the report's figures wait for its end.
    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] {
        return w.controller().status().state == RunState::Running && w.sceneView()->snapshot();
    }));
    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state == RunState::Paused; }));
    w.refresh();
    const QString going = out.filePath(QStringLiteral("going"));
    QString error;
    EXPECT_FALSE(w.exportFigureSet(going, &error).isEmpty());
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_EQ(written.count(), 1);
    EXPECT_EQ(written.front().at(0).toString(), going);
    const QString note = written.front().at(1).toString();
    EXPECT_TRUE(note.contains(QStringLiteral("without the report's figures")) &&
                note.contains(QStringLiteral("still going")))
        << note.toStdString();
    EXPECT_TRUE(QFile::exists(QDir(going).filePath(QStringLiteral("scene.png"))));
    EXPECT_FALSE(QDir(going).exists(QStringLiteral("report")));

    // The finished run: the report's figures of its run folder, in report/figures.
    click(w, w.startAction());
    ASSERT_TRUE(
        waitFor([&] { return w.controller().status().state == RunState::Finished; }, 180000))
        << w.controller().status().error;
    w.refresh();
    const QString live = out.filePath(QStringLiteral("live"));
    const QStringList files = w.exportFigureSet(live, &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    EXPECT_TRUE(files.contains(QDir(live).filePath(QStringLiteral("scene.pdf"))));
    ASSERT_TRUE(waitFor([&] { return written.count() == 2; }, 120000));
    EXPECT_EQ(written.back().at(0).toString(), live);
    EXPECT_EQ(written.back().at(1).toString(), QString()) << w.runFolder().toStdString();
    const QDir liveFigures(QDir(live).filePath(QStringLiteral("report/figures")));
    expectTheReportsFigures(liveFigures);

    // q/p in its CSV is the run's series as the window charted it (one run: the mean is the
    // series at each strain of the figure's axis, the scatter zero).
    const SnapshotPtr shown = w.sceneView()->snapshot();
    ASSERT_TRUE(shown);
    const auto table = std::find_if(shown->series.begin(), shown->series.end(),
                                    [](const SeriesTable& t) { return t.test == "p015kPa"; });
    ASSERT_NE(table, shown->series.end());
    const Curve qp = shearCurve(*table, "q_over_p");
    const auto csv = readCsv(liveFigures.filePath(QStringLiteral("01_q_over_p.csv")));
    ASSERT_GT(csv.size(), 50u);
    const int test = columnOf(csv.front(), "test"), x = columnOf(csv.front(), "eps1 [-]");
    const int mean = columnOf(csv.front(), "q_over_p mean [-]");
    const int sd = columnOf(csv.front(), "q_over_p sd [-]");
    ASSERT_TRUE(test >= 0 && x >= 0 && mean >= 0 && sd >= 0);
    int checked = 0;
    for (std::size_t r = 1; r < csv.size(); ++r) {
        ASSERT_EQ(csv[r][std::size_t(test)], "p015kPa");
        // The CSV's 9 significant digits may put the last strain just past the series' end.
        const double at = std::clamp(std::stod(csv[r][std::size_t(x)]), qp.x.front(), qp.x.back());
        const auto expected = valueAt(qp, at);
        ASSERT_TRUE(expected.has_value()) << csv[r][std::size_t(x)];
        EXPECT_NEAR(std::stod(csv[r][std::size_t(mean)]), *expected,
                    1e-7 * std::max(1.0, std::abs(*expected)));
        EXPECT_EQ(std::stod(csv[r][std::size_t(sd)]), 0.0);
        ++checked;
    }
    EXPECT_GT(checked, 50);

    // The void-cell picture at the peak shows cells coloured by valence.
    const QImage peak(liveFigures.filePath(QStringLiteral("05_p015kPa_peak.png")));
    ASSERT_FALSE(peak.isNull());
    EXPECT_GT(colouredPixels(peak), peak.width() * peak.height() / 4 / 50); // > 2 %

    // The same run's file opened in another window: the same report's figures.
    MainWindow viewer;
    viewer.setGrainlabExecutable(QStringLiteral(GRAINLAB_EXE));
    viewer.resize(1400, 900);
    viewer.show();
    ASSERT_TRUE(viewer.openRunFolder(w.runFolder(), &error)) << error.toStdString();
    QSignalSpy viewerWritten(&viewer, &MainWindow::figureSetWritten);
    const QString opened = out.filePath(QStringLiteral("run-file"));
    viewer.exportFigureSet(opened, &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    ASSERT_TRUE(waitFor([&] { return viewerWritten.count() == 1; }, 120000));
    EXPECT_EQ(viewerWritten.front().at(1).toString(), QString());
    const QDir openedFigures(QDir(opened).filePath(QStringLiteral("report/figures")));
    expectTheReportsFigures(openedFigures);
    EXPECT_EQ(
        readWholeFile(openedFigures.filePath(QStringLiteral("01_q_over_p.csv")).toStdString()),
        readWholeFile(liveFigures.filePath(QStringLiteral("01_q_over_p.csv")).toStdString()));

    QDir(w.runFolder()).removeRecursively();
    out.removeRecursively();
}

} // namespace
} // namespace grainlab::ui
