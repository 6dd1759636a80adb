// The crash test (issue 12): a small experiment (two compaction stages, friction during shear,
// two short shear tests) run to the end uninterrupted, then interrupted at many steps spread over
// every stage by SIGKILL, SIGINT or SIGTERM (the GRAINLAB_TEST_STOP_AFTER_STEPS hook of
// `grainlab run`), resumed with --resume, and required to give the same bits: every row of every
// series in the CSVs and in the run file, the samples, each test's peak checkpoint (of q/p,
// whose running maximum a resumed run takes over from its checkpoint) and the final state.
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_files.h"
#include "grainlab/csv_series.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation_state.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using test::execGrainlab;
using test::readText;

/// Two compaction stages of 200 ovals from the grid, two shear tests with friction 0.5 to
/// 0.3 %: about 71,000 steps (a second or two).
nlohmann::json crashExperiment() {
    nlohmann::json j = nlohmann::json::parse(
        readText(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json"));
    j["name"] = "crash";
    j["grains"]["count"] = 200;
    j["compaction"]["pressures"] = {25e3, 50e3};
    j["compaction"]["max_strain_rate"] = 60; // a shorter compaction: the test's running time
    j["shear"]["pressures"] = {25e3, 50e3};
    j["shear"]["target_axial_strain"] = 0.003;
    j["record"]["strain_interval"] = 2e-4;
    j["record"]["snapshot_strain_interval"] = 5e-4;
    j["record"]["step_interval"] = 500;
    j["record"]["snapshot_step_interval"] = 3000;
    return j;
}

/// Runs grainlab with `arguments`; stops itself after `stopAfter` steps with `signal` (none if
/// stopAfter is 0). Returns the wait status.
int runGrainlab(const std::vector<std::string>& arguments, std::int64_t stopAfter = 0,
                const char* signal = "KILL") {
    const pid_t child = fork();
    if (child == 0) {
        if (stopAfter > 0) {
            setenv("GRAINLAB_TEST_STOP_AFTER_STEPS", std::to_string(stopAfter).c_str(), 1);
            setenv("GRAINLAB_TEST_STOP_SIGNAL", signal, 1);
        }
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
        execGrainlab(arguments);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return status;
}

bool sameBits(const std::vector<std::vector<double>>& a,
              const std::vector<std::vector<double>>& b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t r = 0; r < a.size(); ++r) {
        if (a[r].size() != b[r].size() ||
            (!a[r].empty() && std::memcmp(a[r].data(), b[r].data(), a[r].size() * 8) != 0)) {
            return false;
        }
    }
    return true;
}

/// The series and states of a finished run folder, for comparison.
struct RunRecord {
    std::map<std::string, std::string> csv;
    std::map<std::string, SeriesTable> series;
    std::vector<double> samplePressures;
    std::vector<SimulationState> samples;
    std::map<std::string, CheckpointInfo> peakInfo; ///< by test
    std::map<std::string, SimulationState> peaks;   ///< by test
    SimulationState last;
};

RunRecord readRun(const fs::path& folder) {
    RunRecord r;
    const std::string file = (folder / "run.h5").string();
    for (const std::string& test : listTests(file)) {
        r.csv[test] = readText(folder / test / "series.csv");
        r.series[test] = readSeries(file, test);
    }
    r.samplePressures = listSamples(file);
    for (double p : r.samplePressures) {
        r.samples.push_back(readState(file, sampleGroup(p)));
    }
    for (const CheckpointInfo& info : listCheckpointInfo(file)) {
        if (info.peak) {
            EXPECT_EQ(r.peakInfo.count(info.test), 0u) << "two peak checkpoints of " << info.test;
            r.peakInfo[info.test] = info;
            r.peaks[info.test] = readState(file, checkpointGroup(info.name));
        }
    }
    r.last = readState(file, checkpointGroup(listCheckpoints(file).back()));
    return r;
}

/// What differs between the maps by test `a` and `b`: their sizes (of `what`), each test of `a`
/// that `b` lacks ("no <thing> <test>"), and for a test in both, what `differ(test, x, y)` says.
template <class Map, class Differ>
std::string differencesByTest(const Map& a, const Map& b, const std::string& what,
                              const std::string& thing, Differ differ) {
    std::string out;
    if (a.size() != b.size()) {
        out += fmt::format(" {} {} against {};", b.size(), what, a.size());
    }
    for (const auto& [test, value] : a) {
        const auto it = b.find(test);
        out +=
            it == b.end() ? fmt::format(" no {}{};", thing, test) : differ(test, value, it->second);
    }
    return out;
}

/// What differs between two runs ("" if nothing).
std::string differences(const RunRecord& a, const RunRecord& b) {
    std::string out = differencesByTest(
        a.csv, b.csv, "tests", "",
        [&](const std::string& test, const std::string& text, const std::string& other) {
            std::string d = other != text ? " " + test + "/series.csv;" : "";
            const SeriesTable& sa = a.series.at(test);
            const SeriesTable& sb = b.series.at(test);
            if (!sameBits(sa.rows, sb.rows) || sa.stages != sb.stages) {
                d += fmt::format(" run.h5 series {} ({} rows against {});", test, sb.rows.size(),
                                 sa.rows.size());
            }
            return d;
        });
    if (a.samplePressures != b.samplePressures) {
        out += " sample list;";
    } else {
        for (std::size_t k = 0; k < a.samples.size(); ++k) {
            if (!identicalDynamics(a.samples[k], b.samples[k])) {
                out += fmt::format(" sample {} Pa;", a.samplePressures[k]);
            }
        }
    }
    out += differencesByTest(
        a.peaks, b.peaks, "peak checkpoints", "peak checkpoint of ",
        [&](const std::string& test, const SimulationState& state, const SimulationState& other) {
            const bool same =
                identicalDynamics(state, other) &&
                a.peakInfo.at(test).peakStressRatio == b.peakInfo.at(test).peakStressRatio &&
                a.peakInfo.at(test).axialStrain == b.peakInfo.at(test).axialStrain;
            return same ? std::string()
                        : fmt::format(" peak checkpoint of {} (step {} against {});", test,
                                      other.step, state.step);
        });
    if (!identicalDynamics(a.last, b.last)) {
        out += fmt::format(" final state (step {} against {});", b.last.step, a.last.step);
    }
    return out;
}

/// An interruption of a run: after `step` steps of its process, by `signal`.
struct Case {
    std::string what;
    std::int64_t step; ///< steps of the interrupted process
    const char* signal;
};

/// Runs `experiment` into base/caseNN for each case, stopped as the case says, resumes it with
/// --resume, and compares the finished folder with `reference`; a folder that matches is
/// removed. Returns the failures, one line each ("" when every case matched).
std::string runCases(const fs::path& base, const fs::path& experiment, const RunRecord& reference,
                     const std::vector<Case>& cases) {
    std::string failed;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Case& c = cases[k];
        const fs::path out = base / fmt::format("case{:02d}", k);
        const std::string label = fmt::format("{} ({} after {} steps)", c.what, c.signal, c.step);
        const int first =
            runGrainlab({"run", experiment.string(), "--out", out.string()}, c.step, c.signal);
        if (std::string(c.signal) == "KILL") {
            EXPECT_TRUE(WIFSIGNALED(first) && WTERMSIG(first) == SIGKILL) << label;
        } else {
            EXPECT_TRUE(WIFEXITED(first) && WEXITSTATUS(first) == 130) << label;
        }
        const int second = runGrainlab({"run", "--resume", out.string()});
        if (!(WIFEXITED(second) && WEXITSTATUS(second) == 0)) {
            ADD_FAILURE() << label << ": --resume failed (status " << second << ")";
            failed += "\n  " + label + ": --resume failed";
            continue;
        }
        const std::string diff = differences(reference, readRun(out));
        if (!diff.empty()) {
            ADD_FAILURE() << label << ": differs in" << diff;
            failed += "\n  " + label + ":" + diff;
        } else {
            fs::remove_all(out);
        }
    }
    return failed;
}

TEST(CrashResume, EveryInterruptionResumesToTheSameBits) {
    const fs::path base =
        fs::temp_directory_path() / fmt::format("grainlab-test-crash-{}", getpid());
    fs::remove_all(base);
    fs::create_directories(base);
    const fs::path experiment = base / "experiment.json";
    std::ofstream(experiment) << crashExperiment().dump(2);

    const fs::path whole = base / "whole";
    const int wholeStatus = runGrainlab({"run", experiment.string(), "--out", whole.string()});
    ASSERT_TRUE(WIFEXITED(wholeStatus) && WEXITSTATUS(wholeStatus) == 0);
    const RunRecord reference = readRun(whole);
    ASSERT_EQ(reference.peaks.size(), 2u) << "one peak checkpoint per shear test";

    // Where the stages are, in steps of one uninterrupted process: the compaction runs from
    // step 0; each test starts from its sample's step, after everything before it.
    const auto stageSteps = [&](const std::string& test, const std::string& stage) {
        const SeriesTable& t = reference.series.at(test);
        const int step = t.column("step");
        std::pair<std::int64_t, std::int64_t> range{-1, -1};
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            if (t.stages[r] == stage) {
                const auto s = static_cast<std::int64_t>(t.rows[r][step]);
                range.first = range.first < 0 ? s : range.first;
                range.second = s;
            }
        }
        EXPECT_GE(range.first, 0) << test << ": no stage " << stage;
        return range;
    };
    const auto c25 = stageSteps("compaction", "compaction 25 kPa");
    const auto c50 = stageSteps("compaction", "compaction 50 kPa");
    const auto e25 = stageSteps("p025kPa", "equilibration 25 kPa");
    const auto s25 = stageSteps("p025kPa", "shear 25 kPa");
    const auto e50 = stageSteps("p050kPa", "equilibration 50 kPa");
    const auto s50 = stageSteps("p050kPa", "shear 50 kPa");
    const std::int64_t compactionEnd = c50.second;
    const std::int64_t test1 = compactionEnd - c25.second;      // process - sim step
    const std::int64_t test2 = test1 + s25.second - c50.second; // (test 2 from sample 2)
    // Its kill points (+500, +1213) fall inside stage 2, before its first periodic checkpoint
    // (3000 steps into the stage).
    ASSERT_GT(c50.second - c25.second, 1300) << "stage 2 too short for the kill points";

    const std::int64_t s25len = s25.second - s25.first, s50len = s50.second - s50.first;
    const std::vector<Case> cases = {
        {"compaction stage 1, before its first checkpoint", 1700, "KILL"},
        {"compaction stage 1, just after a checkpoint", 6000, "KILL"},
        {"compaction stage 1, mid-stage", c25.second / 2 + 777, "KILL"},
        {"compaction stage 1, SIGTERM", c25.second / 3 + 41, "TERM"},
        {"compaction stage 1, at its end", c25.second, "KILL"},
        {"compaction stage 2, before its first checkpoint", c25.second + 500, "KILL"},
        {"compaction stage 2, SIGINT", c25.second + 1213, "INT"},
        {"compaction, at its end", compactionEnd, "KILL"},
        {"equilibration 25 kPa, early", test1 + e25.first + 300, "KILL"},
        {"equilibration 25 kPa, SIGINT", test1 + e25.first + 1111, "INT"},
        {"shear 25 kPa, before its first checkpoint", test1 + s25.first + 250, "KILL"},
        {"shear 25 kPa, SIGINT early", test1 + s25.first + 613, "INT"},
        {"shear 25 kPa, SIGINT", test1 + s25.first + s25len / 3 + 7, "INT"},
        {"shear 25 kPa, SIGINT mid", test1 + s25.first + s25len / 2 + 1, "INT"},
        {"shear 25 kPa, SIGTERM late", test1 + s25.first + 2 * s25len / 3 + 3, "TERM"},
        {"shear 25 kPa, late", test1 + s25.second - 1, "KILL"},
        {"shear 25 kPa, at its end", test1 + s25.second, "KILL"},
        {"equilibration 50 kPa", test2 + e50.first + 700, "KILL"},
        {"shear 50 kPa, SIGINT mid", test2 + s50.first + s50len / 2 + 13, "INT"},
        {"shear 50 kPa, mid", test2 + s50.first + s50len / 2 + 301, "KILL"},
        {"shear 50 kPa, late SIGINT", test2 + s50.second - 2, "INT"},
        {"the run, at its very end", test2 + s50.second, "KILL"},
    };
    const std::string failed = runCases(base, experiment, reference, cases);
    if (!failed.empty()) {
        std::fprintf(stderr, "crash cases that failed:%s\n", failed.c_str());
    } else {
        fs::remove_all(base);
    }
}

// Every test kind through the run file: constant volume, a drained test in extension followed by
// probes from a strain of it (their start state kept in the run file's group probe_start until
// they start), and a cyclic test at constant volume, each killed or stopped in its middle and
// resumed with --resume, gives the same bits as the uninterrupted run.
TEST(CrashResume, EveryTestKindResumesFromAStopInItsMiddleToTheSameBits) {
    const fs::path base =
        fs::temp_directory_path() / fmt::format("grainlab-test-crash-kinds-{}", getpid());
    fs::remove_all(base);
    fs::create_directories(base);
    nlohmann::json j = crashExperiment();
    j["compaction"]["pressures"] = {25e3};
    j["shear"]["pressures"] = {25e3};
    j["test"] = nlohmann::json::parse(R"([
        {"kind": "constant_volume"},
        {"kind": "drained", "direction": "extension"},
        {"kind": "probes", "start": "strain", "start_strain": 0.001, "count": 8,
         "increment": 1e-5},
        {"kind": "cyclic", "amplitude": 5e-4, "cycles": 2, "drainage": "constant_volume"}])");
    const fs::path experiment = base / "experiment.json";
    std::ofstream(experiment) << j.dump(2);

    const fs::path whole = base / "whole";
    const int wholeStatus = runGrainlab({"run", experiment.string(), "--out", whole.string()});
    ASSERT_TRUE(WIFEXITED(wholeStatus) && WEXITSTATUS(wholeStatus) == 0);
    const RunRecord reference = readRun(whole);
    ASSERT_EQ(reference.series.size(), 5u); // compaction and four tests

    // The simulation steps of each stage, and where a chain of stages from the sample (its
    // re-equilibration, its test, and the probes that follow without one) ends.
    const auto steps = [&](const std::string& test, const std::string& stage) {
        const SeriesTable& t = reference.series.at(test);
        std::pair<std::int64_t, std::int64_t> range{-1, -1};
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            if (t.stages[r] == stage) {
                const auto s = static_cast<std::int64_t>(t.rows[r][std::size_t(t.column("step"))]);
                range.first = range.first < 0 ? s : range.first;
                range.second = s;
            }
        }
        EXPECT_GE(range.first, 0) << test << ": no stage " << stage;
        return range;
    };
    const std::int64_t sample = steps("compaction", "compaction 25 kPa").second;
    const auto cv = steps("p025kPa-constant-volume", "constant_volume 25 kPa");
    const auto ext = steps("p025kPa-extension", "shear 25 kPa");
    const auto probes = steps("p025kPa-probes", "probes 25 kPa");
    const auto cyclic = steps("p025kPa-cyclic", "cyclic 25 kPa");
    // Steps of the process at simulation step s of each chain (each starts from the sample).
    const std::int64_t chain2 = sample + (cv.second - sample);
    const std::int64_t chain3 = chain2 + (probes.second - sample);
    const auto at = [&](std::int64_t chainStart, std::int64_t s) {
        return chainStart + s - sample;
    };
    const std::int64_t strainPoint = ext.first + 2000; // eps1 = -0.1 %
    const std::vector<Case> cases = {
        {"constant volume, mid", at(sample, (cv.first + cv.second) / 2 + 17), "KILL"},
        {"extension, before the probes' start strain", at(chain2, strainPoint - 301), "INT"},
        {"extension, after the probes' start strain", at(chain2, strainPoint + 1207), "KILL"},
        {"extension, at its end", at(chain2, ext.second), "KILL"},
        {"probes, mid", at(chain2, (probes.first + probes.second) / 2 + 5), "INT"},
        {"cyclic, mid", at(chain3, (cyclic.first + cyclic.second) / 2 + 3), "KILL"},
    };
    const std::string failed = runCases(base, experiment, reference, cases);
    if (failed.empty()) {
        fs::remove_all(base);
    }
}

} // namespace
} // namespace grainlab

namespace grainlab {
namespace {

// A run file written before the run file's large datasets were compressed (tests/data: 40 ovals
// interrupted in compaction by the GrainLab of that time) is read and resumed by this one, which
// writes its new checkpoints compressed, to the same bits as a run of the same experiment made
// from the start now.
TEST(CrashResume, ARunFileFromBeforeCompressionResumesToTheSameBits) {
    const fs::path fixture = fs::path(GRAINLAB_SOURCE_DIR) / "tests/data/run-before-compression";
    const fs::path base = test::freshFolder("crash", "before-compression");
    const fs::path old = base / "old";
    fs::copy(fixture, old, fs::copy_options::recursive);
    fs::remove(old / "experiment.json");
    const std::vector<std::string> before = listCheckpoints((old / "run.h5").string());
    ASSERT_EQ(before.size(), 2u);
    const int resumed = runGrainlab({"run", "--resume", old.string(), "--quiet"});
    ASSERT_TRUE(WIFEXITED(resumed) && WEXITSTATUS(resumed) == 0) << resumed;
    EXPECT_GT(listCheckpoints((old / "run.h5").string()).size(), before.size());
    const fs::path fresh = base / "fresh";
    const int ran = runGrainlab(
        {"run", (fixture / "experiment.json").string(), "--out", fresh.string(), "--quiet"});
    ASSERT_TRUE(WIFEXITED(ran) && WEXITSTATUS(ran) == 0) << ran;
    EXPECT_EQ(differences(readRun(fresh), readRun(old)), "");
    fs::remove_all(base);
}

} // namespace
} // namespace grainlab
