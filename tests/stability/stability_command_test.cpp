// `grainlab stability` end to end through the real executable on the tiny preset: every cell
// writes its result, limits.csv has a row per cell with the estimate beside the measured limit,
// a second run redoes no cell, and the emitted Slurm script and job list are well formed.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "test_folders.h"

#include "common/job_list.h"
#include "grainlab/stability_map.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using namespace test;
const auto run = test::runQuietly;

TEST(StabilityCommand, TinyMapEndToEndAndResumes) {
    const fs::path dir = presetRunFolder("tiny");
    const StabilityMapSpec spec = readStabilityPreset(stabilityPresetFile("tiny"));
    const auto cells = stabilityCells(spec);
    ASSERT_EQ(cells.size(), 4u);
    std::map<std::string, fs::file_time_type> written;
    for (const StabilityCell& c : cells) {
        const fs::path file = cellFile(dir, c.id);
        ASSERT_TRUE(fs::exists(file)) << file;
        written[c.id] = fs::last_write_time(file);
        const StabilityCellResult r = parseCellResult(text(file), file.string());
        EXPECT_TRUE(r.limit.bracketed) << c.id;
        EXPECT_GT(r.limit.limit, spec.lowBound) << c.id;
        EXPECT_LT(r.limit.limit, spec.highBound) << c.id;
        EXPECT_LE(r.limit.high / r.limit.low - 1.0, spec.precision) << c.id;
        EXPECT_NE(r.limit.detector, BlowUp::None) << c.id;
        EXPECT_GT(r.estimate, 0.0) << c.id;
        EXPECT_EQ(r.accuracy.size(), spec.accuracyFractions.size()) << c.id;
    }
    const std::string csv = text(dir / "limits.csv");
    std::istringstream lines(csv);
    std::string header, line;
    std::getline(lines, header);
    EXPECT_NE(header.find("limit [sqrt(m_min/k_n)]"), std::string::npos);
    EXPECT_NE(header.find("estimate [sqrt(m_min/k_n)]"), std::string::npos);
    EXPECT_NE(header.find("limit_over_estimate [-]"), std::string::npos);
    int rows = 0;
    while (std::getline(lines, line)) {
        ++rows;
        EXPECT_EQ(line.find("nan"), std::string::npos) << line;
    }
    EXPECT_EQ(rows, 4);
    EXPECT_TRUE(fs::exists(dir / "accuracy.csv"));
    EXPECT_EQ(
        missingFigures(dir, {"limit_aspect_ratio_packing.svg", "ratio_aspect_ratio_packing.png"}),
        std::vector<std::string>{});

    // Killed or finished, the same command redoes no finished cell: remove one result, and only
    // that cell runs again.
    fs::remove(cellFile(dir, cells[1].id));
    ASSERT_EQ(runStabilityPreset("tiny", dir), 0);
    for (const StabilityCell& c : cells) {
        const auto now = fs::last_write_time(cellFile(dir, c.id));
        if (c.id == cells[1].id) {
            EXPECT_NE(now, written[c.id]);
        } else {
            EXPECT_EQ(now, written[c.id]) << c.id << " was redone";
        }
    }
    EXPECT_EQ(runStability("collect " + dir.string() + " --quiet"), 0);
    // A cell run again by hand (a resubmitted array task) finds its result and does nothing.
    ASSERT_EQ(runStability("cell " + dir.string() + " --cell " + cells[0].id), 0);
    EXPECT_EQ(fs::last_write_time(cellFile(dir, cells[0].id)), written[cells[0].id]);
    fs::remove_all(dir);
}

TEST(StabilityCommand, EmitsASlurmArrayAndAJobList) {
    const fs::path dir = freshFolder("emit");
    ASSERT_EQ(runStabilityPreset("full", dir, "--emit slurm"), 0);
    const fs::path script = dir / "stability.slurm";
    ASSERT_TRUE(fs::exists(script));
    EXPECT_EQ(run("bash -n " + script.string()), 0);
    const std::string s = text(script);
    EXPECT_NE(s.find("#SBATCH --array=0-255"), std::string::npos);
    EXPECT_NE(s.find("eta0.4_kt2_local0.7_shear15kPa"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "cells" / "eta1_kt0.25_none_gas.json")) << "emit runs nothing";
    ASSERT_EQ(runStabilityPreset("full", dir, "--emit parallel"), 0);
    const std::string jobs = text(dir / "jobs.txt");
    EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 256);
    EXPECT_EQ(run("bash -n " + (dir / "jobs.txt").string()), 0);
    // Collecting a map with no cell done yet: an empty table and exit status 3.
    EXPECT_EQ(runStability("collect " + dir.string() + " --quiet"), 3);
    fs::remove_all(dir);
}

TEST(StabilityCommand, RefusesAFolderOfAnotherMap) {
    const fs::path dir = freshFolder("other");
    ASSERT_EQ(runStabilityPreset("full", dir, "--emit parallel"), 0);
    EXPECT_NE(runStabilityPreset("tiny", dir), 0);
    EXPECT_NE(runStability("--out " + dir.string()), 0) << "no preset given";
    fs::remove_all(dir);
}

TEST(StabilityJobList, ASlurmArrayOfArbitraryCommandsRunsEachTask) {
    // The generalised job list: each array task runs its own argv, quoting intact.
    const fs::path dir = freshFolder("array");
    fs::create_directories(dir);
    const std::vector<std::vector<std::string>> commands = {
        {"sh", "-c", "echo one > '" + (dir / "a b").string() + "'"},
        {"sh", "-c", "echo \"it's\" > '" + (dir / "c").string() + "'"}};
    const std::string script =
        slurmArrayScript("t", "a test\nof two lines", dir.string(), commands, 1);
    std::ofstream(dir / "s.slurm") << script;
    EXPECT_EQ(run("bash -n " + (dir / "s.slurm").string()), 0);
    EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=1 bash " + (dir / "s.slurm").string()), 0);
    EXPECT_EQ(text(dir / "c"), "it's\n");
    EXPECT_FALSE(fs::exists(dir / "a b"));
    EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=0 bash " + (dir / "s.slurm").string()), 0);
    EXPECT_EQ(text(dir / "a b"), "one\n");
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
