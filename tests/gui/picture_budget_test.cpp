// The window's picture budget (app/gui/picture_budget.h): a picture that cost c ms is followed
// by the next no sooner than c / share later, never sooner than the frame period; the last
// picture alone decides; the share follows the engine's threads and the processors.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "gui/picture_budget.h"

namespace grainlab::ui {
namespace {

TEST(PictureBudget, ASlowPictureIsFollowedByTheNextOnlyAfterItsCostOverTheShare) {
    const PictureBudget budget(0.1, 33.0);
    // 40 ms of drawing at a tenth of a core: 400 ms between pictures.
    EXPECT_DOUBLE_EQ(budget.intervalMs(40.0), 400.0);
    EXPECT_DOUBLE_EQ(budget.nextPictureAtMs(1000.0, 40.0), 1400.0);
    EXPECT_GE(budget.nextPictureAtMs(1000.0, 40.0), 1000.0 + 40.0 / 0.1);
    // The reference scene's whole cell with chains and void cells (~100 ms): one a second.
    EXPECT_DOUBLE_EQ(budget.intervalMs(100.0), 1000.0);
}

TEST(PictureBudget, ACheapPictureComesAtTheFramePeriod) {
    const PictureBudget budget(0.1, 33.0);
    EXPECT_DOUBLE_EQ(budget.intervalMs(1.0), 33.0);
    EXPECT_DOUBLE_EQ(budget.intervalMs(0.0), 33.0);
    EXPECT_DOUBLE_EQ(budget.nextPictureAtMs(500.0, 1.0), 533.0);
    // The boundary: 3.3 ms at a tenth of a core is exactly the frame period.
    EXPECT_NEAR(budget.intervalMs(3.3), 33.0, 1e-9);
    EXPECT_NEAR(budget.intervalMs(3.4), 34.0, 1e-9);
}

TEST(PictureBudget, AFastPictureAfterSlowOnesIsFollowedAtOnceByTheFramePeriod) {
    // The cost follows the view: zooming in makes the next picture cheap, and the pictures
    // speed up from the next one on, not after a memory of the slow ones fades.
    const PictureBudget budget(0.1, 33.0);
    double at = 0.0;
    for (int k = 0; k < 5; ++k) {
        const double next = budget.nextPictureAtMs(at, 90.0);
        EXPECT_DOUBLE_EQ(next - at, 900.0);
        at = next;
    }
    EXPECT_DOUBLE_EQ(budget.nextPictureAtMs(at, 2.0) - at, 33.0);
    // And a slow one after fast ones is spaced at once.
    EXPECT_DOUBLE_EQ(budget.nextPictureAtMs(at, 50.0) - at, 500.0);
}

TEST(PictureBudget, ABadCostCountsAsNothingAndAShareOutOfRangeIsClamped) {
    const PictureBudget budget(0.1, 33.0);
    EXPECT_DOUBLE_EQ(budget.intervalMs(-5.0), 33.0);
    EXPECT_DOUBLE_EQ(budget.intervalMs(std::numeric_limits<double>::quiet_NaN()), 33.0);
    EXPECT_DOUBLE_EQ(budget.intervalMs(std::numeric_limits<double>::infinity()), 33.0);
    EXPECT_DOUBLE_EQ(PictureBudget(2.0, 33.0).share(), 1.0);
    EXPECT_DOUBLE_EQ(PictureBudget(2.0, 33.0).intervalMs(50.0), 50.0); // a whole core at most
    EXPECT_GT(PictureBudget(0.0, 33.0).share(), 0.0);                  // no division by zero
    EXPECT_TRUE(std::isfinite(PictureBudget(0.0, 33.0).intervalMs(1.0)));
    EXPECT_DOUBLE_EQ(PictureBudget(0.5, -1.0).intervalMs(0.0), 0.0);
}

TEST(PictureBudget, TheShareFollowsTheEngineThreadsAndTheProcessors) {
    // The engine fills every core: its threads wait for one another at each barrier, so any
    // core's picture work holds all of them up; 3 % of its speed is 3 % of one core.
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(2, 2), 0.03);
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(4, 2), 0.03); // more threads than processors
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(1, 1), 0.03);
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(32, 32), 0.03);
    // A core left free (the quick experiment's 800 grains run one thread): half of it.
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(2, 8), 0.5);
    // Nonsense counts are read as one.
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(0, 0), 0.03);
    EXPECT_DOUBLE_EQ(PictureBudget::shareFor(0, 2), 0.5);
}

} // namespace
} // namespace grainlab::ui
