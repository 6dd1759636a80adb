// The progress estimate (progress_estimate.h) over the plan of the quick experiment: 0 at the
// start, 1 when done, never decreasing over the whole sequence of stages, and the same numbers
// as the closed form the runner has always reported (written out here as the oracle).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/experiment_file.h"
#include "progress_estimate.h"
#include "stage.h"

namespace grainlab {
namespace {

ExperimentConfig quick() {
    return readExperimentFile(std::string(GRAINLAB_SOURCE_DIR) +
                              "/resources/experiments/quick.json");
}

std::vector<StageShare> sharesOf(const ExperimentConfig& config) {
    std::vector<StageShare> out;
    for (const PlannedStage& p : experimentPlan(config)) {
        out.push_back(makeStage(p)->share(config));
    }
    return out;
}

/// The estimate as a closed form over the protocol's phases: compaction k weighs
/// (k == 0 ? 0.1 : 0.01) / dt steps and settles; a re-equilibration 2 calm windows and settles;
/// a shear its stride to the target strain, linearly.
double closedForm(const ExperimentConfig& config, StageKind kind, int index, double inStage) {
    const double dt = config.parameters.timeStep;
    const auto capped = [](double expected, std::int64_t maxSteps) {
        return std::round(std::clamp(expected, 1.0, std::max(1.0, double(maxSteps))));
    };
    const auto compactionWeight = [&](int k) {
        return capped((k == 0 ? 0.1 : 0.01) / dt, config.compaction.criterion.maxSteps);
    };
    const EquilibriumCriterion& eq = config.shear.equilibration;
    const double equilibrationWeight =
        capped(2.0 * double(eq.calmChecks) * double(eq.checkInterval), eq.maxSteps);
    const double shearWeight = double(std::max<std::int64_t>(
        1, std::llround(config.shear.targetAxialStrain / config.shear.axialStrainPerStep)));
    const int nc = int(config.compaction.pressures.size());
    const int ns = int(config.shear.pressures.size());
    double compactionTotal = 0;
    for (int k = 0; k < nc; ++k) {
        compactionTotal += compactionWeight(k);
    }
    const double testWeight = equilibrationWeight + shearWeight;
    const double total = compactionTotal + ns * testWeight;
    const auto settling = [](double steps, double weight) {
        return weight * -std::expm1(-steps / weight);
    };
    double done = 0;
    switch (kind) {
    case StageKind::Compaction:
        for (int k = 0; k < index; ++k) {
            done += compactionWeight(k);
        }
        done += settling(inStage, compactionWeight(index));
        break;
    case StageKind::Equilibration:
        done = compactionTotal + index * testWeight + settling(inStage, equilibrationWeight);
        break;
    case StageKind::Shear:
        done = compactionTotal + index * testWeight + equilibrationWeight +
               std::min(inStage, shearWeight);
        break;
    case StageKind::Done:
        done = total;
        break;
    }
    return std::clamp(done / total, 0.0, 1.0);
}

TEST(ProgressEstimate, QuickPresetGivesTheClosedFormsNumbersBitForBit) {
    const ExperimentConfig config = quick();
    const std::vector<PlannedStage> plan = experimentPlan(config);
    const std::vector<StageShare> shares = sharesOf(config);
    ASSERT_EQ(plan.size(), 4u + 2u * config.shear.pressures.size());
    for (std::size_t k = 0; k < plan.size(); ++k) {
        for (const std::int64_t steps : {0, 1, 99, 1000, 12345, 100000, 250000, 10000000}) {
            EXPECT_EQ(progressFraction(shares, k, steps),
                      closedForm(config, plan[k].kind, plan[k].index, double(steps)))
                << "stage " << k << " at " << steps << " steps";
        }
    }
    EXPECT_EQ(progressFraction(shares, plan.size(), 0), closedForm(config, StageKind::Done, 0, 0));
}

TEST(ProgressEstimate, StartsAtZeroEndsAtOneAndNeverDecreasesOverAWholeRun) {
    const ExperimentConfig config = quick();
    const std::vector<StageShare> shares = sharesOf(config);
    EXPECT_EQ(progressFraction(shares, 0, 0), 0.0);
    EXPECT_EQ(progressFraction(shares, shares.size(), 0), 1.0);
    // Every stage may end at any step count (a settling stage that overran, one that calmed
    // at once): within a stage the estimate rises with its steps, and the next stage starts at
    // or above every value its predecessor reported.
    double highest = 0;
    for (std::size_t k = 0; k < shares.size(); ++k) {
        const double start = progressFraction(shares, k, 0);
        ASSERT_GE(start, highest) << "stage " << k;
        double last = start;
        for (std::int64_t steps = 1; steps <= 3000000; steps += 997) {
            const double f = progressFraction(shares, k, steps);
            ASSERT_GE(f, last) << "stage " << k << " at " << steps << " steps";
            last = f;
        }
        highest = last;
    }
    EXPECT_GE(progressFraction(shares, shares.size(), 0), highest);
}

TEST(ProgressEstimate, AnEmptyPlanIsDone) {
    EXPECT_EQ(progressFraction({}, 0, 0), 1.0);
}

} // namespace
} // namespace grainlab
