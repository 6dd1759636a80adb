// Tests of the micro-structure measures (docs/measures.md): closed forms on hand-built contact
// networks, and the unbalanced-force index on a packing compacted by the engine.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/assembly.h"
#include "grainlab/measures.h"
#include "grainlab/simulation.h"
#include "grainlab/snapshot.h"
#include "networks.h"
#include "scenes.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// An empty network of n grains of area `area` in a rectangular cell L1 x L2.
ContactNetwork emptyNetwork(int n, double L1, double L2, double area = 1e-6) {
    return test::emptyNetwork(n, {L1, 0.0, 0.0, L2}, area);
}

/// A contact between grains a and b (image shift 0) with a normal at `angle` and given forces;
/// the geometry is only consistent enough for the measures that read normals and forces.
void addContact(ContactNetwork& net, int a, int b, double angle, double fn, double ft = 0,
                bool sliding = false) {
    ContactRecord r;
    r.first = a;
    r.second = b;
    r.normal1 = std::cos(angle);
    r.normal2 = std::sin(angle);
    r.branch1 = 1e-3 * r.normal1;
    r.branch2 = 1e-3 * r.normal2;
    r.point1 = 0.5 * r.branch1;
    r.point2 = 0.5 * r.branch2;
    r.normalForce = fn;
    r.tangentialForce = ft;
    r.sliding = sliding;
    net.contacts.push_back(r);
}

TEST(Measures, FabricOfKnownNormals) {
    ContactNetwork net = emptyNetwork(4, 1, 1);
    addContact(net, 0, 1, 0.0, 1);
    addContact(net, 1, 2, 0.5 * kPi, 1);
    addContact(net, 2, 3, 0.25 * kPi, 1);
    const FabricTensor f = fabricTensor(net);
    EXPECT_EQ(f.contacts, 3);
    EXPECT_NEAR(f.h11, 0.5, 1e-15);
    EXPECT_NEAR(f.h22, 0.5, 1e-15);
    EXPECT_NEAR(f.h12, 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(f.deviator, 0.0, 1e-15);
    EXPECT_NEAR(f.ratio, 0.0, 1e-15);

    // Normals at +-30 degrees from x1: H11 = cos^2 30 = 3/4, H12 cancels.
    ContactNetwork axial = emptyNetwork(3, 1, 1);
    addContact(axial, 0, 1, kPi / 6, 1);
    addContact(axial, 1, 2, -kPi / 6, 1);
    const FabricTensor g = fabricTensor(axial);
    EXPECT_NEAR(g.h11, 0.75, 1e-15);
    EXPECT_NEAR(g.h22, 0.25, 1e-15);
    EXPECT_NEAR(g.h12, 0.0, 1e-15);
    EXPECT_NEAR(g.deviator, 0.5, 1e-15);
    EXPECT_NEAR(g.ratio, 0.5, 1e-15);
    // The sign of a normal does not matter (n (x) n).
    addContact(axial, 2, 0, kPi + kPi / 6, 1);
    addContact(axial, 0, 2, -kPi / 6 + kPi, 1);
    EXPECT_NEAR(fabricTensor(axial).h11, 0.75, 1e-15);
}

TEST(Measures, StrongAndWeakSplitOnKnownForces) {
    // |f| = 1, 1, sqrt(5), 2.5: f_a = sqrt((1 + 1 + 5 + 6.25) / 4) = 1.820: two strong.
    // Mean normal force (1 + 1 + 1 + 2.5) / 4 = 1.375: one strong.
    ContactNetwork net = emptyNetwork(5, 1, 1);
    addContact(net, 0, 1, 0.0, 1.0);            // weak in both
    addContact(net, 1, 2, 0.5 * kPi, 1.0);      // weak in both
    addContact(net, 2, 3, 0.5 * kPi, 1.0, 2.0); // strong by |f| only
    addContact(net, 3, 4, 0.0, 2.5);            // strong in both
    const StrongWeakFabric rms = strongWeakFabric(net, StrongForceThreshold::RmsForce);
    EXPECT_NEAR(rms.threshold, std::sqrt(13.25 / 4.0), 1e-14);
    EXPECT_EQ(rms.strong.contacts, 2);
    EXPECT_EQ(rms.weak.contacts, 2);
    EXPECT_NEAR(rms.strong.h11, 0.5, 1e-15);
    EXPECT_NEAR(rms.strong.h22, 0.5, 1e-15);
    EXPECT_NEAR(rms.weak.h11, 0.5, 1e-15);

    const StrongWeakFabric mean = strongWeakFabric(net, StrongForceThreshold::MeanNormalForce);
    EXPECT_NEAR(mean.threshold, 1.375, 1e-15);
    EXPECT_EQ(mean.strong.contacts, 1);
    EXPECT_EQ(mean.weak.contacts, 3);
    EXPECT_NEAR(mean.strong.h11, 1.0, 1e-15);
    EXPECT_NEAR(mean.strong.ratio, 1.0, 1e-15);
    EXPECT_NEAR(mean.weak.h11, 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(mean.weak.h22, 2.0 / 3.0, 1e-15);

    MeasureOptions options;
    options.strongThreshold = StrongForceThreshold::MeanNormalForce;
    EXPECT_EQ(computeMeasures(net, options).strongWeak.strong.contacts, 1);
    EXPECT_EQ(computeMeasures(net).strongWeak.strong.contacts, 2);
}

/// Ring of 12 grains (0..11), a chain 12-13 hanging from grain 0, an isolated pair 14-15 and a
/// rattler 16.
ContactNetwork ringWithChain() {
    ContactNetwork net = emptyNetwork(17, 1, 1);
    for (int i = 0; i < 12; ++i) {
        addContact(net, i, (i + 1) % 12, 2 * kPi * (i + 3) / 12, 1.0);
    }
    addContact(net, 0, 12, 0.0, 1.0);
    addContact(net, 12, 13, 0.0, 1.0);
    addContact(net, 14, 15, 0.0, 1.0);
    return net;
}

TEST(Measures, CoordinationNumbersWhereTheyDiffer) {
    const ContactNetwork net = ringWithChain();
    const CoordinationCounts c = coordinationCounts(net);
    EXPECT_EQ(c.grains, 17);
    EXPECT_EQ(c.contacts, 15);
    EXPECT_EQ(c.rattlers, 1);
    EXPECT_EQ(c.singleContact, 3);
    EXPECT_NEAR(c.coordination, 30.0 / 17.0, 1e-15);
    EXPECT_NEAR(c.mechanicalCoordination, 27.0 / 13.0, 1e-15);

    const LoadBearingGraph g = loadBearingGraph(net);
    EXPECT_EQ(g.grains, 12);
    EXPECT_EQ(g.contacts, 12);
    EXPECT_NEAR(g.coordination, 2.0, 1e-15);
    for (int i = 0; i < 17; ++i) {
        EXPECT_EQ(g.grainInGraph[i], i < 12 ? 1 : 0) << "grain " << i;
    }
    for (std::size_t k = 0; k < net.contacts.size(); ++k) {
        EXPECT_EQ(g.contactInGraph[k], k < 12 ? 1 : 0) << "contact " << k;
    }
}

TEST(Measures, PruningCascadesThroughLongChains) {
    // A triangle 0-1-2 with a 20-grain chain hanging from it: pruning must walk the whole chain
    // back to the triangle, whatever the order of the contacts.
    ContactNetwork net = emptyNetwork(23, 1, 1);
    for (int i = 22; i > 3; --i) {
        addContact(net, i - 1, i, 0.0, 1.0);
    }
    addContact(net, 2, 3, 0.0, 1.0);
    addContact(net, 0, 1, 0.0, 1.0);
    addContact(net, 1, 2, 0.0, 1.0);
    addContact(net, 2, 0, 0.0, 1.0);
    const LoadBearingGraph g = loadBearingGraph(net);
    EXPECT_EQ(g.grains, 3);
    EXPECT_EQ(g.contacts, 3);
    // A tree has no load-bearing graph at all.
    ContactNetwork tree = emptyNetwork(4, 1, 1);
    addContact(tree, 0, 1, 0.0, 1.0);
    addContact(tree, 0, 2, 0.0, 1.0);
    addContact(tree, 0, 3, 0.0, 1.0);
    EXPECT_EQ(loadBearingGraph(tree).grains, 0);
    EXPECT_EQ(loadBearingGraph(tree).coordination, 0.0);
    EXPECT_EQ(coordinationCounts(tree).mechanicalCoordination, 2.0 * 3 - 3);
}

TEST(Measures, SlidingUnbalancedForceAndVoidRatio) {
    ContactNetwork net = emptyNetwork(4, 0.02, 0.05, 2.0e-4); // cell 1e-3, grains 8e-4
    addContact(net, 0, 1, 0.0, 3.0, 4.0, true);               // |f| = 5
    addContact(net, 1, 2, 0.0, 5.0, 0.0, false);              // |f| = 5
    net.netForce1[3] = 3.0;
    net.netForce2[3] = 4.0;
    EXPECT_EQ(slidingContactCount(net), 1);
    // sqrt(25 / 4) / sqrt(50 / 2) = 0.5.
    EXPECT_NEAR(unbalancedForceIndex(net), 50.0, 1e-12);
    EXPECT_NEAR(voidRatio(net), 0.25, 1e-12);
    EXPECT_NEAR(meanEquivalentDiameter(net), std::sqrt(4 * 2.0e-4 / kPi), 1e-15);
    const MeasureSet m = computeMeasures(net);
    EXPECT_EQ(m.slidingContacts, 1);
    EXPECT_NEAR(m.slidingIndex, 0.5, 1e-15);
    EXPECT_NEAR(m.unbalancedForce, 50.0, 1e-12);
    // No contacts: every ratio is 0, nothing divides by zero (FP exceptions are on).
    const MeasureSet empty = computeMeasures(emptyNetwork(3, 1, 1));
    EXPECT_EQ(empty.unbalancedForce, 0.0);
    EXPECT_EQ(empty.counts.mechanicalCoordination, 0.0);
    EXPECT_EQ(empty.fabric.ratio, 0.0);
    EXPECT_EQ(empty.voidCells.voidCount, 0);
    EXPECT_FALSE(empty.voidCells.cellular);
    const MeasureSet none = computeMeasures(ContactNetwork{});
    EXPECT_EQ(none.counts.coordination, 0.0);
    EXPECT_EQ(none.voidRatio, 0.0);
}

TEST(Measures, BadContactIndexIsRefused) {
    ContactNetwork net = emptyNetwork(2, 1, 1);
    addContact(net, 0, 2, 0.0, 1.0);
    EXPECT_THROW(computeMeasures(net), std::invalid_argument);
}

TEST(Measures, StressInvariantsAndInertialNumber) {
    const StressMeasures s = stressMeasures(Stress{300e3, 100e3, 5e3});
    EXPECT_NEAR(s.p, 200e3, 1e-9);
    EXPECT_NEAR(s.q, 100e3, 1e-9);
    EXPECT_NEAR(s.qOverP, 0.5, 1e-15);
    EXPECT_NEAR(s.phiDeg, 30.0, 1e-12);
    // Lateral stress above axial: q < 0, phi < 0.
    EXPECT_NEAR(stressMeasures(Stress{100e3, 300e3, 0}).phiDeg, -30.0, 1e-12);
    // Tension or no stress: no NaN.
    EXPECT_EQ(stressMeasures(Stress{0, 0, 0}).qOverP, 0.0);
    EXPECT_EQ(stressMeasures(Stress{-1, -3, 0}).phiDeg, 0.0);
    EXPECT_NEAR(stressMeasures(Stress{10, -1, 0}).phiDeg, 90.0, 1e-12); // |q/p| > 1 clamped
    // I = |0.2| * 1e-3 * sqrt(2650 / 1e5): the axial rate alone, either sign.
    EXPECT_NEAR(inertialNumber(0.2, 1e-3, 2650, 1e5), 0.2e-3 * std::sqrt(0.0265), 1e-15);
    EXPECT_NEAR(inertialNumber(-0.2, 1e-3, 2650, 1e5), 0.2e-3 * std::sqrt(0.0265), 1e-15);
    EXPECT_EQ(inertialNumber(0.2, 1e-3, 2650, 0), 0.0);
}

TEST(Measures, SeriesColumnsFollowTheSpec) {
    const std::vector<std::string> expected = {"step",     "time",        "stage",
                                               "eps1",     "eps2",        "epsv",
                                               "DI",       "sigma11",     "sigma22",
                                               "sigma12",  "p",           "q",
                                               "q_over_p", "phi_deg",     "e",
                                               "Np",       "Nc",          "Z",
                                               "Np_eff",   "Nc_eff",      "Z_eff",
                                               "Z_m",      "N_slip",      "S",
                                               "Nv",       "Nv_over_Nvi", "valence_mean",
                                               "H11",      "H22",         "H12",
                                               "Hdev",     "Hratio",      "Hs11",
                                               "Hs22",     "Hs12",        "Hsdev",
                                               "Hsratio",  "Hw11",        "Hw22",
                                               "Hw12",     "Hwdev",       "Hwratio",
                                               "N_strong", "I_uf",        "inertial_number",
                                               "E_kin",    "E_elastic",   "W_friction",
                                               "W_damping"};
    const auto& columns = seriesColumns();
    ASSERT_EQ(columns.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(columns[k].name, expected[k]);
        EXPECT_EQ(columns[k].text, expected[k] == "stage");
        EXPECT_FALSE(columns[k].unit.empty());
    }
    EXPECT_EQ(seriesHeader(columns[8]), "sigma22 [Pa]");
    EXPECT_EQ(seriesHeader(columns[12]), "q_over_p [-]");
    EXPECT_EQ(seriesHeader(columns[1]), "time [s]");
    EXPECT_EQ(seriesHeader(columns[2]), "stage");
    EXPECT_EQ(seriesHeader(columns[43]), "I_uf [%]");
    EXPECT_EQ(seriesHeader(columns[48]), "W_damping [J]");
}

TEST(Measures, FiguresLabelColumnsAsAPaperWould) {
    // Strains in percent, stresses in kPa, ratios bare; the factor turns stored into drawn values.
    EXPECT_EQ(axisLabelOf("eps1").text, "ε1 [%]");
    EXPECT_EQ(axisLabelOf("eps1").scale, 100.0);
    EXPECT_EQ(axisLabelOf("epsv").text, "εv [%]");
    EXPECT_EQ(axisLabelOf("epsv").scale, 100.0);
    EXPECT_EQ(axisLabelOf("q").text, "q [kPa]");
    EXPECT_EQ(axisLabelOf("q").scale, 1e-3);
    EXPECT_EQ(axisLabelOf("q_over_p").text, "q/p");
    EXPECT_EQ(axisLabelOf("Z_eff").text, "Z̄");
    EXPECT_EQ(axisLabelOf("I_uf").text, "I_uf [%]"); // already stored in percent
    EXPECT_EQ(axisLabelOf("I_uf").scale, 1.0);
    EXPECT_EQ(axisLabelOf("E_kin").text, "E_kin [J]");
    EXPECT_EQ(axisLabelOf("not_a_column").text, "not_a_column");
    // No label of a numeric column keeps the CSV's "[-]" or an underscore-joined ratio name.
    for (const SeriesColumn& c : seriesColumns()) {
        if (c.text) {
            continue;
        }
        const AxisLabel label = axisLabelOf(c.name);
        EXPECT_EQ(label.text.find("[-]"), std::string::npos) << c.name;
        EXPECT_EQ(label.text.find("_over_"), std::string::npos) << c.name;
        EXPECT_GT(label.scale, 0.0) << c.name;
    }
}

TEST(Measures, SeriesRowPutsEachValueUnderItsColumn) {
    MeasureSet m;
    m.counts.grains = 100;
    m.counts.contacts = 150;
    m.counts.coordination = 3.0;
    m.counts.mechanicalCoordination = 3.5;
    m.loadBearing.grains = 90;
    m.loadBearing.contacts = 149;
    m.loadBearing.coordination = 3.31;
    m.slidingContacts = 7;
    m.slidingIndex = 0.14;
    m.fabric = {0.6, 0.4, 0.01, 0.2, 0.2, 150};
    m.strongWeak.strong = {0.7, 0.3, 0.02, 0.4, 0.4, 40};
    m.strongWeak.weak = {0.55, 0.45, 0.03, 0.1, 0.1, 110};
    m.unbalancedForce = 0.42;
    m.voidRatio = 0.21;
    m.meanDiameter = 1.5e-3;
    m.voidCells.voidCount = 59;
    m.voidCells.meanValence = 5.05;
    RecordInputs in;
    in.step = 123456;
    in.time = 0.123456;
    in.eps1 = 0.01;
    in.eps2 = -0.004;
    in.epsv = 0.006;
    in.dilatancyIndex = -0.3;
    in.stress = {150e3, 50e3, 2e3};
    in.initialVoidCount = 118;
    in.strainRate1 = 0.2;
    in.strainRate2 = -0.1;
    in.density = 2650;
    in.energies = {1.0, 2.0, 3.0, 4.0, 5.0};
    const std::vector<double> row = seriesRow(m, in);
    const auto& columns = seriesColumns();
    ASSERT_EQ(row.size(), columns.size() - 1);
    auto value = [&](const std::string& name) {
        std::size_t k = 0;
        for (const SeriesColumn& c : columns) {
            if (c.name == name) {
                return row.at(k);
            }
            k += c.text ? 0 : 1;
        }
        ADD_FAILURE() << "no column " << name;
        return 0.0;
    };
    EXPECT_EQ(value("step"), 123456.0);
    EXPECT_EQ(value("time"), 0.123456);
    EXPECT_EQ(value("eps1"), 0.01);
    EXPECT_EQ(value("eps2"), -0.004);
    EXPECT_EQ(value("epsv"), 0.006);
    EXPECT_EQ(value("DI"), -0.3);
    EXPECT_EQ(value("sigma11"), 150e3);
    EXPECT_EQ(value("sigma22"), 50e3);
    EXPECT_EQ(value("sigma12"), 2e3);
    EXPECT_EQ(value("p"), 100e3);
    EXPECT_EQ(value("q"), 50e3);
    EXPECT_EQ(value("q_over_p"), 0.5);
    EXPECT_NEAR(value("phi_deg"), 30.0, 1e-12);
    EXPECT_EQ(value("e"), 0.21);
    EXPECT_EQ(value("Np"), 100);
    EXPECT_EQ(value("Nc"), 150);
    EXPECT_EQ(value("Z"), 3.0);
    EXPECT_EQ(value("Np_eff"), 90);
    EXPECT_EQ(value("Nc_eff"), 149);
    EXPECT_EQ(value("Z_eff"), 3.31);
    EXPECT_EQ(value("Z_m"), 3.5);
    EXPECT_EQ(value("N_slip"), 7);
    EXPECT_EQ(value("S"), 0.14);
    EXPECT_EQ(value("Nv"), 59);
    EXPECT_EQ(value("Nv_over_Nvi"), 0.5);
    EXPECT_EQ(value("valence_mean"), 5.05);
    EXPECT_EQ(value("H11"), 0.6);
    EXPECT_EQ(value("H22"), 0.4);
    EXPECT_EQ(value("H12"), 0.01);
    EXPECT_EQ(value("Hdev"), 0.2);
    EXPECT_EQ(value("Hratio"), 0.2);
    EXPECT_EQ(value("Hs11"), 0.7);
    EXPECT_EQ(value("Hs12"), 0.02);
    EXPECT_EQ(value("Hsratio"), 0.4);
    EXPECT_EQ(value("Hw22"), 0.45);
    EXPECT_EQ(value("Hwdev"), 0.1);
    EXPECT_EQ(value("N_strong"), 40);
    EXPECT_EQ(value("I_uf"), 0.42);
    // The axial rate 0.2 /s only: the lateral -0.1 /s is not part of I.
    EXPECT_NEAR(value("inertial_number"), 0.2 * 1.5e-3 * std::sqrt(2650 / 100e3), 1e-15);
    EXPECT_EQ(value("E_kin"), 1.0);
    EXPECT_EQ(value("E_elastic"), 2.0);
    EXPECT_EQ(value("W_friction"), 4.0);
    EXPECT_EQ(value("W_damping"), 5.0);
    // N_vi unknown: the ratio is 0, not a division by zero.
    in.initialVoidCount = 0;
    EXPECT_EQ(seriesRow(m, in).at(24), 0.0);
}

TEST(Measures, HexagonalLatticeClosedForms) {
    const double d = 1e-3;
    const ContactNetwork net = test::hexagonalNetwork(8, 6, d);
    const MeasureSet m = computeMeasures(net);
    EXPECT_EQ(m.counts.contacts, 3 * 48);
    EXPECT_NEAR(m.counts.coordination, 6.0, 1e-15);
    EXPECT_NEAR(m.counts.mechanicalCoordination, 6.0, 1e-15);
    EXPECT_NEAR(m.loadBearing.coordination, 6.0, 1e-15);
    EXPECT_NEAR(m.fabric.h11, 0.5, 1e-14);
    EXPECT_NEAR(m.fabric.h22, 0.5, 1e-14);
    EXPECT_NEAR(m.fabric.h12, 0.0, 1e-14);
    EXPECT_EQ(m.voidCells.voidCount, 96);
    EXPECT_NEAR(m.voidCells.meanValence, 3.0, 1e-15);
    EXPECT_NEAR(m.voidRatio, 2 * std::sqrt(3.0) / kPi - 1, 1e-12);
    // Equal forces: the rms threshold equals every force, so no contact is strong.
    EXPECT_EQ(m.strongWeak.strong.contacts, 0);
    EXPECT_EQ(m.strongWeak.weak.contacts, 144);
}

TEST(Measures, AllMeasuresAtTheReferenceSize) {
    // The reference experiment's size: 130 x 65 hexagonal lattice, 25350 contacts. (How long
    // this takes is reported by `grainlab bench`, not tested.)
    ContactNetwork net = test::hexagonalNetwork(65, 130, 1e-3);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> uniform(0.5, 1.5);
    for (ContactRecord& r : net.contacts) {
        r.normalForce = uniform(random);
    }
    const MeasureSet m = computeMeasures(net);
    EXPECT_EQ(m.voidCells.voidCount, 2 * 8450);
    EXPECT_TRUE(m.voidCells.cellular) << m.voidCells.problem;
    EXPECT_NEAR(m.counts.coordination, 6.0, 1e-12);
}

TEST(MeasuresPacking, UnbalancedForceSmallAtEquilibriumLargeWhenPerturbed) {
    // A dense, frictionless oval packing compacted by the engine to 100 kPa.
    Simulation simulation = test::compactedPacking(300, 0.6, 11, 60000);
    // Settle until the unbalanced force is small, within a bounded number of steps.
    for (int k = 0; k < 40 && computeMeasures(simulation.contactNetwork()).unbalancedForce >= 0.5;
         ++k) {
        simulation.advance(2000);
    }
    const Stress s = simulation.stress();
    ASSERT_NEAR(s.s11, 1e5, 2e3);
    ASSERT_NEAR(s.s22, 1e5, 2e3);
    const MeasureSet m = computeMeasures(simulation.contactNetwork());
    EXPECT_LT(m.unbalancedForce, 1.0);
    EXPECT_GT(m.counts.coordination, 4.0);
    // Isotropic compaction: a nearly isotropic fabric.
    EXPECT_NEAR(m.fabric.h11 + m.fabric.h22, 1.0, 1e-12);
    EXPECT_LT(std::fabs(m.fabric.ratio), 0.1);
    EXPECT_GT(m.strongWeak.strong.contacts, 0);
    EXPECT_EQ(m.strongWeak.strong.contacts + m.strongWeak.weak.contacts, m.counts.contacts);
    EXPECT_LE(m.loadBearing.grains, m.counts.grains);
    EXPECT_GE(m.loadBearing.coordination, m.counts.coordination);

    // Random velocity kicks of ~5 cm/s, then 20 steps: the grains are far from equilibrium
    // (I_uf ~ 36 % here against ~0.3 % before).
    SimulationState state = simulation.state();
    std::mt19937_64 random(5);
    std::normal_distribution<double> kick(0.0, 0.05);
    for (std::size_t i = 0; i < state.grains.size(); ++i) {
        state.grains.v1[i] += kick(random);
        state.grains.v2[i] += kick(random);
    }
    Simulation perturbed(state);
    perturbed.advance(20);
    EXPECT_GT(computeMeasures(perturbed.contactNetwork()).unbalancedForce, 10.0);

    // Displacing grains also unbalances them, with no time stepping at all.
    SimulationState displaced = simulation.state();
    for (std::size_t i = 0; i < displaced.grains.size(); i += 3) {
        displaced.grains.x1[i] += 2e-6;
    }
    Simulation moved(displaced);
    EXPECT_GT(computeMeasures(moved.contactNetwork()).unbalancedForce, 10.0);
}

TEST(MeasuresPacking, ASnapshotMeasuredLaterEqualsOneMeasuredAtOnce) {
    // The live window copies the configuration on the engine's thread and measures elsewhere.
    const Simulation simulation = test::compactedPacking(200, 0.6, 3, 30000);
    Snapshot now, later;
    fillSnapshotScene(now, simulation);
    fillSnapshotScene(later, simulation, {}, SnapshotMeasures::Later);
    EXPECT_TRUE(now.measured);
    EXPECT_FALSE(later.measured);
    EXPECT_TRUE(later.voidCells.empty());
    EXPECT_TRUE(later.loadBearing.empty());
    EXPECT_EQ(later.x1, now.x1);
    EXPECT_EQ(later.network.contacts.size(), now.network.contacts.size());
    addSnapshotMeasures(later);
    EXPECT_TRUE(later.measured);
    EXPECT_EQ(later.loadBearing, now.loadBearing);
    ASSERT_EQ(later.voidCells.size(), now.voidCells.size());
    ASSERT_GT(now.voidCells.size(), 50u);
    for (std::size_t v = 0; v < now.voidCells.size(); ++v) {
        EXPECT_EQ(later.voidCells[v].grains, now.voidCells[v].grains);
        EXPECT_EQ(later.voidCells[v].x1, now.voidCells[v].x1);
        EXPECT_EQ(later.voidCells[v].area, now.voidCells[v].area);
    }
    // Measuring twice changes nothing.
    const std::size_t cells = later.voidCells.size();
    addSnapshotMeasures(later);
    EXPECT_EQ(later.voidCells.size(), cells);
}

} // namespace
} // namespace grainlab
