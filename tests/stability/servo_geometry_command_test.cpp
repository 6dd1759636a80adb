// `grainlab stability` end to end on the servo and geometry presets' tiny maps, through the real
// executable: the servo map's cells run through the pool and resume, its tables name the
// largest stable gain of each cell with the gain far past the limit found unstable; the
// geometry map runs in one process and writes its tables; both draw their figures.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "test_folders.h"

#include "grainlab/geometry_map.h"
#include "grainlab/servo_map.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using namespace test;

std::size_t rows(const std::string& csv) {
    return std::size_t(std::count(csv.begin(), csv.end(), '\n')) - 1;
}

TEST(ServoMapCommand, TinyMapEndToEndAndResumes) {
    const fs::path dir = presetRunFolder("servo-tiny");
    const ServoMapSpec spec = readServoPreset(stabilityPresetFile("servo-tiny"));
    const auto cells = servoCells(spec);
    ASSERT_EQ(cells.size(), 2u);
    fs::file_time_type first;
    for (const ServoCell& c : cells) {
        const fs::path file = cellFile(dir, c.id);
        ASSERT_TRUE(fs::exists(file)) << file;
        const ServoCellResult r = parseServoCellResult(text(file), file.string());
        ASSERT_GE(r.runs.size(), spec.gains.size()) << c.id;
        // The grid: g = 0.3 is stable, g = 4 (twice the loop's limit of about 2) is not, so the
        // limit was bisected between them.
        EXPECT_EQ(r.runs[0].gain, 0.3);
        EXPECT_FALSE(servoUnstable(r.runs[0].response)) << c.id;
        EXPECT_EQ(r.runs[1].gain, 4.0);
        EXPECT_TRUE(servoUnstable(r.runs[1].response)) << c.id;
        EXPECT_TRUE(r.limit.bracketed) << c.id;
        EXPECT_GE(r.limit.low, 0.3) << c.id;
        EXPECT_LT(r.limit.high, 4.0) << c.id;
        EXPECT_LE(r.limit.high / r.limit.low - 1, spec.precision) << c.id;
        EXPECT_GT(r.runs.size(), spec.gains.size()) << c.id << ": no bisection run";
        EXPECT_GT(r.stiffnessOverPressure, 100) << c.id;
        if (c.interval == 1) {
            first = fs::last_write_time(file);
        }
    }
    const std::string limits = text(dir / "servo_limits.csv");
    EXPECT_EQ(rows(limits), 2u);
    EXPECT_NE(limits.find("stable_gain_limit [-]"), std::string::npos);
    EXPECT_NE(limits.find("lag_number [-]"), std::string::npos);
    EXPECT_EQ(limits.find("nan"), std::string::npos);
    const std::string runs = text(dir / "servo_runs.csv");
    EXPECT_NE(runs.find("max_error [-]"), std::string::npos);
    EXPECT_NE(runs.find(",bisection,"), std::string::npos);
    EXPECT_EQ(missingFigures(dir, {"response_eta1_p15kPa.svg", "stable_gain.png"}),
              std::vector<std::string>{});
    // Resumes: only a removed cell runs again.
    fs::remove(cellFile(dir, cells[1].id));
    ASSERT_EQ(runStabilityPreset("servo-tiny", dir), 0);
    EXPECT_TRUE(fs::exists(cellFile(dir, cells[1].id)));
    EXPECT_EQ(fs::last_write_time(cellFile(dir, cells[0].id)), first);
    EXPECT_EQ(runStability("collect " + dir.string() + " --quiet"), 0);
    // The emitted job list names the servo cells.
    ASSERT_EQ(runStabilityPreset("servo-tiny", dir, "--emit parallel"), 0);
    EXPECT_NE(text(dir / "jobs.txt").find(cells[1].id), std::string::npos);
    fs::remove_all(dir);
}

TEST(GeometryMapCommand, TinyMapEndToEnd) {
    const fs::path dir = presetRunFolder("geometry-tiny");
    const std::string levels = text(dir / "geometry.csv");
    EXPECT_EQ(rows(levels), 3u * 3u); // three overlaps, three kernels
    EXPECT_NE(levels.find("overlap_fraction [-]"), std::string::npos);
    const std::string limits = text(dir / "geometry_limits.csv");
    EXPECT_NE(limits.find("0.6,engine,no,"), std::string::npos) << limits;
    EXPECT_EQ(limits.find("nan"), std::string::npos);
    EXPECT_EQ(missingFigures(dir, {"departure.svg"}), std::vector<std::string>{});
    // One process: nothing to emit, no cells to collect.
    EXPECT_NE(runStabilityPreset("geometry-tiny", dir, "--emit slurm"), 0);
    EXPECT_NE(runStability("collect " + dir.string()), 0);
    // A preset of an unknown kind is refused.
    const fs::path bad = dir / "bad.json";
    std::ofstream(bad) << R"({"kind": "servos", "axes": {}})";
    EXPECT_NE(runStability(bad.string() + " --out " + (dir / "x").string()), 0);
    EXPECT_FALSE(fs::exists(dir / "x"));
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
