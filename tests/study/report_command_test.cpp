// `grainlab reproduce` and `grainlab report` end to end on the tiny experiment at two seeds
// (150 ovals, 15 and 100 kPa, shear to 2 %): the runs go through the study's pool, then every
// figure's CSV, the headline table and the report pages are written; the curves' means and
// bands equal the mean and standard deviation computed from the two runs' series, the fit's
// coefficients equal a hand least-squares fit, and (with the window) the void-cell pictures show
// cells.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <sys/wait.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#ifdef GRAINLAB_WITH_GUI
#include <QImage>
#endif

#include "test_folders.h"

#include "grainlab/run_file.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/statistics.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;
using test::freshFolder;
using test::run;
using test::text;

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
    std::vector<std::vector<std::string>> t;
    std::istringstream in(text(p));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::string cell;
        bool quoted = false;
        for (char c : line) {
            if (c == '"') {
                quoted = !quoted;
            } else if (c == ',' && !quoted) {
                cells.push_back(cell);
                cell.clear();
            } else {
                cell += c;
            }
        }
        cells.push_back(cell);
        t.push_back(cells);
    }
    return t;
}

int columnOf(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t c = 0; c < header.size(); ++c) {
        if (header[c] == name) {
            return int(c);
        }
    }
    return -1;
}

class Reproduce : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = new fs::path(freshFolder("reproduce"));
        status_ = run(std::string(GRAINLAB_EXE) +
                      " reproduce --experiment " GRAINLAB_SOURCE_DIR
                      "/resources/experiments/tiny.json --seeds 2 --quiet --out " +
                      folder_->string() + " > " + folder_->string() + ".log 2>&1");
    }
    static void TearDownTestSuite() {
        fs::remove_all(*folder_);
        fs::remove(folder_->string() + ".log");
        delete folder_;
    }
    static SeriesTable series(int seed, const std::string& test) {
        return readSeries(
            (*folder_ / "study" / "runs" / ("ref-seed" + std::to_string(seed)) / "run.h5").string(),
            test);
    }
    static fs::path* folder_;
    static int status_;
};
fs::path* Reproduce::folder_ = nullptr;
int Reproduce::status_ = -1;

TEST_F(Reproduce, WritesEveryFigureTheTableAndThePages) {
    ASSERT_EQ(status_, 0) << text(folder_->string() + ".log");
    const fs::path report = *folder_ / "report";
    for (const char* f : {"report.html", "report.md", "headline.csv"}) {
        EXPECT_TRUE(fs::exists(report / f)) << f;
    }
    for (const char* name :
         {"01_q", "01_q_over_p", "02_phi_peak", "03_epsv", "03_DI", "04_Z", "04_Z_eff", "04_S",
          "04_Z_and_Z_eff", "06_Nv_over_Nvi", "06_Z_eff_vs_Nv_over_Nvi", "07_Hdev", "07_Hsdev",
          "07_Hwdev", "08_q_over_p_vs_Hratio", "08_q_over_p_vs_Hsratio"}) {
        EXPECT_TRUE(fs::exists(report / "figures" / (std::string(name) + ".csv"))) << name;
#ifdef GRAINLAB_WITH_GUI
        for (const char* format : {".png", ".svg", ".pdf"}) {
            EXPECT_TRUE(fs::exists(report / "figures" / (std::string(name) + format)))
                << name << format;
        }
#endif
    }
    const std::string html = text(report / "report.html");
    EXPECT_NE(html.find("e after compaction"), std::string::npos);
    EXPECT_NE(html.find("0.126"), std::string::npos); // the published void ratio beside ours
#ifdef GRAINLAB_WITH_GUI
    EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos); // self-contained
#endif
}

TEST_F(Reproduce, CurvesAreTheMeanOfTheTwoSeedsWithTheirStandardDeviation) {
    ASSERT_EQ(status_, 0);
    const auto csv = readCsv(*folder_ / "report" / "figures" / "01_q_over_p.csv");
    ASSERT_GT(csv.size(), 10u);
    const auto& h = csv.front();
    const int test = columnOf(h, "test"), x = columnOf(h, "eps1 [-]");
    const int mean = columnOf(h, "q_over_p mean [-]"), sd = columnOf(h, "q_over_p sd [-]");
    const int runs = columnOf(h, "runs [-]");
    ASSERT_GE(test, 0);
    ASSERT_GE(x, 0);
    ASSERT_GE(mean, 0);
    ASSERT_GE(sd, 0);
    const Curve a = shearCurve(series(1, "p015kPa"), "q_over_p");
    const Curve b = shearCurve(series(2, "p015kPa"), "q_over_p");
    int checked = 0;
    for (std::size_t r = 1; r < csv.size(); ++r) {
        if (csv[r][std::size_t(test)] != "p015kPa" || csv[r][std::size_t(runs)] != "2") {
            continue;
        }
        const double at = std::stod(csv[r][std::size_t(x)]);
        const auto ya = valueAt(a, at), yb = valueAt(b, at);
        ASSERT_TRUE(ya && yb) << at;
        EXPECT_NEAR(std::stod(csv[r][std::size_t(mean)]), (*ya + *yb) / 2, 1e-7);
        EXPECT_NEAR(std::stod(csv[r][std::size_t(sd)]), std::abs(*ya - *yb) / std::sqrt(2.0), 1e-7);
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

TEST_F(Reproduce, TheFitIsALeastSquaresLineThroughTheRecords) {
    ASSERT_EQ(status_, 0);
    const auto csv = readCsv(*folder_ / "report" / "headline.csv");
    const auto& h = csv.front();
    const int number = columnOf(h, "number"), test = columnOf(h, "test"),
              mean = columnOf(h, "mean");
    // The slope of each run's test by hand, then their mean.
    double slopes = 0;
    for (int seed = 1; seed <= 2; ++seed) {
        const SeriesTable t = series(seed, "p100kPa");
        const Curve x = shearCurve(t, "Nv_over_Nvi"), y = shearCurve(t, "Z_eff");
        double mx = 0, my = 0;
        for (std::size_t k = 0; k < x.y.size(); ++k) {
            mx += x.y[k];
            my += y.y[k];
        }
        mx /= double(x.y.size());
        my /= double(y.y.size());
        double sxy = 0, sxx = 0;
        for (std::size_t k = 0; k < x.y.size(); ++k) {
            sxy += (x.y[k] - mx) * (y.y[k] - my);
            sxx += (x.y[k] - mx) * (x.y[k] - mx);
        }
        ASSERT_GT(sxx, 0);
        slopes += sxy / sxx / 2;
    }
    bool found = false;
    for (std::size_t r = 1; r < csv.size(); ++r) {
        if (csv[r][std::size_t(number)] == "fit_slope" && csv[r][std::size_t(test)] == "p100kPa") {
            EXPECT_NEAR(std::stod(csv[r][std::size_t(mean)]), slopes, 1e-6 * std::abs(slopes));
            found = true;
        }
    }
    EXPECT_TRUE(found);
}

#ifdef GRAINLAB_WITH_GUI
TEST_F(Reproduce, VoidCellPicturesShowCells) {
    ASSERT_EQ(status_, 0);
    for (const char* stem : {"05_p015kPa_start", "05_p015kPa_peak", "05_p100kPa_10pc"}) {
        const fs::path png = *folder_ / "report" / "figures" / (std::string(stem) + ".png");
        QImage image(QString::fromStdString(png.string()));
        ASSERT_FALSE(image.isNull()) << stem;
        // Cells are shaded by valence: count pixels that are neither white-ish (the cell, the
        // background) nor grey (the grains, their outlines).
        int coloured = 0;
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2) {
                const QColor c = image.pixelColor(x, y);
                const int spread = std::max({c.red(), c.green(), c.blue()}) -
                                   std::min({c.red(), c.green(), c.blue()});
                coloured += spread > 40 ? 1 : 0;
            }
        }
        EXPECT_GT(coloured, image.width() * image.height() / 4 / 50) << stem; // > 2 %
        EXPECT_TRUE(fs::exists(png.parent_path() / (std::string(stem) + ".csv")));
    }
}
#endif

TEST_F(Reproduce, ARunGivenTwiceIsRefusedNamingIt) {
    ASSERT_EQ(status_, 0);
    const fs::path seed1 = *folder_ / "study" / "runs" / "ref-seed1";
    const fs::path out = *folder_ / "twice";
    const std::string log = folder_->string() + "-twice.log";
    // The same folder under a second spelling (a trailing slash, a "." in it) is the same run.
    const std::string again = (seed1.parent_path() / "." / "ref-seed1").string() + "/";
    EXPECT_EQ(run(fmt::format("{} report {} {} --out {} > {} 2>&1", GRAINLAB_EXE, seed1.string(),
                              again, out.string(), log)),
              1);
    EXPECT_NE(text(log).find(again + ": this run is given twice (also as " + seed1.string()),
              std::string::npos)
        << text(log);
    EXPECT_FALSE(fs::exists(out / "headline.csv"));
    fs::remove(log);
}

TEST_F(Reproduce, OneRunsHeadlineTableJudgesNoScatterAsItsPageDoes) {
    ASSERT_EQ(status_, 0);
    const fs::path out = *folder_ / "one";
    ASSERT_EQ(run(fmt::format("{} report {} --out {} > /dev/null 2>&1", GRAINLAB_EXE,
                              (*folder_ / "study" / "runs" / "ref-seed1").string(), out.string())),
              0);
    const auto table = readCsv(out / "headline.csv");
    ASSERT_GT(table.size(), 1u);
    const int published = columnOf(table[0], "published"), agrees = columnOf(table[0], "agrees"),
              beyond = columnOf(table[0], "beyond_scatter"), runs = columnOf(table[0], "runs [-]");
    ASSERT_GE(std::min({published, agrees, beyond, runs}), 0);
    int judged = 0;
    for (std::size_t r = 1; r < table.size(); ++r) {
        const auto& row = table[r];
        if (row.size() <= std::size_t(beyond) || row[published].empty() || row[runs] != "1") {
            continue;
        }
        // One run: never "beyond the scatter" (σ = 0), as report.md says.
        EXPECT_EQ(row[beyond], "one run: no scatter") << row[0] << " " << row[2];
        if (row[0] != "I_uf_mean") {
            EXPECT_EQ(row[agrees], "one run: no scatter") << row[0] << " " << row[2];
        } else {
            EXPECT_TRUE(row[agrees] == "yes" || row[agrees] == "no") << row[agrees];
        }
        ++judged;
    }
    EXPECT_GT(judged, 0);
}

TEST(Report, RefusesRunsOfDifferentExperimentsAndUnfinishedRuns) {
    const fs::path folder = freshFolder("report-refusals");
    fs::create_directories(folder / "not-a-run");
    const std::string log = folder.string() + "/log.txt";
    EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " report " + (folder / "not-a-run").string() +
                  " --out " + (folder / "r").string() + " > " + log + " 2>&1"),
              1);
    EXPECT_NE(text(log).find("not a run folder"), std::string::npos) << text(log);
    fs::remove_all(folder);
}

} // namespace
} // namespace grainlab
