// The run's warnings (run_warning.h): a shear test loaded above the measured quasi-static
// inertial number and a time step close to the stable limit are warned about once, at the step
// they concern, and the run file holds the same list as the runner. A stage that cannot calm
// says why.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiment_fixtures.h"
#include "grainlab/assembly.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/loading_rate.h"
#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "grainlab/study_plan.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

std::vector<RunWarning> runToTheEnd(const ExperimentConfig& config, const std::string& path) {
    RunFile file(path, config.sourceText);
    ExperimentRunner runner(config, &file);
    while (runner.advance(1000)) {
    }
    return runner.warnings();
}

fs::path scratchFolder(const char* name) {
    const fs::path dir = fs::temp_directory_path() / fmt::format("grainlab_{}_{}", name, getpid());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(RunWarnings, AShearAboveTheQuasiStaticLimitIsWarnedAboutOnceInTheRunFileToo) {
    nlohmann::json j = test::smallQuickExperiment();
    const ExperimentConfig probe = parseExperimentText(j.dump(), "probe.json");
    // I falls as 1/sqrt(p): 1.2 times the limit at 25 kPa is 0.85 times it at 50 kPa.
    const double perStep = 1.2 * kQuasiStaticInertialNumber / shearInertialNumber(probe, 25e3) *
                           probe.shear.axialStrainPerStep;
    j["shear"]["axial_strain_per_step"] = perStep;
    const ExperimentConfig config = parseExperimentText(j.dump(), "fast.json");
    ASSERT_GT(shearInertialNumber(config, 25e3), kQuasiStaticInertialNumber);
    ASSERT_LT(shearInertialNumber(config, 50e3), kQuasiStaticInertialNumber);

    const fs::path dir = scratchFolder("warn_inertial");
    const std::vector<RunWarning> given = runToTheEnd(config, (dir / "run.h5").string());
    ASSERT_EQ(given.size(), 1u);
    EXPECT_EQ(given[0].kind, "inertial_number");
    EXPECT_EQ(given[0].test, "p025kPa");
    EXPECT_EQ(given[0].axialStrain, 0.0); // at the start of its shear
    EXPECT_NE(given[0].text.find("25 kPa"), std::string::npos) << given[0].text;
    EXPECT_NE(given[0].text.find("shear.axial_strain_per_step"), std::string::npos);
    // The step it was given at is the first record of the shear of p025kPa.
    const SeriesTable series = readSeries((dir / "run.h5").string(), "p025kPa");
    bool found = false;
    for (std::size_t r = 0; r < series.rows.size(); ++r) {
        if (series.stageKinds[r] == "shear") {
            EXPECT_EQ(double(given[0].step), series.rows[r][series.column("step")]);
            found = true;
            break;
        }
    }
    EXPECT_TRUE(found);
    EXPECT_EQ(readWarnings((dir / "run.h5").string()), given);

    // Below the limit at both pressures nothing is warned about, and the file's list is empty.
    j["shear"]["axial_strain_per_step"] = 0.5 * perStep / 1.2;
    const ExperimentConfig slow = parseExperimentText(j.dump(), "slow.json");
    ASSERT_LT(shearInertialNumber(slow, 25e3), kQuasiStaticInertialNumber);
    EXPECT_TRUE(runToTheEnd(slow, (dir / "slow.h5").string()).empty());
    EXPECT_TRUE(readWarnings((dir / "slow.h5").string()).empty());
    fs::remove_all(dir);
}

// One inertial number: the series column, the warning and the study's knob, on a test at the
// start of its shear (mean stress = confining pressure, axial rate = strain per step / step).
TEST(RunWarnings, ColumnWarningAndKnobShareOneInertialNumber) {
    const std::string base = test::smallQuickExperiment().dump();
    const double pressure = 25e3; // the lowest shear pressure of test::smallQuickExperiment()
    for (const double level :
         {0.5 * kQuasiStaticInertialNumber, 2.0 * kQuasiStaticInertialNumber}) {
        KnobLevel knob;
        knob.number = level;
        const ExperimentConfig c = parseExperimentText(
            applySetting(base, "quick.json", {{KnobKind::InertialNumber, knob}}, 1), "made.json");
        // The knob sets the rate that the warning reads back.
        const double warned = shearInertialNumber(c, pressure);
        EXPECT_NEAR(warned, level, 1e-12 * level);
        EXPECT_EQ(inertialNumberWarning(c, pressure).has_value(),
                  level > kQuasiStaticInertialNumber);
        // The column, on the record of that state: a lateral rate does not enter I.
        RecordInputs in;
        in.stress = {pressure, pressure, 0.0};
        in.strainRate1 = c.shear.axialStrainPerStep / c.parameters.timeStep;
        in.strainRate2 = -0.4 * in.strainRate1;
        in.meanDiameter = meanGrainDiameter(c);
        in.density = c.parameters.density;
        const std::vector<double> row = seriesRow(MeasureSet{}, in);
        std::size_t k = 0;
        for (const SeriesColumn& column : seriesColumns()) {
            if (column.name == "inertial_number") {
                break;
            }
            k += column.text ? 0 : 1;
        }
        EXPECT_NEAR(row.at(k), warned, 1e-12 * warned);
        // Under a higher mean stress (the axial stress up during shear) the column is lower.
        in.stress = {3.0 * pressure, pressure, 0.0};
        EXPECT_LT(seriesRow(MeasureSet{}, in).at(k), warned);
    }
}

// The default preset is quasi-static at every pressure it shears: it does not warn about itself.
TEST(RunWarnings, TheQuickPresetIsQuasiStatic) {
    const ExperimentConfig c =
        readExperimentFile(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json");
    ASSERT_FALSE(c.shear.pressures.empty());
    for (const double p : c.shear.pressures) {
        EXPECT_LE(shearInertialNumber(c, p), kQuasiStaticInertialNumber) << p;
        EXPECT_FALSE(inertialNumberWarning(c, p)) << p;
    }
}

TEST(RunWarnings, ATimeStepNearTheLimitIsWarnedAboutAtTheStart) {
    nlohmann::json j = test::smallQuickExperiment();
    const ExperimentConfig probe = parseExperimentText(j.dump(), "probe.json");
    const double limit = criticalTimeStep(assemblyShapes(probe.assembly), probe.parameters).limit;
    // Within 20 % of the limit, keeping the loading rate per second.
    j["time_step"] = 0.9 * limit;
    j["shear"]["axial_strain_per_step"] =
        probe.shear.axialStrainPerStep / probe.parameters.timeStep * 0.9 * limit;
    const ExperimentConfig config = parseExperimentText(j.dump(), "near.json");
    const fs::path dir = scratchFolder("warn_step");
    RunFile file((dir / "run.h5").string(), config.sourceText);
    ExperimentRunner runner(config, &file);
    // Given before the first step, so that it is in the first checkpoint and on the screen.
    ASSERT_EQ(runner.warnings().size(), 1u);
    const RunWarning& w = runner.warnings()[0];
    EXPECT_EQ(w.kind, "time_step");
    EXPECT_EQ(w.test, "compaction");
    EXPECT_EQ(w.step, 0);
    EXPECT_EQ(w.text, checkTimeStep(assemblyShapes(config.assembly), config.parameters));
    EXPECT_NE(w.text.find("within 20 %"), std::string::npos) << w.text;
    EXPECT_EQ(runner.snapshot()->warnings, runner.warnings());
    file.flush();
    EXPECT_EQ(readWarnings((dir / "run.h5").string()), runner.warnings());
    fs::remove_all(dir);
}

std::string stageFailure(const ExperimentConfig& config) {
    ExperimentRunner runner(config);
    try {
        while (runner.advance(1000)) {
        }
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return {};
}

TEST(RunWarnings, AStageWithNothingToDissipateSaysSo) {
    nlohmann::json j = test::smallQuickExperiment();
    j["damping"] = {{"kind", "none"}};
    j["compaction"]["criterion"]["max_steps"] = 20000;
    const std::string error = stageFailure(parseExperimentText(j.dump(), "undamped.json"));
    EXPECT_NE(error.find("did not reach equilibrium within 20000 steps"), std::string::npos)
        << error;
    EXPECT_NE(error.find("nothing dissipates energy"), std::string::npos) << error;
    EXPECT_EQ(error.find("raise the stage's criterion.max_steps"), std::string::npos) << error;
}

TEST(RunWarnings, AStageThatJittersPastTheStableStepNamesTheTimeStep) {
    // The guard loosened (one contact assumed on the stiffest grain instead of six), a step
    // twice the usual estimate: above every limit the maps measured for these ovals, so the
    // compacted packing jitters and its I_uf keeps a floor instead of calming.
    nlohmann::json j = test::smallQuickExperimentAt25kPa();
    const ExperimentConfig usual = parseExperimentText(j.dump(), "usual.json");
    const double estimate =
        criticalTimeStep(assemblyShapes(usual.assembly), usual.parameters).estimate;
    j["stability"]["design_coordination"] = 1;
    j["time_step"] = 2.0 * estimate;
    j["shear"]["axial_strain_per_step"] = 2.0 * estimate * 1.0; // 1 /s
    j["compaction"]["criterion"]["max_steps"] = 30000;
    const std::string error = stageFailure(parseExperimentText(j.dump(), "jitter.json"));
    EXPECT_NE(error.find("does not fall"), std::string::npos) << error;
    EXPECT_NE(error.find(fmt::format("time_step = {:.4g} s", 2.0 * estimate)), std::string::npos)
        << error;
    EXPECT_NE(error.find("stability.design_coordination = 1"), std::string::npos) << error;
    EXPECT_NE(error.find("lower time_step"), std::string::npos) << error;
    EXPECT_EQ(error.find("raise the stage's criterion.max_steps"), std::string::npos) << error;
}

TEST(RunWarnings, AStageCutShortWhileCalmingAdvisesMoreSteps) {
    // The loose grid's compaction at 25 kPa jams after some 35 000 steps and calms by about
    // 65 000: cut at 20 000 it is still gathering, cut at 45 000 its I_uf is still falling.
    nlohmann::json j = test::smallQuickExperimentAt25kPa();
    j["compaction"]["criterion"]["max_steps"] = 20000;
    std::string error = stageFailure(parseExperimentText(j.dump(), "gathering.json"));
    EXPECT_NE(error.find("the stress is still far from its target"), std::string::npos) << error;
    EXPECT_EQ(error.find("time_step"), std::string::npos) << error;
    j["compaction"]["criterion"]["max_steps"] = 45000;
    error = stageFailure(parseExperimentText(j.dump(), "calming.json"));
    EXPECT_NE(error.find("was still falling: raise the stage's criterion.max_steps"),
              std::string::npos)
        << error;
    EXPECT_EQ(error.find("time_step"), std::string::npos) << error;
}

} // namespace
} // namespace grainlab
