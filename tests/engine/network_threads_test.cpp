// The contact network and the unbalanced force index as the runner's records and equilibrium
// checks take them: the network's records are made on the engine's threads (the same bits on
// any thread count), and Simulation::unbalancedForceIndex() (no contact geometry) gives the
// same bits as the index of the full network.
#include <cstring>

#include <gtest/gtest.h>

#include "grainlab/measures.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

/// 300 grains compacted to 100 kPa, then sheared with friction for a while, so that contacts
/// carry tangential forces and some slide.
SimulationState shearedState(double aspect, int threads) {
    scenes::CompactedSceneSpec spec;
    spec.grains = 300;
    spec.aspectRatio = aspect;
    spec.criterion.maxSteps = 100000;
    SimulationState s = scenes::compactedState(spec);
    s.parameters.friction = 0.5;
    s.parameters.threads = threads;
    Simulation sim(std::move(s));
    sim.setAxisControl(0, AxisControl{AxisMode::Strain, 0.5, sim.cell()[0]});
    sim.setAxisControl(1, AxisControl{AxisMode::Stress, 0.0, 1e5});
    sim.advance(3000);
    return sim.state();
}

bool sameBits(const ContactRecord& a, const ContactRecord& b) {
    const auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    return a.first == b.first && a.second == b.second && a.shift1 == b.shift1 &&
           a.shift2 == b.shift2 && same(a.branch1, b.branch1) && same(a.branch2, b.branch2) &&
           same(a.normal1, b.normal1) && same(a.normal2, b.normal2) && same(a.point1, b.point1) &&
           same(a.point2, b.point2) && same(a.overlap, b.overlap) &&
           same(a.normalForce, b.normalForce) && same(a.tangentialForce, b.tangentialForce) &&
           a.sliding == b.sliding;
}

class NetworkThreads : public ::testing::TestWithParam<double> {};

TEST_P(NetworkThreads, TheNetworkIsTheSameBitsOnOneAndTwoThreads) {
    SimulationState state = shearedState(GetParam(), 1);
    const Simulation one(state);
    state.parameters.threads = 2;
    const Simulation two(std::move(state));
    const ContactNetwork a = one.contactNetwork(), b = two.contactNetwork();
    ASSERT_GT(a.contacts.size(), 300u);
    ASSERT_EQ(a.contacts.size(), b.contacts.size());
    for (std::size_t c = 0; c < a.contacts.size(); ++c) {
        ASSERT_TRUE(sameBits(a.contacts[c], b.contacts[c])) << "contact " << c;
    }
    EXPECT_EQ(a.netForce1, b.netForce1);
    EXPECT_EQ(a.netForce2, b.netForce2);
    // In pair order: sorted by first grain, as the pairs are.
    for (std::size_t c = 1; c < a.contacts.size(); ++c) {
        ASSERT_LE(a.contacts[c - 1].first, a.contacts[c].first);
    }
}

TEST_P(NetworkThreads, TheIndexWithoutGeometryIsTheNetworksIndex) {
    const Simulation sim(shearedState(GetParam(), 2));
    const ContactNetwork network = sim.contactNetwork();
    double tangential = 0;
    for (const ContactRecord& r : network.contacts) {
        tangential += std::abs(r.tangentialForce);
    }
    ASSERT_GT(tangential, 0.0) << "the sheared state should carry tangential forces";
    const double fromNetwork = unbalancedForceIndex(network);
    EXPECT_GT(fromNetwork, 0.0);
    EXPECT_EQ(sim.unbalancedForceIndex(), fromNetwork); // the same bits
}

INSTANTIATE_TEST_SUITE_P(Shapes, NetworkThreads, ::testing::Values(1.0, 0.6),
                         [](const auto& info) { return info.param < 1.0 ? "ovals" : "disks"; });

} // namespace
} // namespace grainlab
