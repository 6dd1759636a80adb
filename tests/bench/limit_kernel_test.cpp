// The bench's minimal disk kernel (app/bench/limit_kernel.h) computes what the engine computes:
// on a small frictional disk scene, moving, with tangential history, both are stepped side by
// side with the servo off (axis 1 at a constant engineering rate, axis 2 held) and their
// positions, velocities and per-grain forces compared after every few steps. Without this the
// `--limit` row would compare the engine with a kernel doing other (perhaps less) work.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "bench/limit_kernel.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

constexpr double kStrainRate = 0.2; // [1/s], as the bench

/// 150 disks compacted to 100 kPa (as the bench prepares them), then sheared with friction for
/// 300 steps: touching, moving, tangential forces stored.
SimulationState movingFrictionalDisks() {
    scenes::CompactedSceneSpec spec;
    spec.grains = 150;
    spec.aspectRatio = 1.0;
    spec.seed = 9;
    SimulationState dense = scenes::compactedState(spec);
    dense.parameters = SimulationParameters{};
    dense.parameters.friction = 0.5;
    Simulation shear(std::move(dense));
    shear.setAxisControl(0, AxisControl{AxisMode::Strain, 2.0});
    shear.setAxisControl(1, AxisControl{AxisMode::Strain, -1.0});
    shear.advance(300);
    return shear.state();
}

double largest(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) {
        m = std::max(m, std::fabs(x));
    }
    return m;
}

TEST(LimitKernel, ComputesTheEngineForcesOnAMovingFrictionalScene) {
    const SimulationState state = movingFrictionalDisks();
    std::size_t stored = 0;
    for (double f : state.pairs.tangentialForce) {
        stored += f != 0.0 ? 1 : 0;
    }
    ASSERT_GT(stored, 50u) << "the scene must carry tangential history";

    Simulation engine(state);
    // As the bench drives it (a constant strain rate on axis 1), with axis 2 held.
    engine.setAxisControl(0, AxisControl{AxisMode::Strain, kStrainRate});
    engine.setAxisControl(1, AxisControl{AxisMode::Strain, 0.0});
    LimitKernel kernel(state, kStrainRate, 1);
    ASSERT_EQ(kernel.pairCount(), engine.stateRef().pairs.size());

    const double width = 1e-3; // the smallest grain [m]
    for (int round = 0; round < 10; ++round) {
        engine.advance(30);
        kernel.advance(30);
        const SimulationState& s = engine.stateRef();
        const ContactNetwork net = engine.contactNetwork();
        std::vector<double> f1, f2, torque;
        kernel.netForces(f1, f2, torque);
        ASSERT_EQ(kernel.contactCount(), engine.contactCount()) << "round " << round;
        const double forceScale = std::max(largest(net.netForce1), largest(net.netForce2));
        const double speedScale = largest(s.grains.v1);
        ASSERT_GT(forceScale, 0.0);
        ASSERT_GT(speedScale, 0.0);
        for (std::size_t i = 0; i < s.grains.size(); ++i) {
            // The same expressions in the same order: bit-identical without fused multiply-adds
            // (checked with -ffp-contract=off over these 300 steps); the native build fuses them
            // differently in the two loops, and a net force is a small difference of contact
            // forces, so its round-off grows to ~1e-8 of the largest net force and spin in 300
            // steps.
            ASSERT_NEAR(kernel.x1()[i], s.grains.x1[i], 1e-12 * width) << "grain " << i;
            ASSERT_NEAR(kernel.x2()[i], s.grains.x2[i], 1e-12 * width) << "grain " << i;
            ASSERT_NEAR(kernel.v1()[i], s.grains.v1[i], 1e-7 * speedScale) << "grain " << i;
            ASSERT_NEAR(kernel.omega()[i], s.grains.omega[i], 1e-7 * speedScale / width)
                << "grain " << i;
            ASSERT_NEAR(f1[i], net.netForce1[i], 1e-7 * forceScale) << "grain " << i;
            ASSERT_NEAR(f2[i], net.netForce2[i], 1e-7 * forceScale) << "grain " << i;
        }
    }
}

TEST(LimitKernel, RefusesOvals) {
    scenes::CompactedSceneSpec spec;
    spec.grains = 40;
    spec.aspectRatio = 0.6;
    spec.criterion.maxSteps = 10;
    const SimulationState state = scenes::compactScene(spec).simulation.state();
    EXPECT_THROW(LimitKernel(state, kStrainRate, 1), std::invalid_argument);
}

} // namespace
} // namespace grainlab
