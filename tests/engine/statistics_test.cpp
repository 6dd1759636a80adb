// Statistics over runs against hand computations: scatter, interpolation, mean curves with their
// band, RMS differences.
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/statistics.h"

namespace grainlab {
namespace {

TEST(Statistics, ScatterIsTheMeanAndTheSampleStandardDeviation) {
    const Scatter s = scatterOf(std::vector<double>{1, 2, 3, 4});
    EXPECT_EQ(s.count, 4);
    EXPECT_DOUBLE_EQ(s.mean, 2.5);
    EXPECT_DOUBLE_EQ(s.sd, std::sqrt(5.0 / 3.0)); // sum of squares 5 over n - 1 = 3
    const Scatter one = scatterOf(std::vector<double>{7});
    EXPECT_DOUBLE_EQ(one.mean, 7);
    EXPECT_EQ(one.sd, 0);
    EXPECT_EQ(scatterOf(std::vector<double>{}).count, 0);
    const Scatter some = scatterOf(std::vector<std::optional<double>>{1.0, std::nullopt, 3.0});
    EXPECT_EQ(some.count, 2);
    EXPECT_DOUBLE_EQ(some.mean, 2);
    EXPECT_DOUBLE_EQ(some.sd, std::sqrt(2.0));
}

TEST(Statistics, WithinNoiseIsTwoReferenceStandardDeviations) {
    const Scatter ref{10, 0.5, 5};
    EXPECT_TRUE(withinNoise(1.0, ref));
    EXPECT_TRUE(withinNoise(-1.0, ref));
    EXPECT_FALSE(withinNoise(1.0001, ref));
    EXPECT_FALSE(withinNoise(0.6, ref, 1.0));
    EXPECT_TRUE(withinNoise(0.0, Scatter{1, 0, 1}));
    EXPECT_FALSE(withinNoise(1e-12, Scatter{1, 0, 1}));
}

TEST(Statistics, ValueAtInterpolatesLinearlyInsideTheCurveOnly) {
    const Curve c{{0, 1, 2, 2, 4}, {0, 10, 20, 30, 50}};
    EXPECT_DOUBLE_EQ(*valueAt(c, 0.5), 5);
    EXPECT_DOUBLE_EQ(*valueAt(c, 1), 10);
    EXPECT_DOUBLE_EQ(*valueAt(c, 2), 30); // equal x: the last point counts
    EXPECT_DOUBLE_EQ(*valueAt(c, 3), 40);
    EXPECT_DOUBLE_EQ(*valueAt(c, 4), 50);
    EXPECT_DOUBLE_EQ(*valueAt(c, 0), 0);
    EXPECT_FALSE(valueAt(c, -0.1));
    EXPECT_FALSE(valueAt(c, 4.1));
    EXPECT_FALSE(valueAt(Curve{}, 0));
}

TEST(Statistics, MeanCurveAndBandOfTwoLines) {
    const Curve a{{0, 1}, {0, 1}};     // y = x
    const Curve b{{0, 0.5}, {0, 1.5}}; // y = 3x, reaches x = 0.5 only
    const auto grid = evenlySpaced(0, 1, 5);
    ASSERT_EQ(grid.size(), 5u);
    EXPECT_DOUBLE_EQ(grid[1], 0.25);
    const CurveBand band = meanCurve({a, b}, grid);
    ASSERT_EQ(band.x.size(), 5u);
    EXPECT_DOUBLE_EQ(band.mean[1], 0.5);                 // (0.25 + 0.75) / 2
    EXPECT_DOUBLE_EQ(band.sd[1], std::sqrt(2.0) * 0.25); // |3x - x| / sqrt(2)
    EXPECT_EQ(band.count[1], 2);
    EXPECT_EQ(band.count[3], 1); // x = 0.75: only y = x reaches it
    EXPECT_DOUBLE_EQ(band.mean[3], 0.75);
    EXPECT_EQ(band.sd[3], 0);
}

TEST(Statistics, RmsDifferenceOfShiftedCurvesIsTheShift) {
    const Curve a{{0, 1}, {0, 1}};
    const Curve b{{0, 1}, {0.1, 1.1}};
    EXPECT_NEAR(*rmsDifference(a, b, evenlySpaced(0, 1, 11)), 0.1, 1e-15);
    EXPECT_EQ(*rmsDifference(a, a, evenlySpaced(0, 1, 11)), 0);
    // Only the points both reach count; none shared: nothing.
    const Curve c{{2, 3}, {0, 0}};
    EXPECT_FALSE(rmsDifference(a, c, evenlySpaced(0, 1, 11)));
    // y = x against y = 0 over x in {0, 1}: sqrt((0 + 1) / 2).
    EXPECT_DOUBLE_EQ(*rmsDifference(a, Curve{{0, 1}, {0, 0}}, {0, 1}), std::sqrt(0.5));
}

} // namespace
} // namespace grainlab
