// `grainlab study` end to end on the tiny study (resources/studies/tiny.json: 150 ovals, two
// pressures, shear to 2 %, two knobs at two levels, two seeds): every file written, the
// reference's errors exactly zero, the threads knob changing nothing, the summary against a hand
// computation from study.csv, the recommendation the cheapest valid setting; a killed study that
// resumes redoes no finished run and gives the same results; the GNU parallel job list run line
// by line with bash gives the same results as the local pool.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_folders.h"

#include "grainlab/statistics.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;
using test::childrenOf;
using test::freshFolder;
using test::run;
using test::text;

const std::string kStudy = GRAINLAB_SOURCE_DIR "/resources/studies/tiny.json";

/// A CSV file as rows of cells (no quoted cells in the study's files).
using Table = std::vector<std::vector<std::string>>;
Table readCsv(const fs::path& p) {
    Table t;
    std::istringstream in(text(p));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream row(line);
        while (std::getline(row, cell, ',')) {
            cells.push_back(cell);
        }
        if (!line.empty() && line.back() == ',') {
            cells.emplace_back();
        }
        t.push_back(cells);
    }
    return t;
}

int columnOf(const Table& t, const std::string& name) {
    const auto& h = t.at(0);
    const auto it = std::find(h.begin(), h.end(), name);
    return it == h.end() ? -1 : int(it - h.begin());
}

/// summary.csv without what depends on timing: the cost rows and the "recommended" column.
std::vector<std::string> resultRows(const fs::path& dir) {
    const Table t = readCsv(dir / "summary.csv");
    const int test = columnOf(t, "test"), recommended = columnOf(t, "recommended");
    std::vector<std::string> out;
    for (std::size_t r = 1; r < t.size(); ++r) {
        if (t[r][std::size_t(test)] == "cost") {
            continue;
        }
        std::string line;
        for (std::size_t c = 0; c < t[r].size(); ++c) {
            if (int(c) != recommended) {
                line += t[r][c] + ",";
            }
        }
        out.push_back(line);
    }
    return out;
}

/// study.csv's metric cells by run (the cost columns left out).
std::map<std::string, std::vector<std::string>> runMetrics(const fs::path& dir) {
    const Table t = readCsv(dir / "study.csv");
    const int wall = columnOf(t, "wall_seconds [s]");
    std::map<std::string, std::vector<std::string>> out;
    for (std::size_t r = 1; r < t.size(); ++r) {
        out[t[r][0]] = std::vector<std::string>(t[r].begin(), t[r].begin() + wall);
    }
    return out;
}

/// One uninterrupted run of the tiny study, shared by the tests of this binary.
const fs::path& referenceStudy() {
    static const fs::path dir = [] {
        const fs::path d = freshFolder("reference");
        EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " study " + kStudy + " --out " + d.string() +
                      " --quiet > " + d.string() + ".log 2>&1"),
                  0)
            << text(d.string() + ".log");
        return d;
    }();
    return dir;
}

TEST(StudyCommand, TinyStudyWritesEveryFileAndTheNumbersAddUp) {
    const fs::path& dir = referenceStudy();
    for (const char* f : {"study.json", "study.csv", "summary.csv", "recommended.json"}) {
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    }
#ifdef GRAINLAB_WITH_GUI
    for (const char* f :
         {"error-cost_peak_q_over_p_p015kPa", "error-cost_rms_epsv_p100kPa",
          "curves_q_over_p_p015kPa", "peak_q_over_p_vs_time_step_fraction_p100kPa"}) {
        for (const char* format : {".png", ".svg", ".pdf"}) {
            EXPECT_GT(fs::file_size(dir / "figures" / (std::string(f) + format)), 1000u) << f;
        }
    }
#endif
    const std::vector<std::string> runs{"ref-seed1",
                                        "ref-seed2",
                                        "time_step_fraction-0.5-seed1",
                                        "time_step_fraction-0.5-seed2",
                                        "threads-2-seed1",
                                        "threads-2-seed2"};
    for (const std::string& r : runs) {
        EXPECT_TRUE(fs::exists(dir / "runs" / r / "run.h5")) << r;
        EXPECT_TRUE(fs::exists(dir / "runs" / r / "p015kPa" / "series.csv")) << r;
        EXPECT_TRUE(fs::exists(dir / "experiments" / (r + ".json"))) << r;
        EXPECT_NE(text(dir / "runs" / r / "cost.json").find("\"finished\": true"),
                  std::string::npos)
            << r;
    }

    const Table study = readCsv(dir / "study.csv");
    ASSERT_EQ(study.size(), 7u);
    const Table summary = readCsv(dir / "summary.csv");
    const int setting = columnOf(summary, "setting"), test = columnOf(summary, "test");
    const int metric = columnOf(summary, "metric"), mean = columnOf(summary, "mean");
    const int sd = columnOf(summary, "sd"), error = columnOf(summary, "error");
    const int valid = columnOf(summary, "valid"), recommended = columnOf(summary, "recommended");
    const int withinTolerance = columnOf(summary, "within_tolerance");
    ASSERT_GE(std::min({setting, test, metric, mean, sd, error, valid, recommended}), 0);
    const auto row = [&](const std::string& s, const std::string& t, const std::string& m) {
        for (const auto& r : summary) {
            if (r[std::size_t(setting)] == s && r[std::size_t(test)] == t &&
                r[std::size_t(metric)] == m) {
                return r;
            }
        }
        ADD_FAILURE() << "no row " << s << " " << t << " " << m;
        return std::vector<std::string>(summary[0].size());
    };

    for (const char* t : {"p015kPa", "p100kPa"}) {
        for (const char* m : {"peak_q_over_p", "e_compacted", "rms_q_over_p", "rms_epsv"}) {
            // The reference against itself, and the threads knob, which changes no bit.
            EXPECT_EQ(std::stod(row("ref", t, m)[std::size_t(error)]), 0.0) << t << m;
            EXPECT_EQ(std::stod(row("threads-2", t, m)[std::size_t(error)]), 0.0) << t << m;
        }
    }

    // Mean, sd and error of one metric, by hand from study.csv.
    const int column = columnOf(study, "p015kPa.peak_q_over_p [-]");
    ASSERT_GE(column, 0);
    std::map<std::string, std::vector<double>> bySetting;
    for (std::size_t r = 1; r < study.size(); ++r) {
        bySetting[study[r][1]].push_back(std::stod(study[r][std::size_t(column)]));
    }
    const Scatter a = scatterOf(bySetting["time_step_fraction-0.5"]);
    const Scatter ref = scatterOf(bySetting["ref"]);
    const auto half = row("time_step_fraction-0.5", "p015kPa", "peak_q_over_p");
    EXPECT_NEAR(std::stod(half[std::size_t(mean)]), a.mean, 1e-15);
    EXPECT_NEAR(std::stod(half[std::size_t(sd)]), a.sd, 1e-15);
    EXPECT_NEAR(std::stod(half[std::size_t(error)]), a.mean - ref.mean, 1e-15);

    // The recommendation: valid, and no valid setting is cheaper.
    std::map<std::string, double> cost;
    std::map<std::string, bool> isValid;
    std::string chosen;
    for (std::size_t r = 1; r < summary.size(); ++r) {
        const auto& s = summary[r];
        if (s[std::size_t(test)] == "cost" && s[std::size_t(metric)] == "cpu_seconds") {
            cost[s[std::size_t(setting)]] = std::stod(s[std::size_t(mean)]);
        }
        isValid[s[std::size_t(setting)]] = s[std::size_t(valid)] == "yes";
        if (s[std::size_t(recommended)] == "yes") {
            chosen = s[std::size_t(setting)];
        }
        if (s[std::size_t(valid)] == "yes" && s[std::size_t(test)] != "cost" &&
            !s[std::size_t(withinTolerance)].empty()) {
            // A valid setting is within tolerance on every deciding metric.
            if (s.back() == "yes") {
                EXPECT_EQ(s[std::size_t(withinTolerance)], "yes") << r;
            }
        }
    }
    ASSERT_FALSE(chosen.empty());
    EXPECT_TRUE(isValid[chosen]);
    for (const auto& [s, c] : cost) {
        if (isValid[s]) {
            EXPECT_LE(cost[chosen], c) << s;
        }
    }
    EXPECT_NE(text(dir / "recommended.json").find("\"grains\""), std::string::npos);
}

TEST(StudyCommand, AKilledStudyResumesWithoutRedoingFinishedRuns) {
    const fs::path dir = freshFolder("killed");
    const pid_t study = ::fork();
    if (study == 0) {
        const std::string out = dir.string();
        ::execl(GRAINLAB_EXE, GRAINLAB_EXE, "study", kStudy.c_str(), "--out", out.c_str(),
                "--quiet", "--jobs", "1", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Kill the study and its running run hard once two runs have finished.
    const auto finished = [&] {
        int n = 0;
        if (fs::exists(dir / "runs")) {
            for (const auto& r : fs::directory_iterator(dir / "runs")) {
                n += text(r.path() / "cost.json").find("\"finished\": true") != std::string::npos;
            }
        }
        return n;
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (finished() < 2 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // Stopped first, so that it starts no run between the listing of its runs and the kill.
    ::kill(study, SIGSTOP);
    const auto stopped = [&] {
        std::istringstream stat(text(fs::path("/proc") / std::to_string(study) / "stat"));
        std::string pid, comm, state;
        stat >> pid >> comm >> state;
        return state == "T";
    };
    while (!stopped()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    for (pid_t child : childrenOf(study)) {
        ::kill(child, SIGKILL);
    }
    ::kill(study, SIGKILL);
    int status = 0;
    ::waitpid(study, &status, 0);
    ASSERT_GE(finished(), 2);
    ASSERT_LT(finished(), 6) << "the study ended before it could be killed";
    std::map<std::string, std::string> before;
    for (const auto& r : fs::directory_iterator(dir / "runs")) {
        const std::string cost = text(r.path() / "cost.json");
        if (cost.find("\"finished\": true") != std::string::npos) {
            before[r.path().filename()] = cost;
        }
    }
    EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " study " + kStudy + " --out " + dir.string() +
                  " --quiet > " + dir.string() + ".log 2>&1"),
              0)
        << text(dir.string() + ".log");
    for (const auto& [name, cost] : before) {
        EXPECT_EQ(text(dir / "runs" / name / "cost.json"), cost) << name << " was run again";
    }
    EXPECT_EQ(resultRows(dir), resultRows(referenceStudy()));
    EXPECT_EQ(runMetrics(dir), runMetrics(referenceStudy()));
}

TEST(StudyCommand, TheParallelJobListGivesTheSameResultsAsThePool) {
    const fs::path dir = freshFolder("parallel");
    ASSERT_EQ(run(std::string(GRAINLAB_EXE) + " study " + kStudy + " --out " + dir.string() +
                  " --emit parallel > /dev/null"),
              0);
    EXPECT_FALSE(fs::exists(dir / "runs" / "ref-seed1" / "run.h5")); // nothing run yet
    std::istringstream lines(text(dir / "jobs.txt"));
    int count = 0;
    for (std::string line; std::getline(lines, line); ++count) {
        const fs::path script = dir / "job.sh";
        std::ofstream(script) << line << "\n";
        ASSERT_EQ(run("bash " + script.string() + " > /dev/null 2>&1"), 0) << line;
    }
    EXPECT_EQ(count, 6);
    // collect: all finished (status 0), the same results as the local pool.
    ASSERT_EQ(run(std::string(GRAINLAB_EXE) + " study collect " + dir.string() + " --quiet"), 0);
    EXPECT_EQ(resultRows(dir), resultRows(referenceStudy()));
    EXPECT_EQ(runMetrics(dir), runMetrics(referenceStudy()));

    // The Slurm script of the same study is valid bash and names every run.
    ASSERT_EQ(run(std::string(GRAINLAB_EXE) + " study " + kStudy + " --out " + dir.string() +
                  " --emit slurm > /dev/null"),
              0);
    const std::string slurm = text(dir / "study.slurm");
    EXPECT_EQ(run("bash -n " + (dir / "study.slurm").string()), 0);
    for (const auto& r : fs::directory_iterator(dir / "experiments")) {
        EXPECT_NE(slurm.find("'" + r.path().stem().string() + "'"), std::string::npos) << r.path();
    }
}

TEST(StudyCommand, RefusesAFolderOfAnotherStudyAndABadStudyFile) {
    const fs::path dir = freshFolder("refusals");
    fs::create_directories(dir);
    std::ofstream(dir / "notes.txt") << "mine\n";
    EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " study " + kStudy + " --out " + dir.string() +
                  " --emit parallel > " + dir.string() + ".log 2>&1"),
              1);
    EXPECT_NE(text(dir.string() + ".log").find("holds no study"), std::string::npos)
        << text(dir.string() + ".log");
    EXPECT_EQ(text(dir / "notes.txt"), "mine\n");

    const fs::path bad = dir.string() + "-bad.json";
    std::ofstream(bad) << R"({"base": ")" << GRAINLAB_SOURCE_DIR
                       << R"(/resources/experiments/tiny.json", "knobs": {"threads": [0]}})";
    EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " study " + bad.string() + " --out " + dir.string() +
                  "-new > " + dir.string() + ".log 2>&1"),
              1);
    EXPECT_NE(text(dir.string() + ".log").find("knobs.threads[0]"), std::string::npos)
        << text(dir.string() + ".log");
    EXPECT_FALSE(fs::exists(dir.string() + "-new"));
}

} // namespace
} // namespace grainlab
