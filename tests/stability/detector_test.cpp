// The blow-up detector of the stability probe on real scenes, one test per failure mode: each
// mode is driven past the limit and must fire, and the same scene at a small step must not.
// The quiet mode is the one a new user meets: a damped dense packing just above its limit
// neither runs away nor turns NaN, it jitters, and only the floor of the unbalanced-force index
// shows it.
#include <cfenv>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "grainlab/simulation.h"
#include "grainlab/stability_cell.h"
#include "grainlab/stability_probe.h"
#include "grainlab/stability_scene.h"

namespace grainlab {
namespace {

StabilityMapSpec smallMap() {
    StabilityMapSpec spec;
    spec.grains = 100;
    spec.steps = 2000;
    return spec;
}

StabilityCell cellOf(double eta, DampingParameters damping, PackingState packing) {
    return {"test", eta, 1.0, damping, packing};
}

/// A probe start for `cell`, with its settings; the packing built once per kind.
struct Scene {
    SimulationState state;
    ProbeSettings settings;
    double unit = 0;
};

Scene sceneOf(const StabilityCell& cell) {
    const StabilityMapSpec spec = smallMap();
    const StabilityPacking packing = stabilityPacking(spec, cell);
    Scene s{stabilityProbeState(spec, cell, packing, cell.damping),
            stabilityProbeSettings(spec, cell), 0.0};
    s.unit = probeTimeUnit(s.state);
    return s;
}

const DampingParameters kNone{DampingKind::None, 0.0};
const DampingParameters kViscous{DampingKind::GlobalViscous, 0.05};
const PackingState kGas{PackingKind::Gas, 0.0};
const PackingState kDense{PackingKind::Dense, 15e3};

TEST(StabilityDetector, GasCollisionsPastTheLimitBreakTheEnergyBalance) {
    const Scene gas = sceneOf(cellOf(1.0, kNone, kGas));
    EXPECT_TRUE(runStabilityProbe(gas.state, 0.2 * gas.unit, gas.settings).stable);
    const ProbeResult far = runStabilityProbe(gas.state, 3.0 * gas.unit, gas.settings);
    EXPECT_FALSE(far.stable);
    EXPECT_EQ(far.detector, BlowUp::EnergyResidual) << far.detail;
}

TEST(StabilityDetector, DensePackingFarAboveTheLimitRunsAway) {
    const Scene dense = sceneOf(cellOf(0.6, kNone, kDense));
    const ProbeResult small = runStabilityProbe(dense.state, 0.2 * dense.unit, dense.settings);
    EXPECT_TRUE(small.stable) << small.detail;
    EXPECT_LT(small.maxResidual, 1e-3);
    const ProbeResult far = runStabilityProbe(dense.state, 2.5 * dense.unit, dense.settings);
    EXPECT_FALSE(far.stable);
    EXPECT_LT(far.step, 50) << "far above the limit the run fails within a few tens of steps";
    EXPECT_TRUE(far.detector == BlowUp::Displacement || far.detector == BlowUp::EnergyResidual ||
                far.detector == BlowUp::KineticEnergy)
        << blowUpName(far.detector) << ": " << far.detail;
    // With the energy detectors off, the same run is caught by the motion itself.
    ProbeSettings motionOnly = dense.settings;
    motionOnly.thresholds.maxResidual = motionOnly.thresholds.catastrophic =
        motionOnly.thresholds.growth = std::numeric_limits<double>::infinity();
    const ProbeResult runaway = runStabilityProbe(dense.state, 2.5 * dense.unit, motionOnly);
    EXPECT_FALSE(runaway.stable);
    EXPECT_TRUE(runaway.detector == BlowUp::Displacement || runaway.detector == BlowUp::Overlap ||
                runaway.detector == BlowUp::NonFinite)
        << blowUpName(runaway.detector) << ": " << runaway.detail;
}

TEST(StabilityDetector, DampedDensePackingJustAboveTheLimitOnlyJitters) {
    const Scene dense = sceneOf(cellOf(1.0, kViscous, kDense));
    ASSERT_TRUE(dense.settings.thresholds.unbalancedFloor);
    // Only the floor: the energy detectors off, to show that the floor alone names the mode.
    ProbeSettings floorOnly = dense.settings;
    floorOnly.trace = true;
    floorOnly.thresholds.maxResidual = floorOnly.thresholds.catastrophic =
        floorOnly.thresholds.growth = std::numeric_limits<double>::infinity();
    const ProbeResult calm = runStabilityProbe(dense.state, 0.3 * dense.unit, floorOnly);
    EXPECT_TRUE(calm.stable) << calm.detail;
    EXPECT_LT(calm.finalUnbalanced, 1.0) << "at a stable step the packing calms";
    const ProbeResult jitter = runStabilityProbe(dense.state, 0.8 * dense.unit, floorOnly);
    EXPECT_FALSE(jitter.stable);
    EXPECT_EQ(jitter.detector, BlowUp::UnbalancedFloor) << jitter.detail;
    EXPECT_EQ(jitter.stepsRun, floorOnly.steps) << "nothing ran away: the run went to its end";
    double kinetic = 0, overlap = 0;
    for (const ProbeCheck& c : jitter.trace) {
        ASSERT_TRUE(std::isfinite(c.kinetic) && std::isfinite(c.residual));
        kinetic = std::max(kinetic, c.kinetic);
        overlap = std::max(overlap, c.maxOverlap);
    }
    EXPECT_LT(kinetic, 1.0) << "no kinetic energy without bound";
    EXPECT_LT(overlap, 0.05) << "no overlap runaway";
    EXPECT_GT(jitter.finalUnbalanced, 5.0);
    // With every detector on, the same step is unstable too.
    EXPECT_FALSE(runStabilityProbe(dense.state, 0.8 * dense.unit, dense.settings).stable);
}

TEST(StabilityDetector, OverlapAndNonFiniteStatesAreNamed) {
    // Two disks pressed into each other by 0.3 of their width, at a small step.
    SimulationState s;
    s.parameters.damping = {DampingKind::None, 0.0};
    s.parameters.friction = 0.0;
    s.cell = {6e-3, 0.0, 0.0, 6e-3};
    s.shapes.push_back(makeOval(1e-3, 1.0));
    s.grains.resize(2);
    for (int i = 0; i < 2; ++i) {
        s.grains.x1[i] = 3e-3 + (i ? 0.35e-3 : -0.35e-3);
        s.grains.x2[i] = 3e-3;
        s.grains.theta[i] = s.grains.v1[i] = s.grains.v2[i] = s.grains.omega[i] = 0;
        s.grains.shape[i] = 0;
    }
    ProbeSettings settings;
    const ProbeResult overlap = runStabilityProbe(s, 0.01 * probeTimeUnit(s), settings);
    EXPECT_FALSE(overlap.stable);
    EXPECT_EQ(overlap.detector, BlowUp::Overlap) << overlap.detail;
    s.grains.x1[1] = 4.5e-3; // apart
    EXPECT_TRUE(runStabilityProbe(s, 0.01 * probeTimeUnit(s), settings).stable);
    s.grains.v1[0] = std::numeric_limits<double>::quiet_NaN();
    // The test main traps invalid operations; this probe must meet the NaN it is given.
    const int traps = fedisableexcept(FE_ALL_EXCEPT);
    const ProbeResult nan = runStabilityProbe(s, 0.01 * probeTimeUnit(s), settings);
    std::feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(traps);
    EXPECT_FALSE(nan.stable);
    EXPECT_EQ(nan.detector, BlowUp::NonFinite) << nan.detail;
    EXPECT_EQ(nan.step, 1);
}

} // namespace
} // namespace grainlab
