// A study's expansion into settings and runs: one-at-a-time and grid designs, the derived levels
// (time step from the critical-step estimate, loading rate from the inertial number), seeds, and
// every run's experiment valid.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "grainlab/oval_shape.h"
#include "grainlab/study_plan.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

std::string quickText() {
    std::ifstream in(GRAINLAB_SOURCE_DIR "/resources/experiments/quick.json");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

KnobLevel number(double v) {
    return KnobLevel{v, ""};
}
KnobLevel object(const char* json) {
    return KnobLevel{0, json};
}

StudySpec smallStudy() {
    StudySpec spec;
    spec.baseExperiment = quickText();
    spec.baseSource = "quick.json";
    spec.knobs = {{KnobKind::TimeStepFraction, {number(0.5), number(0.25)}},
                  {KnobKind::Damping, {object(R"({"kind":"none"})")}}};
    spec.seeds = {1, 2};
    return spec;
}

TEST(StudyPlan, OneAtATimeIsTheReferenceAndEachLevelOfEachKnob) {
    const StudyPlan plan = planStudy(smallStudy());
    ASSERT_EQ(plan.settings.size(), 4u);
    EXPECT_EQ(plan.settings[0].id, "ref");
    EXPECT_TRUE(plan.settings[0].isReference);
    EXPECT_EQ(plan.settings[1].id, "time_step_fraction-0.5");
    EXPECT_EQ(plan.settings[2].id, "time_step_fraction-0.25");
    EXPECT_EQ(plan.settings[3].id, "damping-none");
    ASSERT_EQ(plan.runs.size(), 8u);
    EXPECT_EQ(plan.runs[3].id, "time_step_fraction-0.5-seed2");
    EXPECT_EQ(plan.runs[3].setting, 1);
    EXPECT_EQ(plan.runs[3].seed, 2u);

    // The reference run is the base experiment at its seed, nothing else changed.
    const ExperimentConfig base = parseExperimentText(quickText(), "quick.json");
    const ExperimentConfig ref = parseExperimentText(plan.runs[0].experimentText, "ref");
    EXPECT_EQ(ref.assembly.seed, 1u);
    EXPECT_EQ(ref.parameters.timeStep, base.parameters.timeStep);
    EXPECT_EQ(ref.parameters.damping.kind, base.parameters.damping.kind);

    // Half the engine's critical-step estimate for the base's shapes.
    std::vector<OvalShape> shapes;
    for (double w : base.assembly.widths) {
        shapes.push_back(makeOval(w, base.assembly.aspectRatio));
    }
    const double limit = criticalTimeStep(shapes, base.parameters).estimate;
    const ExperimentConfig half = parseExperimentText(plan.runs[2].experimentText, "half");
    EXPECT_DOUBLE_EQ(half.parameters.timeStep, 0.5 * limit);
    // The loading rate per second is the base's: the strain per step scales with the step.
    EXPECT_DOUBLE_EQ(half.shear.axialStrainPerStep / half.parameters.timeStep,
                     base.shear.axialStrainPerStep / base.parameters.timeStep);
    EXPECT_EQ(half.parameters.damping.kind, base.parameters.damping.kind);
    // A smaller step than the base's gets the same physical time to reach equilibrium: the
    // stages' step caps grow by the base's step over the setting's (never shrink).
    const double stretch = base.parameters.timeStep / half.parameters.timeStep;
    ASSERT_GT(stretch, 1.0); // half the limit is below the quick experiment's 1e-6 s
    EXPECT_EQ(half.compaction.criterion.maxSteps,
              std::int64_t(std::ceil(double(base.compaction.criterion.maxSteps) * stretch)));
    EXPECT_EQ(half.shear.equilibration.maxSteps,
              std::int64_t(std::ceil(double(base.shear.equilibration.maxSteps) * stretch)));
    const ExperimentConfig undamped = parseExperimentText(plan.runs[7].experimentText, "none");
    EXPECT_EQ(undamped.parameters.damping.kind, DampingKind::None);
    EXPECT_EQ(undamped.parameters.timeStep, base.parameters.timeStep);
    EXPECT_EQ(undamped.assembly.seed, 2u);
}

TEST(StudyPlan, GridIsEveryCombinationAndALevelEqualToTheReferenceIsNotRepeated) {
    StudySpec spec = smallStudy();
    spec.design = StudyDesign::Grid;
    spec.reference[KnobKind::TimeStepFraction] = number(0.25);
    const StudyPlan plan = planStudy(spec);
    // Grid: {0.5, 0.25} x {none}; the reference (0.25, base damping) is not in it.
    ASSERT_EQ(plan.settings.size(), 3u);
    EXPECT_EQ(plan.settings[1].id, "time_step_fraction-0.5_damping-none");
    EXPECT_EQ(plan.settings[2].id, "damping-none"); // 0.25 is the reference's level

    spec.design = StudyDesign::OneAtATime;
    const StudyPlan one = planStudy(spec);
    ASSERT_EQ(one.settings.size(), 3u); // ref (0.25), 0.5, none: 0.25 not again
}

TEST(StudyPlan, InertialNumberLevelSetsTheStrainPerStep) {
    StudySpec spec = smallStudy();
    spec.knobs = {{KnobKind::InertialNumber, {number(1e-3)}}};
    spec.seeds = {1};
    const StudyPlan plan = planStudy(spec);
    ASSERT_EQ(plan.runs.size(), 2u);
    const ExperimentConfig c = parseExperimentText(plan.runs[1].experimentText, "I");
    // I = (eps1 per step / dt) d sqrt(rho / p) at the lowest pressure sheared.
    double d = 0;
    const int classes = int(c.assembly.widths.size());
    for (int i = 0; i < c.assembly.grainCount; ++i) {
        d += makeOval(c.assembly.widths[std::size_t(i % classes)], c.assembly.aspectRatio)
                 .equivalentDiameter();
    }
    d /= c.assembly.grainCount;
    const double p = c.shear.pressures.front();
    const double I = c.shear.axialStrainPerStep / c.parameters.timeStep * d *
                     std::sqrt(c.parameters.density / p);
    EXPECT_NEAR(I, 1e-3, 1e-15);
}

TEST(StudyPlan, ALevelThatMakesAnInvalidExperimentNamesTheSetting) {
    StudySpec spec = smallStudy();
    spec.knobs = {{KnobKind::TimeStepFraction, {number(1.5)}}}; // above the stable limit
    try {
        planStudy(spec);
        FAIL() << "an unstable time step was accepted";
    } catch (const ExperimentFileError& e) {
        EXPECT_NE(std::string(e.what()).find("time_step_fraction-1.5"), std::string::npos)
            << e.what();
        EXPECT_EQ(e.keyPath, "time_step");
    }
}

TEST(StudyPlan, LevelLabels) {
    EXPECT_EQ(number(0.5).label(), "0.5");
    EXPECT_EQ(object(R"({"kind":"cundall_local","coefficient":0.7})").label(), "cundall_local-0.7");
    EXPECT_EQ(object(R"({"aspect_ratio":1})").label(), "disk");
    EXPECT_EQ(object(R"({"aspect_ratio":0.6,"closure":"equal_area"})").label(),
              "oval-0.6-equal_area");
}

} // namespace
} // namespace grainlab

namespace grainlab {
namespace {

TEST(StudyPlan, AKnobsValueInAnExperimentIsTheLevelThatMadeIt) {
    const std::string base = quickText();
    EXPECT_EQ(*knobValueIn(base, KnobKind::GrainCount), 800.0);
    EXPECT_EQ(*knobValueIn(base, KnobKind::NeighbourSkin), 0.1); // the default skin
    EXPECT_FALSE(knobValueIn(base, KnobKind::Damping));
    for (const auto& [kind, value] :
         std::vector<std::pair<KnobKind, double>>{{KnobKind::TimeStepFraction, 0.5},
                                                  {KnobKind::InertialNumber, 0.0005},
                                                  {KnobKind::AxialStrainPerStep, 2e-6},
                                                  {KnobKind::NeighbourSkin, 0.3},
                                                  {KnobKind::Threads, 2}}) {
        KnobLevel level;
        level.number = value;
        const std::string made = applySetting(base, "quick.json", {{kind, level}}, 1);
        EXPECT_NEAR(*knobValueIn(made, kind), value, 1e-12 * value) << knobName(kind);
    }
}

} // namespace
} // namespace grainlab
