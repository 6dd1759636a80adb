// Steady-state criterion on synthetic series, the critical stress ratio summary, and the
// critical state line fit against exact lines and a hand least-squares computation.
#include "grainlab/critical_state.h"
#include "grainlab/statistics.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace grainlab {
namespace {

struct Series {
    std::vector<double> eps1, q, p, epsV;
};

// n records over eps1 in [0, 0.3], q(eps), p constant, epsV(eps).
template <class Q, class V>
Series makeSeries(int n, Q q, V v, double p = 1e5) {
    Series s;
    for (int i = 0; i < n; ++i) {
        const double e = 0.3 * i / (n - 1);
        s.eps1.push_back(e);
        s.q.push_back(q(e));
        s.p.push_back(p);
        s.epsV.push_back(v(e));
    }
    return s;
}

SteadyStateResult check(const Series& s) {
    return steadyState(s.eps1, s.q, s.p, s.epsV);
}

TEST(SteadyState, ASteadyEndIsSteady) {
    // Hardening then flat at q = 0.8 p after eps1 = 0.1; dilation stops there too.
    const Series s = makeSeries(
        301, [](double e) { return 8e4 * std::min(1.0, e / 0.1); },
        [](double e) { return -0.2 * std::min(e, 0.1); });
    const SteadyStateResult r = check(s);
    EXPECT_TRUE(r.steady) << r.reason;
    EXPECT_NEAR(r.stressSlope, 0.0, 1e-12);
    EXPECT_NEAR(r.volumeSlope, 0.0, 1e-12);
    EXPECT_GE(r.samples, 50u); // eps1 in [0.25, 0.3] at 0.001 spacing, 0.25 at round-off
    EXPECT_LE(r.samples, 51u);
}

TEST(SteadyState, StillHardeningIsNotSteady) {
    // dq/deps1 = 2 p over the last window: above the bound 0.5.
    const Series s = makeSeries(
        301, [](double e) { return 2e5 * e; }, [](double) { return 0.0; });
    const SteadyStateResult r = check(s);
    EXPECT_FALSE(r.steady);
    EXPECT_NEAR(r.stressSlope, 2.0, 1e-9);
    EXPECT_NE(r.reason.find("dq/deps1"), std::string::npos) << r.reason;
}

TEST(SteadyState, StillDilatingIsNotSteady) {
    const Series s = makeSeries(
        301, [](double) { return 8e4; }, [](double e) { return -0.2 * e; });
    const SteadyStateResult r = check(s);
    EXPECT_FALSE(r.steady);
    EXPECT_NEAR(r.volumeSlope, -0.2, 1e-9);
    EXPECT_NE(r.reason.find("deps_v"), std::string::npos) << r.reason;
}

TEST(SteadyState, NoisySteadyIsSteadyAndNoisyHardeningIsNot) {
    // Fluctuations of 1 % of p on q and 1e-4 on epsV, 101 records in the window: the
    // least-squares slopes scatter by 0.07 and 7e-4 (sigma / sqrt(S_xx)), well inside the bounds.
    std::mt19937_64 rng(3);
    std::normal_distribution<double> noise(0.0, 1.0);
    const Series steady = makeSeries(
        601, [&](double) { return 8e4 + 1e3 * noise(rng); },
        [&](double) { return 1e-4 * noise(rng); });
    EXPECT_TRUE(check(steady).steady) << check(steady).reason;
    const Series hardening = makeSeries(
        601, [&](double e) { return 8e4 + 2e5 * e + 1e3 * noise(rng); },
        [&](double) { return 1e-4 * noise(rng); });
    EXPECT_FALSE(check(hardening).steady);
}

TEST(SteadyState, ExtensionAndShortTests) {
    Series s = makeSeries(
        301, [](double) { return -5e4; }, [](double) { return 0.0; });
    for (double& e : s.eps1) {
        e = -e;
    }
    EXPECT_TRUE(check(s).steady) << check(s).reason;
    const Series shortTest = makeSeries(
        3, [](double) { return 0.0; }, [](double) { return 0.0; });
    Series tiny = shortTest;
    for (double& e : tiny.eps1) {
        e *= 0.1; // spans 0.03 < window
    }
    EXPECT_FALSE(check(tiny).steady);
}

TEST(CriticalState, StressRatioMeanAndSampleScatter) {
    // M over the steady tests is the seed statistics' scatterOf (statistics.h).
    const Scatter s = scatterOf(std::vector<double>{0.5, 0.6, 0.7});
    EXPECT_NEAR(s.mean, 0.6, 1e-15);
    EXPECT_NEAR(s.sd, 0.1, 1e-15); // sqrt((0.01 + 0 + 0.01) / 2)
    EXPECT_EQ(s.count, 3);
    EXPECT_EQ(scatterOf(std::vector<double>{0.55}).sd, 0.0);
}

TEST(CriticalState, ExactLineIsRecovered) {
    const double eGamma = 1.05, lambda = 0.021;
    std::vector<double> p = {2e4, 5e4, 1e5, 4e5, 1e6}, e;
    for (double x : p) {
        e.push_back(eGamma - lambda * std::log(x));
    }
    const CriticalStateLine line = fitCriticalStateLine(p, e);
    EXPECT_NEAR(line.eGamma, eGamma, 1e-12);
    EXPECT_NEAR(line.lambda, lambda, 1e-13);
    EXPECT_NEAR(line.rSquared, 1.0, 1e-12);
    EXPECT_NEAR(line.voidRatioAt(3e5), eGamma - lambda * std::log(3e5), 1e-12);
    EXPECT_EQ(line.equation(), "e = 1.05 - 0.021 ln(p'/1 Pa)");
}

TEST(CriticalState, ScatteredPointsMatchAHandLeastSquares) {
    // x = ln p = {0, 1, 2} (p = 1, e, e^2 Pa), y = {0.9, 0.85, 0.82}: by hand, mean x = 1,
    // mean y = 2.57 / 3 = 0.856667, Sxy = (-1)(0.043333) + (1)(-0.036667) = -0.08,
    // Sxx = 2, slope = -0.04, intercept = 0.856667 + 0.04 = 0.896667; residuals
    // 0.003333, -0.006667, 0.003333 give SSres = 6.6667e-5; SStot = 0.0032667; R^2 = 0.979592.
    const std::vector<double> p = {1.0, std::exp(1.0), std::exp(2.0)};
    const CriticalStateLine line = fitCriticalStateLine(p, {0.9, 0.85, 0.82});
    EXPECT_NEAR(line.lambda, 0.04, 1e-12);
    EXPECT_NEAR(line.eGamma, 0.896666666666667, 1e-12);
    EXPECT_NEAR(line.rSquared, 1.0 - 6.666666666666667e-5 / 0.003266666666666667, 1e-10);
    EXPECT_EQ(line.points, 3u);
}

TEST(CriticalState, RefusesTooFewOrDegeneratePoints) {
    EXPECT_THROW(fitCriticalStateLine({1e5}, {0.8}), std::invalid_argument);
    EXPECT_THROW(fitCriticalStateLine({1e5, 1e5}, {0.8, 0.7}), std::invalid_argument);
    EXPECT_THROW(fitCriticalStateLine({1e5, -1.0}, {0.8, 0.7}), std::invalid_argument);
}

} // namespace
} // namespace grainlab
