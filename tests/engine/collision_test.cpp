// Two-grain closed forms (docs/physics.md): head-on and oblique collisions, a loaded contact,
// Coulomb sliding.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "grainlab/contact_law.h"
#include "scenes.h"

namespace grainlab {
namespace {

using test::bareParameters;
using test::GrainSpec;
using test::makeScene;

constexpr double kPi = std::numbers::pi;

TEST(Collision, HeadOnDisksMatchHarmonicContact) {
    // Two equal disks approach at +-v. Linear spring: contact lasts pi sqrt(m_eff / k_n), the
    // rebound is elastic (restitution 1 without damping) and energy is conserved.
    const double d = 1.5e-3, v = 0.05;
    auto p = bareParameters();
    p.timeStep = 1e-7; // ~150 steps per contact: the discrete onset error is O(dt / T)
    const double gap = 2e-7;
    SimulationState s = makeScene({{0.01, 0.01 - 0.5 * d - gap, 0, 0, v, 0, d, 1.0},
                                   {0.01, 0.01 + 0.5 * d + gap, 0, 0, -v, 0, d, 1.0}},
                                  0.02, 0.02, p);
    Simulation sim(std::move(s));
    const double m = sim.grainMass()[0];
    const double kineticBefore = sim.energies().kinetic;
    std::int64_t contactSteps = 0;
    double maxEnergyError = 0;
    for (int k = 0; k < 4000; ++k) {
        sim.step();
        contactSteps += sim.contactCount();
        const Energies e = sim.energies();
        if (sim.contactCount() == 0) {
            maxEnergyError = std::max(maxEnergyError, std::fabs(e.kinetic - kineticBefore));
        }
    }
    const double duration = kPi * std::sqrt(0.5 * m / p.normalStiffness);
    EXPECT_NEAR(contactSteps * p.timeStep, duration, 2.0 * p.timeStep);
    const auto& g = sim.stateRef().grains;
    EXPECT_NEAR(g.v2[0], -v, 1e-3 * v) << "restitution must be 1 without damping";
    EXPECT_NEAR(g.v2[1], v, 1e-3 * v);
    EXPECT_LT(maxEnergyError, 2e-3 * kineticBefore);
    EXPECT_DOUBLE_EQ(g.v1[0], 0.0); // head-on: nothing sideways
}

TEST(Collision, ViscousDampingGivesRestitutionBelowOne) {
    const double d = 1e-3, v = 0.05;
    auto p = bareParameters();
    p.damping = {DampingKind::GlobalViscous, 0.05};
    Simulation sim(makeScene({{0.01, 0.01 - 0.5 * d - 1e-6, 0, 0, v, 0, d, 1.0},
                              {0.01, 0.01 + 0.5 * d + 1e-6, 0, 0, -v, 0, d, 1.0}},
                             0.02, 0.02, p));
    sim.advance(300);
    const double after = sim.stateRef().grains.v2[1];
    EXPECT_GT(after, 0.0);
    EXPECT_LT(after, 0.95 * v);
    EXPECT_GT(sim.energies().dampingWork, 0.0);
}

TEST(Collision, ObliqueFrictionalImpactDissipatesBySliding) {
    // A spinning-free oblique impact with friction: the tangential impulse is bounded by
    // mu times the normal impulse, and the energy lost equals the sliding work.
    const double d = 1.5e-3, v = 0.2;
    auto p = bareParameters();
    p.friction = 0.3;
    p.timeStep = 1e-7;
    const double angle = 40.0 * kPi / 180.0;
    const double offset = 0.5 * d + 1e-7;
    Simulation sim(makeScene({{0.01, 0.01, 0, 0, 0, 0, d, 1.0},
                              {0.01 - 2 * offset * std::cos(angle),
                               0.01 - 2 * offset * std::sin(angle), 0, v, 0, 0, d, 1.0}},
                             0.03, 0.03, p));
    const Energies before = sim.energies();
    bool slid = false;
    for (int k = 0; k < 6000; ++k) {
        sim.step();
        for (const auto& c : sim.contactNetwork().contacts) {
            EXPECT_LE(std::fabs(c.tangentialForce), p.friction * c.normalForce * (1 + 1e-12));
            slid = slid || c.sliding;
        }
    }
    EXPECT_TRUE(slid);
    const Energies after = sim.energies();
    EXPECT_EQ(sim.contactCount(), 0u);
    EXPECT_GT(after.frictionWork, 0.0);
    EXPECT_NEAR(before.kinetic - after.kinetic, after.frictionWork, 0.01 * after.frictionWork);
    // Impulses: momentum is conserved, and the spins balance (equal disks, opposite torques).
    const auto& g = sim.stateRef().grains;
    EXPECT_NEAR(g.v1[0] + g.v1[1], v, 1e-12);
    EXPECT_NEAR(g.v2[0] + g.v2[1], 0.0, 1e-12);
    EXPECT_NEAR(g.omega[0], g.omega[1], 1e-9 * std::fabs(g.omega[0]) + 1e-12);
    EXPECT_GT(std::fabs(g.omega[0]), 0.0);
}

TEST(Collision, LoadedChainReachesSpringForce) {
    // Four disks stacked along x1 in a periodic cell form an endless chain. Holding sigma11 at
    // a target with the servo, the chain force must settle at sigma11 * L2 and each overlap at
    // f_n / k_n: a grain resting against another under a sustained load.
    const double d = 1e-3, target = 2e5;
    auto p = bareParameters();
    p.damping = {DampingKind::GlobalViscous, 0.3};
    p.servo.maxStrainRate = 5.0;
    const double l1 = 4.0 * d + 1e-5, l2 = 2.5 * d;
    std::vector<test::GrainSpec> chain;
    for (int k = 0; k < 4; ++k) {
        chain.push_back({(k + 0.5) * l1 / 4, 0.5 * l2, 0, 0, 0, 0, d, 1.0});
    }
    Simulation sim(makeScene(chain, l1, l2, p));
    sim.setAxisControl(0, {AxisMode::Stress, 0.0, target});
    sim.setAxisControl(1, {AxisMode::Strain, 0.0, 0.0});
    sim.advance(20000);
    const ContactNetwork net = sim.contactNetwork();
    ASSERT_EQ(net.contacts.size(), 4u);
    const double expected = target * sim.cell()[3];
    for (const auto& c : net.contacts) {
        EXPECT_NEAR(c.normalForce, expected, 1e-3 * expected);
        EXPECT_NEAR(c.normalForce, p.normalStiffness * c.overlap, 1e-9 * c.normalForce);
    }
    EXPECT_NEAR(sim.stress().s11, target, 1e-3 * target);
}

TEST(ContactLaw, TangentialForceGrowsThenSlidesAtCoulombLimit) {
    const ContactLawParameters p = contactLawParameters(1e8, 1e8, 0.5, 1e-6);
    const double overlap = 1e-6; // f_n = 100 N, limit 50 N
    const double vt = 0.1;       // each step: -k_t vt dt = -10 N
    double ft = 0;
    double slipWork = 0;
    for (int k = 1; k <= 8; ++k) {
        const ContactForce f = linearContactForce(overlap, vt, ft, p);
        ft = f.tangential;
        slipWork += f.slipWork;
        EXPECT_DOUBLE_EQ(f.normal, 100.0);
        if (k <= 5) {
            EXPECT_NEAR(ft, -10.0 * k, 1e-9);
            EXPECT_FALSE(f.sliding);
        } else {
            EXPECT_DOUBLE_EQ(ft, -50.0);
            EXPECT_TRUE(f.sliding);
        }
    }
    // Three sliding steps of vt dt = 1e-7 m against 50 N.
    EXPECT_NEAR(slipWork, 3 * 50.0 * 1e-7, 1e-12);
}

} // namespace
} // namespace grainlab
