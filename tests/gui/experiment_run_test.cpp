// The window's experiment run reports progress that never goes back, from the first steps of
// compaction to the end, and moves at every sample of the compaction (where the window showed
// 0 % and no ETA: the old estimate moved only with the count of passing equilibrium checks,
// which starts over whenever a check fails).
#include <gtest/gtest.h>

#include "gui/experiment_run.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

TEST(ExperimentRun, ProgressNeverDecreasesAndMovesDuringCompaction) {
    ExperimentConfig config = window_tests::smallExperiment();
    config.compaction.pressures = {15e3, 25e3};
    config.shear.pressures = {25e3, 15e3};
    const std::unique_ptr<SteppedRun> run = makeExperimentRun(config);
    double previous = run->progress().fraction;
    EXPECT_EQ(previous, 0.0);
    std::int64_t samples = 0, compactionSamples = 0, movingInCompaction = 0;
    std::string stage;
    bool more = true;
    while (more) {
        more = run->advance(100);
        const RunProgress p = run->progress();
        ++samples;
        ASSERT_GE(p.fraction, previous) << "at step " << p.step << " (" << p.stage << ")";
        ASSERT_LE(p.fraction, 1.0);
        if (p.stage.rfind("compaction", 0) == 0) {
            ++compactionSamples;
            movingInCompaction += p.fraction > previous;
        }
        stage = p.stage;
        previous = p.fraction;
    }
    EXPECT_EQ(previous, 1.0);
    EXPECT_GT(samples, 100);
    // Every sample of the compaction is further on than the one before.
    EXPECT_GT(compactionSamples, 50);
    EXPECT_EQ(movingInCompaction, compactionSamples);
}

} // namespace
} // namespace grainlab::ui
