// cost.json, what a run folder's run has cost: written by every `grainlab run` process, summed
// over the processes of a resumed run, and marked finished only when the run is.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "cli_test_files.h"
#include "common/run_cost.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using test::readText;

fs::path freshFolder(const std::string& name) {
    return test::freshFolder("cost", name);
}

/// 120 grains, one pressure, a short shear.
fs::path tinyExperiment(const fs::path& folder) {
    nlohmann::json j = nlohmann::json::parse(
        readText(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json"));
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = 0.002;
    const fs::path p = folder / "experiment.json";
    std::ofstream(p) << j.dump(2);
    return p;
}

int grainlab(const std::string& arguments, const std::string& environment = "") {
    return std::system(
        fmt::format("{} {} run {} > /dev/null 2>&1", environment, GRAINLAB_EXE, arguments).c_str());
}

TEST(RunCost, SummedOverTheProcessesOfAResumedRunAndFinishedOnlyAtTheEnd) {
    const fs::path base = freshFolder("resumed");
    const fs::path experiment = tinyExperiment(base);
    ASSERT_EQ(grainlab(fmt::format("{} --out {} --quiet", experiment.string(),
                                   (base / "whole").string())),
              0);
    const RunCostRecord whole = readRunCost((base / "whole").string());
    EXPECT_TRUE(whole.finished);
    EXPECT_EQ(whole.processes, 1);
    EXPECT_GT(whole.steps, 1000);
    EXPECT_EQ(whole.grainSteps, whole.steps * 120);
    EXPECT_GT(whole.cpuSeconds, 0);
    EXPECT_GE(whole.wallSeconds, 0.5 * whole.cpuSeconds);
    EXPECT_EQ(whole.threads, 1);
    // Where the wall time went: each part measured, together no more than the process's wall.
    const RunnerTimes& t = whole.times;
    EXPECT_GT(t.stepping, 0);
    EXPECT_GT(t.records, 0);
    EXPECT_GT(t.checkpoints, 0);
    EXPECT_GE(t.events, 0);
    EXPECT_LE(t.stepping + t.records + t.checkpoints + t.events, whole.wallSeconds);

    // Interrupted (Ctrl-C) after 3000 steps, then resumed.
    const std::string parts = (base / "parts").string();
    grainlab(fmt::format("{} --out {} --quiet", experiment.string(), parts),
             "GRAINLAB_TEST_STOP_AFTER_STEPS=3000 GRAINLAB_TEST_STOP_SIGNAL=INT");
    const RunCostRecord first = readRunCost(parts);
    EXPECT_FALSE(first.finished);
    EXPECT_EQ(first.processes, 1);
    EXPECT_EQ(first.steps, 3000);
    ASSERT_EQ(grainlab(fmt::format("--resume {} --quiet", parts)), 0);
    const RunCostRecord total = readRunCost(parts);
    EXPECT_TRUE(total.finished);
    EXPECT_EQ(total.processes, 2);
    // The resumed process redid the steps since the checkpoint: at least the whole run's steps.
    EXPECT_GE(total.steps, whole.steps);
    EXPECT_GT(total.cpuSeconds, first.cpuSeconds);
    EXPECT_GT(total.times.stepping, first.times.stepping);
    EXPECT_GT(total.times.checkpoints, first.times.checkpoints);
}

TEST(RunCost, TheRunSaysWhereItsTimeWentAndCostJsonAgrees) {
    const fs::path base = freshFolder("told");
    const std::string out = (base / "run").string();
    const test::CommandOutput r =
        test::grainlabOutput(fmt::format("run {} --out {}", tinyExperiment(base).string(), out));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string line = "grainlab run: time in this process: stepping ";
    const std::size_t at = r.output.find(line);
    ASSERT_NE(at, std::string::npos) << r.output;
    // The four parts' shares, as printed, add up to 100 %.
    double shares = 0;
    std::size_t from = at;
    for (int part = 0; part < 4; ++part) {
        const std::size_t open = r.output.find(" (", from), close = r.output.find(" %)", open);
        ASSERT_NE(close, std::string::npos) << r.output.substr(at);
        shares += std::stod(r.output.substr(open + 2, close - open - 2));
        from = close;
    }
    EXPECT_NEAR(shares, 100.0, 0.25) << r.output.substr(at);
    // One process: cost.json's seconds are the ones printed.
    const RunnerTimes t = readRunCost(out).times;
    EXPECT_NE(r.output.find(fmt::format("stepping {:.1f} s", t.stepping)), std::string::npos);
    EXPECT_NE(r.output.find(fmt::format("records {:.1f} s", t.records)), std::string::npos);
}

TEST(RunCost, AFinishedRunWhoseRecordMissedTheEndIsMarkedFinishedOnResume) {
    const fs::path base = freshFolder("missed");
    const std::string out = (base / "run").string();
    ASSERT_EQ(grainlab(fmt::format("{} --out {} --quiet", tinyExperiment(base).string(), out)), 0);
    RunCostRecord cost = readRunCost(out);
    cost.finished = false; // as if killed between the last checkpoint and the cost record
    writeRunCost(out, cost);
    const std::string runFile = readText(fs::path(out) / "run.h5");
    ASSERT_EQ(grainlab(fmt::format("--resume {} --quiet", out)), 0);
    const RunCostRecord after = readRunCost(out);
    EXPECT_TRUE(after.finished);
    EXPECT_EQ(after.steps, cost.steps);
    EXPECT_EQ(after.processes, cost.processes);
    EXPECT_EQ(readText(fs::path(out) / "run.h5"), runFile) << "the finished run was changed";
}

TEST(RunCost, ABadRecordIsRefusedNamingTheFile) {
    const fs::path base = freshFolder("bad");
    std::ofstream(base / "cost.json") << "{\"finished\": 1}";
    try {
        readRunCost(base.string());
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("cost.json"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(readRunCost((base / "none").string()).finished); // no record: nothing spent
}

TEST(RunCost, ARecordWrittenBeforeTheTimeBreakdownReadsWithZeroParts) {
    const RunCostRecord old =
        readRunCost(std::string(GRAINLAB_SOURCE_DIR) + "/tests/data/run-before-compression");
    EXPECT_EQ(old.steps, 2000);
    EXPECT_GT(old.cpuSeconds, 0);
    EXPECT_EQ(old.times.stepping + old.times.records + old.times.checkpoints + old.times.events,
              0.0);
}

} // namespace
} // namespace grainlab
