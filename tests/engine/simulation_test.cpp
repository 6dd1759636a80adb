// The engine as a whole (docs/physics.md): periodic cell, Love-Weber stress, servo, stability,
// determinism, restart, neighbour lists, and the disk and frictionless fast paths.
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <set>
#include <tuple>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/time_step.h"
#include "scenes.h"

namespace grainlab {
namespace {

using test::bareParameters;
using test::makeScene;
using test::smallAssembly;

/// The shared compacted scene (engine/scenes): `grains` of aspect ratio `aspect` compacted
/// isotropically to `pressure` [Pa] by the servo, capped at 40 /s, until the runner's
/// equilibrium rule holds or `maxSteps` steps.
scenes::CompactedSceneSpec compaction(int grains, double aspect, std::uint64_t seed,
                                      double pressure, std::int64_t maxSteps) {
    scenes::CompactedSceneSpec spec{.grains = grains,
                                    .aspectRatio = aspect,
                                    .widths = {},
                                    .seed = seed,
                                    .pressure = pressure,
                                    .maxStrainRate = 40.0};
    spec.criterion.maxSteps = maxSteps;
    return spec;
}

/// 300 grains compacted frictionless to 100 kPa until the equilibrium rule holds, velocities
/// cleared (computed once per aspect ratio and test binary). Seed 42, the scene's own: from the
/// assembly of seed 1234, one weak sliding contact of ContactHistorySurvivesWrapsAndRebuilds
/// parts by 2.5e-6 of its normal force after 3000 steps (round-off grown by the dynamics, not
/// lost history), beyond that test's 1e-6.
SimulationState denseAssembly(double aspect) {
    static std::mutex lock;
    static std::map<double, SimulationState> cache;
    std::lock_guard<std::mutex> guard(lock);
    auto it = cache.find(aspect);
    if (it == cache.end()) {
        const scenes::CompactedSceneSpec spec = compaction(300, aspect, 42, 1e5, 400000);
        it = cache.emplace(aspect, scenes::compactedState(spec)).first;
    }
    return it->second;
}

TEST(PeriodicCell, GrainAcrossTheBoundaryTouchesThroughItsImage) {
    const double d = 1e-3, l = 5e-3;
    // Grain 0 near the top of the cell along x1, grain 1 near the bottom: they overlap through
    // the boundary by 1 micrometre.
    Simulation sim(makeScene({{l - 0.5 * d + 0.5e-6, 2e-3, 0, 0, 0, 0, d, 1.0},
                              {0.5 * d - 0.5e-6 + 0.0, 2e-3, 0, 0, 0, 0, d, 1.0}},
                             l, l, bareParameters()));
    const ContactNetwork net = sim.contactNetwork();
    ASSERT_EQ(net.contacts.size(), 1u);
    const ContactRecord& c = net.contacts[0];
    EXPECT_NEAR(c.overlap, 1e-6, 1e-15);
    EXPECT_EQ(std::abs(c.shift1), 1);
    EXPECT_EQ(c.shift2, 0);
    // Grain 0 lies just below the image of grain 1 (one cell up): the contact pushes grain 0
    // down (-x1) and grain 1 up, apart across the boundary.
    EXPECT_LT(net.netForce1[0], 0.0);
    EXPECT_GT(net.netForce1[1], 0.0);
    EXPECT_NEAR(net.netForce1[0], -1e8 * 1e-6, 1e-6);
}

TEST(PeriodicCell, ContactHistorySurvivesWrapsAndRebuilds) {
    // A frictional dense assembly sheared while drifting along x2, so grains cross the boundary.
    // With a tiny skin the list is rebuilt (and positions wrapped) many times; with a huge skin
    // never. If history were lost at a wrap, the two runs would part macroscopically.
    SimulationState start = denseAssembly(0.6);
    start.parameters.friction = 0.5;
    for (double& v : start.grains.v2) {
        v = 2.0;
    }
    SimulationState small = start, huge = start;
    small.parameters.neighbourSkin = 1e-5;
    huge.parameters.neighbourSkin = 0.015;
    small.pairs = {};
    huge.pairs = {};
    small.reference1.clear();
    huge.reference1.clear();
    Simulation a(std::move(small)), b(std::move(huge));
    for (Simulation* sim : {&a, &b}) {
        sim->setAxisControl(0, {AxisMode::Strain, 1.0, 0});
        sim->setAxisControl(1, {AxisMode::Stress, 0, 1e5});
        sim->advance(3000);
    }
    EXPECT_GT(a.neighbourRebuilds(), 20);
    EXPECT_EQ(b.neighbourRebuilds(), 1); // the initial build only
    const ContactNetwork na = a.contactNetwork(), nb = b.contactNetwork();
    ASSERT_EQ(na.contacts.size(), nb.contacts.size());
    double sumA = 0, sumB = 0;
    int sliding = 0;
    for (std::size_t c = 0; c < na.contacts.size(); ++c) {
        ASSERT_EQ(na.contacts[c].first, nb.contacts[c].first);
        ASSERT_EQ(na.contacts[c].second, nb.contacts[c].second);
        EXPECT_NEAR(na.contacts[c].tangentialForce, nb.contacts[c].tangentialForce,
                    1e-6 * na.contacts[c].normalForce);
        sumA += std::fabs(na.contacts[c].tangentialForce);
        sumB += std::fabs(nb.contacts[c].tangentialForce);
        sliding += na.contacts[c].sliding;
    }
    EXPECT_GT(sumA, 0.0);
    EXPECT_NEAR(sumA, sumB, 1e-8 * sumA);
    // The drift carried grains across x2 = L2 (6 mm of 3.6 cm).
    EXPECT_NEAR(a.stress().s11, b.stress().s11, 1e-8 * a.stress().s11);
}

TEST(PeriodicCell, AffineDeformationWithoutContactsLeavesFluctuationsAtZero) {
    auto p = bareParameters();
    p.damping = {DampingKind::GlobalViscous, 0.05};
    SimulationState s = smallAssembly(60, 0.6, 5, p, 0.5);
    const double l1 = s.cell[0], l2 = s.cell[3];
    Simulation sim(std::move(s));
    sim.setAxisControl(0, {AxisMode::Strain, 0.5, 0});
    sim.setAxisControl(1, {AxisMode::Strain, -0.3, 0});
    sim.advance(3000);
    ASSERT_EQ(sim.contactCount(), 0u);
    const auto& g = sim.stateRef().grains;
    const auto& h = sim.cell();
    const auto& h0 = sim.stateRef().referenceCell;
    for (std::size_t i = 0; i < g.size(); ++i) {
        ASSERT_EQ(g.v1[i], 0.0);
        ASSERT_EQ(g.v2[i], 0.0);
        ASSERT_EQ(g.omega[i], 0.0);
        // Positions follow the cell: fractional coordinates are unchanged.
        const auto sNow = toFractional(h, g.x1[i], g.x2[i]);
        const auto sRef =
            toFractional(h0, sim.stateRef().reference1[i], sim.stateRef().reference2[i]);
        EXPECT_NEAR(sNow[0], sRef[0], 1e-12);
        EXPECT_NEAR(sNow[1], sRef[1], 1e-12);
    }
    // Cell lengths: h <- (I + L dt) h each step.
    EXPECT_NEAR(h[0], l1 * std::pow(1.0 - 0.5e-6, 3000), 1e-12 * l1);
    EXPECT_NEAR(h[3], l2 * std::pow(1.0 + 0.3e-6, 3000), 1e-12 * l2);
    EXPECT_LT(h[0], l1);
    EXPECT_GT(h[3], l2);
}

TEST(Stress, LoveWeberOfAStaticConfigurationMatchesHandComputation) {
    // Three disks in a cell with two contacts along known directions (frictionless, static).
    const double d = 1e-3, l1 = 8e-3, l2 = 6e-3;
    const double delta = 2e-6;
    const double c = std::cos(0.3), s = std::sin(0.3);
    const double reach = d - delta;
    SimulationState state = makeScene({{3e-3, 3e-3, 0, 0, 0, 0, d, 1.0},
                                       {3e-3 + reach * c, 3e-3 + reach * s, 0, 0, 0, 0, d, 1.0},
                                       {3e-3 - reach, 3e-3, 0, 0, 0, 0, d, 1.0}},
                                      l1, l2, bareParameters());
    Simulation sim(std::move(state));
    ASSERT_EQ(sim.contactCount(), 2u);
    // Each contact: f = k_n delta along l, |l| = reach: f_i l_j = k_n delta reach n_i n_j.
    const double f = 1e8 * delta * reach;
    const double area = l1 * l2;
    const double s11 = f * (c * c + 1.0) / area;
    const double s22 = f * (s * s) / area;
    const double s12 = f * (c * s) / area;
    EXPECT_NEAR(sim.stress().s11, s11, 1e-9 * s11);
    EXPECT_NEAR(sim.stress().s22, s22, 1e-9 * s11);
    EXPECT_NEAR(sim.stress().s12, s12, 1e-9 * s11);
    EXPECT_GT(sim.stress().s11, 0.0); // compression positive
}

TEST(Servo, SmallDenseAssemblyReachesIsotropicTarget) {
    for (double aspect : {1.0, 0.6}) {
        // The rule asks for both stresses within 0.5 % of the target for 20 checks in a row.
        scenes::CompactedSceneSpec spec = compaction(300, aspect, 21, 5e4, 60000);
        spec.criterion.stressTolerance = 0.005;
        scenes::CompactedScene scene = scenes::compactScene(spec);
        EXPECT_TRUE(scene.equilibrium) << "aspect " << aspect << ": " << scene.steps << " steps";
        const Simulation& sim = scene.simulation;
        const Stress s = sim.stress();
        EXPECT_NEAR(s.s11, 5e4, 0.005 * 5e4) << "aspect " << aspect;
        EXPECT_NEAR(s.s22, 5e4, 0.005 * 5e4) << "aspect " << aspect;
        EXPECT_GT(2.0 * sim.contactCount() / double(sim.grainCount()), 3.0);
    }
}

TEST(Stability, LocalDampingLowersTheEstimateByTheStiffnessItAdds) {
    // In the highest mode the velocity opposes the force at every step, so Cundall's local
    // damping adds alpha |F| along F: a stiffness (1 + alpha) k, a step 1 / sqrt(1 + alpha).
    std::vector<OvalShape> shapes{makeOval(1e-3, 0.6), makeOval(2e-3, 0.6)};
    SimulationParameters viscous, local;
    local.damping = {DampingKind::CundallLocal, 0.7};
    const TimeStepLimit a = criticalTimeStep(shapes, viscous), b = criticalTimeStep(shapes, local);
    EXPECT_EQ(a.dampingFactor, 1.0);
    EXPECT_DOUBLE_EQ(b.dampingFactor, 1.0 / std::sqrt(1.7));
    EXPECT_DOUBLE_EQ(b.translational, a.translational / std::sqrt(1.7));
    EXPECT_DOUBLE_EQ(b.rotational, a.rotational / std::sqrt(1.7));
    EXPECT_DOUBLE_EQ(b.limit, a.limit / std::sqrt(1.7));
    local.timeStep = 0.5 * (a.limit + b.limit); // accepted with viscous damping, not with local
    viscous.timeStep = local.timeStep;
    EXPECT_NO_THROW(checkTimeStep(shapes, viscous));
    try {
        checkTimeStep(shapes, local);
        FAIL() << "accepted with local damping";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("Cundall local damping"), std::string::npos)
            << e.what();
    }
}

TEST(Stability, ReferenceTimeStepIsAcceptedAndUnstableOnesRefused) {
    std::vector<OvalShape> shapes;
    for (double w = 1e-3; w <= 2.0001e-3; w += 1e-4) {
        shapes.push_back(makeOval(w, 0.6));
    }
    SimulationParameters p; // reference: 1e-6 s, k = 1e8 N/m
    const TimeStepLimit lim = criticalTimeStep(shapes, p);
    EXPECT_GT(lim.limit, 1.25e-6);
    EXPECT_LT(lim.limit, 2.5e-6);
    EXPECT_EQ(checkTimeStep(shapes, p), "");
    p.timeStep = 1.1 * lim.limit;
    try {
        checkTimeStep(shapes, p);
        FAIL() << "unstable step accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("stable limit"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(fmt::format("{:.4g}", lim.limit)), std::string::npos)
            << e.what();
    }
    p.timeStep = 0.9 * lim.limit;
    EXPECT_NE(checkTimeStep(shapes, p).find("within 20 %"), std::string::npos);
    p.timeStep = lim.limit; // the limit itself is accepted
    EXPECT_NO_THROW(checkTimeStep(shapes, p));
    // The limit is the estimate times the margin, and the message says so.
    EXPECT_DOUBLE_EQ(lim.limit, kTimeStepMargin * lim.estimate);
    EXPECT_EQ(lim.estimate, std::min(lim.translational, lim.rotational));
    p.timeStep = 1.01 * lim.limit;
    try {
        checkTimeStep(shapes, p);
        FAIL() << "a step above the limit accepted";
    } catch (const std::invalid_argument& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find(fmt::format("estimate {:.4g} s", lim.estimate)), std::string::npos)
            << text;
        EXPECT_NE(text.find(fmt::format("safety margin {:g}", kTimeStepMargin)), std::string::npos)
            << text;
        EXPECT_NE(text.find(fmt::format("{:g} to {:g} times the estimate", kSmallestMeasuredLimit,
                                        kLargestMeasuredLimit)),
                  std::string::npos)
            << text;
    }
    // A Simulation refuses it too.
    SimulationParameters bad;
    bad.timeStep = 1e-5;
    EXPECT_THROW(Simulation(smallAssembly(20, 0.6, 1, bad)), std::invalid_argument);
}

TEST(Stability, ExplodingSceneStopsWithGrainStepAndCause) {
    // Grains pushed together far beyond any physical overlap.
    const double d = 1e-3;
    Simulation sim(
        makeScene({{5e-3, 5e-3, 0, 0, 0, 0, d, 1.0}, {5e-3, 5e-3 + 0.7 * d, 0, 0, 0, 0, d, 1.0}},
                  1e-2, 1e-2, bareParameters()));
    try {
        sim.step();
        FAIL() << "no error";
    } catch (const SimulationError& e) {
        EXPECT_EQ(e.step, 1);
        EXPECT_EQ(e.grain, 0);
        EXPECT_NE(e.cause.find("overlap"), std::string::npos) << e.what();
    }
    // A grain flying through several radii per step: runaway motion.
    Simulation fast(makeScene({{5e-3, 5e-3, 0, 0, 1e3, 0, d, 1.0}}, 1e-2, 1e-2, bareParameters()));
    try {
        fast.step();
        FAIL() << "no error";
    } catch (const SimulationError& e) {
        EXPECT_EQ(e.grain, 0);
        EXPECT_NE(e.cause.find("runaway"), std::string::npos) << e.what();
    }
}

TEST(Stability, CellNarrowerThanTwoGrainsIsRefused) {
    EXPECT_THROW(Simulation(makeScene({{1e-3, 1e-3, 0, 0, 0, 0, 1e-3, 1.0}}, 1.9e-3, 1e-2,
                                      bareParameters())),
                 SimulationError);
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalBits) {
    for (double aspect : {1.0, 0.6}) {
        // Frictional compaction from loose (contacts forming, rebuilds, servo) and then shear.
        scenes::CompactedSceneSpec spec = compaction(600, aspect, 3, 1e5, 15000);
        spec.friction = 0.3;
        spec.threads = 1;
        scenes::CompactedScene a = scenes::compactScene(spec);
        spec.threads = 2;
        scenes::CompactedScene b = scenes::compactScene(spec);
        EXPECT_EQ(a.steps, b.steps) << "aspect " << aspect;
        Simulation& one = a.simulation;
        Simulation& two = b.simulation;
        EXPECT_EQ(one.oneFormKernel(), aspect != 1.0) << "aspect " << aspect;
        EXPECT_TRUE(identicalDynamics(one.state(), two.state())) << "aspect " << aspect;
        for (Simulation* sim : {&one, &two}) {
            sim->setAxisControl(0, {AxisMode::Strain, 1.0, 0});
            sim->setAxisControl(1, {AxisMode::Stress, 0, 1e5});
            sim->advance(2000);
        }
        EXPECT_TRUE(identicalDynamics(one.state(), two.state())) << "aspect " << aspect;
        EXPECT_GT(one.contactCount(), 600u);
    }
}

TEST(Restart, ContinuingFromAStateEqualsTheUninterruptedRun) {
    SimulationState dense = denseAssembly(0.6);
    dense.parameters.friction = 0.5;
    dense.parameters.neighbourSkin = 3e-5; // small: the list is rebuilt during the run
    Simulation a(std::move(dense));
    ASSERT_TRUE(a.oneFormKernel()); // the restart must choose the same kernel
    a.setAxisControl(0, {AxisMode::Strain, 1.0, 0});
    a.setAxisControl(1, {AxisMode::Stress, 0, 1e5});
    a.advance(3000);
    const SimulationState middle = a.state();
    a.advance(3000);
    Simulation b(middle);
    b.advance(3000);
    EXPECT_TRUE(identicalDynamics(a.state(), b.state()));
    EXPECT_GT(a.neighbourRebuilds(), 1);
    EXPECT_GT(a.contactCount(), 300u);
}

/// Shears both simulations alike (axis 1 at 1 /s, axis 2 at 100 kPa) for `steps` steps.
void shearBoth(Simulation& a, Simulation& b, std::int64_t steps) {
    for (Simulation* sim : {&a, &b}) {
        sim->setAxisControl(0, {AxisMode::Strain, 1.0, 0});
        sim->setAxisControl(1, {AxisMode::Stress, 0, 1e5});
        sim->advance(steps);
    }
}

/// The largest difference of a grain's centre between two runs of the same grains [m].
double largestPositionGap(const Simulation& one, const Simulation& two) {
    const auto& a = one.stateRef().grains;
    const auto& b = two.stateRef().grains;
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        worst = std::max({worst, std::fabs(a.x1[i] - b.x1[i]), std::fabs(a.x2[i] - b.x2[i])});
    }
    return worst;
}

TEST(FastPaths, DiskThroughOvalPathEqualsDiskPath) {
    SimulationState start = denseAssembly(1.0);
    start.parameters.friction = 0.5;
    SimulationState viaOval = start;
    viaOval.parameters.ovalPathForDisks = true;
    Simulation disk(std::move(start)), oval(std::move(viaOval));
    shearBoth(disk, oval, 2000);
    EXPECT_LT(largestPositionGap(disk, oval), 1e-15); // round-off on millimetre positions
    EXPECT_NEAR(disk.stress().s11, oval.stress().s11, 1e-9 * disk.stress().s11);
    EXPECT_EQ(disk.contactCount(), oval.contactCount());
    EXPECT_GT(disk.contactCount(), 300u);
}

// Ovals of one form at several widths run through the one-form kernel (each grain's arcs its
// half-width times the form's unit arcs); the per-grain tables of the shapes' own arcs differ
// from those products by round-off, so both runs must agree to round-off grown by the dynamics.
TEST(FastPaths, OneFormKernelEqualsPerGrainTables) {
    SimulationState start = denseAssembly(0.6);
    start.parameters.friction = 0.5;
    std::set<double> widths;
    for (const OvalShape& shape : start.shapes) {
        widths.insert(shape.width);
    }
    ASSERT_GT(widths.size(), 5u) << "the scene must have several widths of the one form";
    SimulationState viaTables = start;
    viaTables.parameters.perGrainArcs = true;
    Simulation form(std::move(start)), tables(std::move(viaTables));
    EXPECT_TRUE(form.oneFormKernel());
    EXPECT_FALSE(tables.oneFormKernel());
    shearBoth(form, tables, 2000);
    EXPECT_LT(largestPositionGap(form, tables), 1e-15); // round-off on millimetre positions
    const auto& a = form.stateRef().grains;
    const auto& b = tables.stateRef().grains;
    double worstAngle = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        worstAngle = std::max(worstAngle, std::fabs(a.theta[i] - b.theta[i]));
    }
    EXPECT_LT(worstAngle, 1e-11);
    EXPECT_NEAR(form.stress().s11, tables.stress().s11, 1e-9 * form.stress().s11);
    EXPECT_EQ(form.contactCount(), tables.contactCount());
    EXPECT_GT(form.contactCount(), 300u);
}

TEST(FastPaths, OvalsOfTwoFormsUseThePerGrainTables) {
    // Two grains, 1 and 1.5 mm wide, of aspect ratios `first` and `second` (1: a disk).
    const auto pairOf = [](double first, double second) {
        return Simulation(makeScene(
            {{1e-3, 1e-3, 0, 0, 0, 0, 1e-3, first}, {3e-3, 3e-3, 0, 0, 0, 0, 1.5e-3, second}}, 5e-3,
            5e-3, bareParameters()));
    };
    EXPECT_TRUE(pairOf(0.6, 0.6).oneFormKernel());
    EXPECT_FALSE(pairOf(0.6, 0.5).oneFormKernel());
    EXPECT_FALSE(pairOf(0.6, 1.0).oneFormKernel());
    EXPECT_FALSE(pairOf(1.0, 1.0).oneFormKernel()); // the disk kernel
}

TEST(NeighbourList, NeverMissesAContactUnderDeformation) {
    // All-pairs brute force (every image) against the engine's contacts, during compaction and
    // shear of small oval assemblies.
    SimulationState dense = denseAssembly(0.6);
    dense.parameters.friction = 0.3;
    Simulation sim(std::move(dense));
    sim.setAxisControl(0, {AxisMode::Strain, 2.0, 0});
    sim.setAxisControl(1, {AxisMode::Stress, 0, 1e5});
    int checks = 0;
    for (int round = 0; round < 20; ++round) {
        sim.advance(500);
        const ContactNetwork net = sim.contactNetwork();
        const auto& st = sim.stateRef();
        const auto& h = st.cell;
        std::set<std::tuple<int, int, int, int>> expected, found;
        for (int i = 0; i < net.grainCount; ++i) {
            for (int j = i + 1; j < net.grainCount; ++j) {
                for (int k1 = -1; k1 <= 1; ++k1) {
                    for (int k2 = -1; k2 <= 1; ++k2) {
                        const double l1 = net.x1[j] + h[0] * k1 + h[2] * k2 - net.x1[i];
                        const double l2 = net.x2[j] + h[1] * k1 + h[3] * k2 - net.x2[i];
                        const auto& A = st.shapes[st.grains.shape[i]];
                        const auto& B = st.shapes[st.grains.shape[j]];
                        const ContactGeometry c = ovalContactAllPairs(A, st.grains.theta[i], B,
                                                                      st.grains.theta[j], l1, l2);
                        if (c.overlap > 0) {
                            expected.insert({i, j, k1, k2});
                        }
                    }
                }
            }
        }
        for (const auto& c : net.contacts) {
            found.insert({c.first, c.second, c.shift1, c.shift2});
        }
        EXPECT_EQ(found, expected) << "round " << round;
        checks += static_cast<int>(expected.size());
    }
    EXPECT_GT(checks, 2000);
    EXPECT_GT(sim.neighbourRebuilds(), 1);
}

TEST(Energy, BoundaryWorkBalancesStoredAndDissipatedEnergy) {
    SimulationState dense = denseAssembly(0.6);
    dense.parameters.friction = 0.5;
    Simulation sim(std::move(dense));
    const Energies e0 = sim.energies();
    sim.setAxisControl(0, {AxisMode::Strain, 1.0, 0});
    sim.setAxisControl(1, {AxisMode::Stress, 0, 1e5});
    sim.advance(10000);
    const Energies e = sim.energies();
    const double input = e.boundaryWork - e0.boundaryWork;
    const double accounted = (e.kinetic - e0.kinetic) + (e.elastic - e0.elastic) +
                             (e.frictionWork - e0.frictionWork) + (e.dampingWork - e0.dampingWork);
    ASSERT_GT(input, 0.0);
    EXPECT_NEAR(accounted, input, 0.02 * input);
    EXPECT_GT(e.frictionWork - e0.frictionWork, 0.0);
}

} // namespace
} // namespace grainlab
