// Cyclic measures on synthetic waveforms and response envelopes of synthetic probe responses.
#include "grainlab/path_measures.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "grainlab/loading_path.h"

namespace grainlab {
namespace {

TEST(CyclicMeasures, ReversalsOfATriangularWaveform) {
    // eps1 from the schedule: peaks at records 10, 30, 50, 70 for 80 records.
    const CyclicStrainSchedule schedule(0.0, 0.0, 0.01, 0.001);
    std::vector<double> eps;
    for (int n = 0; n <= 80; ++n) {
        eps.push_back(schedule.strainAt(n));
    }
    const auto r = reversalIndices(eps);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r, (std::vector<std::size_t>{10, 30, 50, 70}));
    const auto spans = cycleSpans(r);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_EQ(spans[0].begin, 10u);
    EXPECT_EQ(spans[0].end, 50u);
}

TEST(CyclicMeasures, FlatStretchesCountOneReversalAtTheirStart) {
    const auto r = reversalIndices({0, 1, 2, 2, 2, 1, 0, 0, 1});
    EXPECT_EQ(r, (std::vector<std::size_t>{2, 6}));
    EXPECT_TRUE(reversalIndices({0, 0, 0}).empty());
    EXPECT_TRUE(reversalIndices({}).empty());
}

TEST(CyclicMeasures, CyclesToThePressureCriterion) {
    // p' decays by 5 % of p0 per cycle of 40 records: falls below 0.5 p0 after 10 cycles.
    const CyclicStrainSchedule schedule(0.0, 0.0, 0.01, 0.001);
    std::vector<double> eps, p;
    const double p0 = 1e5;
    for (int n = 0; n <= 600; ++n) {
        eps.push_back(schedule.strainAt(n));
        p.push_back(p0 * (1.0 - 0.05 * (n - 10) / 40.0 * (n > 10)));
    }
    const auto r = reversalIndices(eps);
    const auto hit = cyclesToPressureFraction(p, r, p0, 0.4987);
    ASSERT_TRUE(hit.has_value());
    // p < 0.4987 p0 first when 0.05 (n - 10) / 40 > 0.5013, n - 10 > 401.04: n = 412 (a
    // fraction off the record grid, so no comparison falls on a tie); reversals before it: 10,
    // 30, ..., 410 (21).
    EXPECT_EQ(hit->index, 412u);
    EXPECT_DOUBLE_EQ(hit->cycles, 10.5);
    EXPECT_FALSE(cyclesToPressureFraction(p, r, p0, 0.01).has_value());
}

TEST(ResponseEnvelope, ALinearMapGivesACentredEllipse) {
    // r = M u for M = [[3, 1], [0.5, 2]]: singular values from M M^T = [[10, 3.5], [3.5, 4.25]].
    const double m11 = 3, m12 = 1, m21 = 0.5, m22 = 2;
    std::vector<std::array<double, 2>> responses;
    for (const auto& u : probeDirections(24)) {
        responses.push_back({m11 * u[0] + m12 * u[1], m21 * u[0] + m22 * u[1]});
    }
    const ResponseEnvelope env = responseEnvelope(responses);
    EXPECT_LT(env.asymmetry, 1e-14);
    EXPECT_LT(env.ellipseResidual, 1e-14);
    EXPECT_NEAR(env.linearMap[0], m11, 1e-13);
    EXPECT_NEAR(env.linearMap[1], m21, 1e-13);
    EXPECT_NEAR(env.linearMap[2], m12, 1e-13);
    EXPECT_NEAR(env.linearMap[3], m22, 1e-13);
    const double mid = 0.5 * (10 + 4.25), rad = std::hypot(0.5 * (10 - 4.25), 3.5);
    EXPECT_NEAR(env.majorSemiAxis, std::sqrt(mid + rad), 1e-13);
    EXPECT_NEAR(env.minorSemiAxis, std::sqrt(mid - rad), 1e-13);
    // Product of the semi-axes = |det M| (area of the ellipse / pi).
    EXPECT_NEAR(env.majorSemiAxis * env.minorSemiAxis, std::fabs(m11 * m22 - m12 * m21), 1e-12);
    // The major axis direction: M M^T v = s^2 v.
    const double c = std::cos(env.majorAngle), s = std::sin(env.majorAngle);
    EXPECT_NEAR(10 * c + 3.5 * s, (mid + rad) * c, 1e-12);
}

TEST(ResponseEnvelope, LoadingUnloadingStiffnessBreaksLinearity) {
    // Stiffer in unloading (u1 < 0) than in loading: opposite inputs no longer give opposite
    // responses, and no single linear map fits.
    std::vector<std::array<double, 2>> responses;
    for (const auto& u : probeDirections(16)) {
        const double k = u[0] > 0 ? 1.0 : 4.0;
        responses.push_back({k * u[0], u[1]});
    }
    const ResponseEnvelope env = responseEnvelope(responses);
    EXPECT_GT(env.asymmetry, 0.5);
    EXPECT_GT(env.ellipseResidual, 0.1);
}

TEST(ResponseEnvelope, RefusesOddOrTooFewProbes) {
    EXPECT_THROW(responseEnvelope(std::vector<std::array<double, 2>>(5)), std::invalid_argument);
    EXPECT_THROW(responseEnvelope(std::vector<std::array<double, 2>>(2)), std::invalid_argument);
}

} // namespace
} // namespace grainlab
