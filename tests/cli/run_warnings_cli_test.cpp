// What `grainlab run` tells the user beyond its progress (issue 16): each warning printed once,
// also with --quiet; a killed and resumed run holds the same warnings as an uninterrupted one;
// a failing run names its cause and the last good checkpoint it keeps.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_files.h"
#include "grainlab/experiment_file.h"
#include "grainlab/loading_rate.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using test::CommandOutput;
using test::grainlabOutput;

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

/// The quick protocol cut to 120 grains, one pressure and a short shear, sheared at twice the
/// quasi-static inertial number.
nlohmann::json fastShear() {
    nlohmann::json j = nlohmann::json::parse(
        test::readText(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json"));
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = 0.004;
    j["shear"]["max_strain_rate"] = 20.0;
    j["record"]["snapshot_strain_interval"] = 1e-3;
    j["record"]["snapshot_step_interval"] = 5000;
    const ExperimentConfig c = parseExperimentText(j.dump(), "fast.json");
    j["shear"]["axial_strain_per_step"] = 2.0 * kQuasiStaticInertialNumber /
                                          shearInertialNumber(c, 50e3) * c.shear.axialStrainPerStep;
    return j;
}

TEST(RunWarningsCommand, PrintedOnceAndKeptThroughAKillAndResume) {
    const fs::path base = test::freshFolder("cli", "warnings");
    const fs::path experiment = base / "fast.json";
    std::ofstream(experiment) << fastShear().dump(2);

    const CommandOutput whole = grainlabOutput(
        fmt::format("run {} --out {} --quiet", experiment.string(), (base / "whole").string()));
    ASSERT_EQ(whole.status, 0) << whole.output;
    const std::string said = "grainlab run: warning (p050kPa, step ";
    EXPECT_EQ(count(whole.output, said), 1u) << whole.output;
    EXPECT_NE(whole.output.find("inertial number"), std::string::npos) << whole.output;
    const std::vector<RunWarning> expected = readWarnings((base / "whole" / "run.h5").string());
    ASSERT_EQ(expected.size(), 1u);

    // Killed in the shear, after the warning (the simulation's step counts the process's steps
    // here: one test, from the generated assembly on; the shear takes some 1500 steps), resumed.
    const fs::path parts = base / "parts";
    const CommandOutput killed =
        grainlabOutput(fmt::format("run {} --out {} --quiet", experiment.string(), parts.string()),
                       "GRAINLAB_TEST_STOP_AFTER_STEPS=" + std::to_string(expected[0].step + 700));
    EXPECT_NE(killed.status, 0);
    EXPECT_EQ(count(killed.output, said), 1u) << killed.output;
    const CommandOutput resumed = test::resumeOutput(parts);
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    // A resumed run repeats its earlier warnings on the terminal, and the file holds each once.
    EXPECT_EQ(count(resumed.output, said), 1u) << resumed.output;
    EXPECT_EQ(readWarnings((parts / "run.h5").string()), expected);
    fs::remove_all(base);
}

/// Writes the experiment `j` to `experiment`, then runs `grainlab run` on it into `out`.
CommandOutput runWritten(const nlohmann::json& j, const fs::path& experiment, const fs::path& out) {
    std::ofstream(experiment) << j.dump(2);
    return grainlabOutput(fmt::format("run {} --out {}", experiment.string(), out.string()));
}

TEST(RunWarningsCommand, AFailingRunNamesItsLastGoodCheckpoint) {
    const fs::path base = test::freshFolder("cli", "lastgood");
    nlohmann::json j = fastShear();
    // An overlap limit no compaction can respect: the run stops with the blow-up error.
    j["stability"]["max_overlap_fraction"] = 1e-4;
    j["record"]["snapshot_step_interval"] = 200;
    const fs::path experiment = base / "fail.json";
    const CommandOutput out = runWritten(j, experiment, base / "out");
    EXPECT_EQ(out.status, 1) << out.output;
    EXPECT_NE(out.output.find("overlap"), std::string::npos) << out.output;
    const std::vector<std::string> checkpoints =
        listCheckpoints((base / "out" / "run.h5").string());
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_NE(out.output.find("keeps its last good checkpoint " + checkpoints.back() + " and"),
              std::string::npos)
        << out.output;
    // A stop of the experiment itself: the message says which key to change and to start a
    // new run, never to resume (which would meet the same stop).
    EXPECT_EQ(out.output.find("--resume"), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("stability.max_overlap_fraction"), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("--out NEW_FOLDER"), std::string::npos) << out.output;
    fs::remove_all(base);
}

TEST(RunWarningsCommand, AStageStepLimitNamesItsKeyAndSuggestsANewRun) {
    const fs::path base = test::freshFolder("cli", "maxsteps");
    nlohmann::json j = fastShear();
    j["compaction"]["criterion"]["max_steps"] = 300; // no compaction is calm this soon
    const fs::path experiment = base / "limit.json";
    const CommandOutput out = runWritten(j, experiment, base / "out");
    EXPECT_EQ(out.status, 1) << out.output;
    EXPECT_NE(out.output.find("did not reach equilibrium"), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("compaction.criterion.max_steps"), std::string::npos) << out.output;
    EXPECT_NE(out.output.find("grainlab run " + experiment.string() + " --out NEW_FOLDER"),
              std::string::npos)
        << out.output;
    EXPECT_EQ(out.output.find("--resume"), std::string::npos) << out.output;
    fs::remove_all(base);
}

} // namespace
} // namespace grainlab
