// The bisection against closed forms: a periodic chain of four equal disks on linear springs,
// pre-compressed, oscillating in its highest mode. The engine integrates with symplectic Euler
// (v <- v + dt F/m, then x <- x + dt v: central differences with velocities at half steps), for
// which a mass-spring mode of frequency omega is stable iff omega dt < 2 (the iteration matrix
// has det 1 and trace 2 - (omega dt)^2). The highest mode of a periodic chain of N (even)
// masses m on springs k has omega = 2 sqrt(k/m), so the chain's limit is exactly
// dt = sqrt(m/k), 1 in the map's unit. With viscous damping integrated time-centred, as the
// engine does (v_new = ((1 - h) v + dt F/m) / (1 + h)), the iteration matrix has det
// (1 - h)/(1 + h) and trace 1 + det - (omega dt)^2/(1 + h), and the Jury conditions give the
// same limit omega dt < 2 for any h: damping moves the limit not at all.
#include <cmath>

#include <gtest/gtest.h>

#include "grainlab/simulation.h"
#include "grainlab/stability_bisection.h"
#include "grainlab/stability_probe.h"

namespace grainlab {
namespace {

constexpr double kWidth = 1e-3;   // disk diameter [m]
constexpr double kOverlap = 1e-5; // pre-compression of every contact [m]
constexpr double kSpeed = 1e-3;   // alternating initial velocity [m/s]

/// Four disks in a row along x1 touching their neighbours (and, across the periodic boundary,
/// the first and the last), with velocities +v, -v, +v, -v: the chain's highest mode.
SimulationState chain(DampingParameters damping) {
    SimulationState s;
    s.parameters.damping = damping;
    s.parameters.friction = 0.0;
    s.parameters.tangentialStiffness = s.parameters.normalStiffness;
    const double spacing = kWidth - kOverlap;
    s.cell = {4 * spacing, 0.0, 0.0, 3 * kWidth};
    s.shapes.push_back(makeOval(kWidth, 1.0));
    s.grains.resize(4);
    for (int i = 0; i < 4; ++i) {
        s.grains.x1[i] = (i + 0.5) * spacing;
        s.grains.x2[i] = 1.5 * kWidth;
        s.grains.theta[i] = 0;
        s.grains.v1[i] = i % 2 ? -kSpeed : kSpeed;
        s.grains.v2[i] = 0;
        s.grains.omega[i] = 0;
        s.grains.shape[i] = 0;
    }
    return s;
}

ProbeSettings chainSettings() {
    ProbeSettings p;
    p.steps = 4000;
    p.checkInterval = 1;
    return p;
}

TEST(StabilityClosedForm, TimeUnitIsSqrtMassOverStiffness) {
    const SimulationState s = chain({DampingKind::None, 0.0});
    const double m = s.parameters.density * s.shapes[0].area;
    EXPECT_DOUBLE_EQ(probeTimeUnit(s), std::sqrt(m / s.parameters.normalStiffness));
}

TEST(StabilityClosedForm, DetectorSplitsTheChainAtItsLimit) {
    const SimulationState s = chain({DampingKind::None, 0.0});
    const double unit = probeTimeUnit(s);
    EXPECT_TRUE(runStabilityProbe(s, 0.2 * unit, chainSettings()).stable);
    EXPECT_TRUE(runStabilityProbe(s, 0.995 * unit, chainSettings()).stable)
        << "bounded, though the energies fluctuate strongly this close to the limit";
    const ProbeResult above = runStabilityProbe(s, 1.005 * unit, chainSettings());
    EXPECT_FALSE(above.stable);
    EXPECT_EQ(above.detector, BlowUp::KineticEnergy) << above.detail;
    const ProbeResult far = runStabilityProbe(s, 3.0 * unit, chainSettings());
    EXPECT_FALSE(far.stable);
    EXPECT_LT(far.step, 100) << far.detail;
}

TEST(StabilityClosedForm, BisectionFindsTheChainLimitToItsPrecision) {
    for (const DampingParameters damping : {DampingParameters{DampingKind::None, 0.0},
                                            DampingParameters{DampingKind::GlobalViscous, 0.2}}) {
        const SimulationState s = chain(damping);
        const double unit = probeTimeUnit(s);
        const double precision = 1e-3;
        const StepLimit limit = bisectStableStep(
            [&](double step) { return runStabilityProbe(s, step * unit, chainSettings()); }, 0.1,
            4.0, precision);
        ASSERT_TRUE(limit.bracketed);
        // The exact limit 1 lies in the final bracket [low, high], high / low - 1 <= precision.
        EXPECT_LE(limit.low, 1.0) << "damping " << int(damping.kind);
        EXPECT_GE(limit.high, 1.0) << "damping " << int(damping.kind);
        EXPECT_LE(limit.high / limit.low - 1.0, precision);
        EXPECT_NEAR(limit.limit, 1.0, precision);
        EXPECT_NE(limit.detector, BlowUp::None);
    }
}

TEST(StabilityClosedForm, BisectionSaysWhenTheBoundsDoNotBracket) {
    const SimulationState s = chain({DampingKind::None, 0.0});
    const double unit = probeTimeUnit(s);
    const StepProbe probe = [&](double step) {
        return runStabilityProbe(s, step * unit, chainSettings());
    };
    const StepLimit tooLow = bisectStableStep(probe, 0.1, 0.5, 0.01);
    EXPECT_FALSE(tooLow.bracketed);
    EXPECT_EQ(tooLow.limit, 0.5) << "stable at the upper bound";
    const StepLimit tooHigh = bisectStableStep(probe, 2.0, 4.0, 0.01);
    EXPECT_FALSE(tooHigh.bracketed);
    EXPECT_EQ(tooHigh.limit, 2.0) << "unstable at the lower bound";
    EXPECT_THROW(bisectStableStep(probe, 0.0, 1.0, 0.01), std::invalid_argument);
    EXPECT_THROW(bisectStableStep(probe, 0.5, 1.0, 0.0), std::invalid_argument);
}

TEST(StabilityClosedForm, TheEngineGuardsStayOnOutsideTheProbe) {
    // The estimate's refusal is what the probe switches off; a plain Simulation keeps it.
    SimulationState s = chain({DampingKind::None, 0.0});
    s.parameters.timeStep = 3.0 * probeTimeUnit(s);
    EXPECT_THROW(Simulation{s}, std::invalid_argument);
    s.parameters.stability.unguarded = true;
    EXPECT_NO_THROW(Simulation{s});
}

} // namespace
} // namespace grainlab
