// The servo probe on cases with known answers. A sampled proportional-integral loop on a plant
// of stiffness ratio r = E_true / E_hat obeys, per servo update (error e_k, integral gain g_I):
//     e_{k+1} = e_k - r g (e_k + I_k),  I_k = I_{k-1} + g_I e_k,
// whose characteristic polynomial z^2 + (r g (1 + g_I) - 2) z + (1 - r g) is stable (Jury) if
// and only if 0 < r g < 4 / (2 + g_I), and whose error changes sign from one update to the
// next once r g > 1 (the root near z = 1 - r g turns negative). A column of equal disks in a
// periodic cell, touching only along x2, is such a plant with r = 1 exactly: every grain is in
// equilibrium, the cell's affine motion is the whole motion, and sigma22 = k_n delta / L1 is
// linear in the lateral strain with slope E_hat_22 = k_n d / L1, which is the servo's affine
// estimate. So the servo must oscillate past g = 1, diverge past g = 4 / (2 + g_I) (2 with no
// integral term), at any interval, and the map's bisection must find that limit.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/oval_shape.h"
#include "grainlab/servo_probe.h"
#include "grainlab/simulation.h"
#include "grainlab/stability_bisection.h"

namespace grainlab {
namespace {

constexpr double kPressure = 1e5; // [Pa]

/// N disks of width 1 mm in a column along x2 with overlap delta each, in a cell 3 mm wide:
/// sigma22 = k_n delta / L1 = `start` times kPressure.
SimulationState diskColumn(double start, int n = 10) {
    const double width = 1e-3, l1 = 3e-3;
    const double kn = SimulationParameters{}.normalStiffness;
    const double overlap = start * kPressure * l1 / kn;
    const double spacing = width - overlap;
    SimulationState s;
    s.shapes = {makeOval(width, 1.0)};
    s.grains.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        s.grains.x1[std::size_t(i)] = 0.5 * l1;
        s.grains.x2[std::size_t(i)] = (i + 0.5) * spacing;
        s.grains.shape[std::size_t(i)] = 0;
    }
    s.cell = {l1, 0.0, 0.0, n * spacing};
    s.parameters.friction = 0.5;
    s.parameters.timeStep = 1e-6;
    return s;
}

ServoShear shearOf(std::int64_t steps) {
    // A rate cap far above what the loop asks for, so that the loop stays linear until the
    // contacts open.
    return {kPressure, 1e-6, 1e4, steps};
}

ServoProbeResult probe(double gain, int interval, double integralGain, std::int64_t updates = 400) {
    return runServoProbe(diskColumn(1.1), {gain, interval, integralGain},
                         shearOf(updates * interval), ServoThresholds{});
}

TEST(ServoProbe, TheDiskColumnIsTheLinearLoopWithRatioOne) {
    // P only, g = 0.5: each update halves the error, from +10 % (sigma22 above its target).
    const ServoProbeResult r = probe(0.5, 1, 0.0, 40);
    ASSERT_GE(r.error.perUpdate.size(), 8u);
    for (std::size_t k = 0; k + 1 < 8; ++k) {
        EXPECT_NEAR(r.error.perUpdate[k + 1], 0.5 * r.error.perUpdate[k], 1e-3 * 0.1) << k;
    }
    EXPECT_EQ(r.response, ServoResponse::Steady);
    EXPECT_LT(r.stats.maxError, 1e-4);
    // The first update reads the starting +10 %; the first step already halves it.
    EXPECT_NEAR(r.error.perUpdate[0], 0.1, 1e-3);
    EXPECT_NEAR(r.stats.transientMax, 0.05, 1e-3);
}

TEST(ServoProbe, OvershootPastGainOneAndDivergencePastTwo) {
    for (int interval : {1, 4}) {
        // g = 0.8: the error keeps its sign; g = 1.5: it alternates, shrinking by half.
        const ServoProbeResult under = probe(0.8, interval, 0.0, 60);
        const ServoProbeResult over = probe(1.5, interval, 0.0, 60);
        for (std::size_t k = 0; k < 6; ++k) {
            EXPECT_GT(under.error.perUpdate[k], 0.0) << "interval " << interval << ", update " << k;
            EXPECT_GT(over.error.perUpdate[k] * (k % 2 == 0 ? 1.0 : -1.0), 0.0)
                << "interval " << interval << ", update " << k;
        }
        EXPECT_EQ(under.response, ServoResponse::Steady) << interval;
        EXPECT_EQ(over.response, ServoResponse::Steady) << interval; // decayed after the transient
        // g = 2.2: |1 - g| = 1.2, the alternation grows until the contacts open.
        const ServoProbeResult diverging = probe(2.2, interval, 0.0);
        EXPECT_EQ(diverging.response, ServoResponse::Diverging) << interval;
        EXPECT_GT(diverging.stats.alternating, 0.1) << interval;
        EXPECT_GT(diverging.stats.reversals, 0.5) << interval;
    }
}

TEST(ServoProbe, BisectionFindsTheJuryLimit) {
    for (double integralGain : {0.0, 0.05}) {
        const double expected = 4.0 / (2.0 + integralGain);
        const StepLimit limit = bisectStableStep(
            [&](double gain) {
                ProbeResult p;
                p.stable = !servoUnstable(probe(gain, 1, integralGain, 1000).response);
                return p;
            },
            1.0, 3.0, 0.002);
        ASSERT_TRUE(limit.bracketed);
        // Just below the limit the alternation decays slowly (|z| -> 1), so the measured line
        // sits a little below it; never above.
        EXPECT_LE(limit.low, expected * 1.003) << integralGain;
        EXPECT_GT(limit.low, expected * 0.98) << integralGain;
    }
}

ServoErrorSeries series(const std::vector<double>& perUpdate) {
    ServoErrorSeries s;
    s.perStep = perUpdate;
    s.perUpdate = perUpdate;
    for (std::size_t k = 0; k < perUpdate.size(); ++k) {
        s.updateStep.push_back(std::int64_t(k));
    }
    return s;
}

TEST(ServoProbe, ClassificationOfSyntheticErrors) {
    const ServoThresholds t;
    std::vector<double> lag(400, 0.02), alternating(400), growing(400), quiet(400);
    for (std::size_t k = 0; k < 400; ++k) {
        alternating[k] = (k % 2 ? -1.0 : 1.0) * 0.03;
        growing[k] = (k % 2 ? -1.0 : 1.0) * 1e-3 * std::pow(1.02, double(k));
        quiet[k] = 0.005 * std::sin(0.01 * double(k));
    }
    EXPECT_EQ(classifyServo(servoErrorStats(series(lag), t), t), ServoResponse::Lagging);
    EXPECT_EQ(classifyServo(servoErrorStats(series(alternating), t), t),
              ServoResponse::Oscillating);
    EXPECT_EQ(classifyServo(servoErrorStats(series(growing), t), t), ServoResponse::Diverging);
    EXPECT_EQ(classifyServo(servoErrorStats(series(quiet), t), t), ServoResponse::Steady);
    const ServoErrorStats a = servoErrorStats(series(alternating), t);
    EXPECT_NEAR(a.alternating, 0.03, 1e-12);
    EXPECT_NEAR(a.reversals, 1.0, 1e-12);
    EXPECT_NEAR(a.meanError, 0.0, 1e-3);
    // A run that stopped is diverging whatever its error was.
    EXPECT_EQ(classifyServo(servoErrorStats(series(quiet), t, true, "overlap"), t),
              ServoResponse::Diverging);
    // A non-finite stress stops the judgement.
    quiet[300] = NAN;
    EXPECT_TRUE(servoErrorStats(series(quiet), t).stopped);
}

} // namespace
} // namespace grainlab
