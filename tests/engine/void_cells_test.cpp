// Tests of the void cells (docs/measures.md): faces of the load-bearing graph on the torus. Closed
// forms on hand-built lattices, rings and chains; the two invariants (Euler on the torus, areas
// adding up to the cell) on dense packings compacted by the engine.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/assembly.h"
#include "grainlab/measures.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/simulation.h"
#include "grainlab/void_cells.h"
#include "networks.h"
#include "scenes.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

using test::emptyNetwork;
using test::hexagonalNetwork;

/// A contact between grain a and the image (shift k) of grain b, contact point at mid-branch.
void addContact(ContactNetwork& net, int a, int b, int k1 = 0, int k2 = 0) {
    test::addBranchContact(net, a, b, k1, k2);
}

/// Rectangular lattice of nx * ny grains, spacings a (along the first cell vector) and b,
/// rotated by `angle`: the cell matrix is not diagonal unless angle = 0.
ContactNetwork rectangularNetwork(int nx, int ny, double a, double b, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    ContactNetwork net = emptyNetwork(nx * ny, {c * nx * a, s * nx * a, -s * ny * b, c * ny * b});
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const double u = (i + 0.3) * a, v = (j + 0.6) * b;
            net.x1[j * nx + i] = c * u - s * v;
            net.x2[j * nx + i] = s * u + c * v;
        }
    }
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            addContact(net, j * nx + i, j * nx + (i + 1) % nx, i + 1 == nx ? 1 : 0, 0);
            addContact(net, j * nx + i, ((j + 1) % ny) * nx + i, 0, j + 1 == ny ? 1 : 0);
        }
    }
    return net;
}

/// Centroid of a stored polygon (vertices are relative to the centroid, so this is ~0).
std::array<double, 3> polygonAreaAndCentroid(const VoidCell& cell) {
    double twiceArea = 0, c1 = 0, c2 = 0;
    const std::size_t n = cell.vertices1.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const double cross =
            cell.vertices1[i] * cell.vertices2[j] - cell.vertices1[j] * cell.vertices2[i];
        twiceArea += cross;
        c1 += (cell.vertices1[i] + cell.vertices1[j]) * cross;
        c2 += (cell.vertices2[i] + cell.vertices2[j]) * cross;
    }
    return {0.5 * twiceArea, c1 / (3 * twiceArea), c2 / (3 * twiceArea)};
}

void expectInsideCell(const ContactNetwork& net, const VoidCell& cell) {
    const auto s = toFractional(net.cell, cell.centroid1, cell.centroid2);
    EXPECT_GE(s[0], 0.0);
    EXPECT_LT(s[0], 1.0);
    EXPECT_GE(s[1], 0.0);
    EXPECT_LT(s[1], 1.0);
}

TEST(VoidCells, HexagonalLatticeGivesTrianglesOfKnownArea) {
    const double d = 1e-3;
    const ContactNetwork net = hexagonalNetwork(10, 8, d);
    const VoidCellSet set = computeVoidCells(net);
    EXPECT_TRUE(set.cellular) << set.problem;
    EXPECT_EQ(set.graphGrains, 80);
    EXPECT_EQ(set.graphContacts, 240);
    EXPECT_EQ(set.voidCount, 160);
    EXPECT_EQ(set.eulerCharacteristic, 0);
    EXPECT_EQ(set.openFaceCount, 0);
    EXPECT_NEAR(set.meanValence, 3.0, 1e-15);
    ASSERT_EQ(set.valenceHistogram.size(), 4u);
    EXPECT_EQ(set.valenceHistogram[3], 160);
    EXPECT_NEAR(set.totalArea, net.cellArea(), 1e-12 * net.cellArea());
    const double triangle = std::sqrt(3.0) / 4.0 * d * d;
    for (const VoidCell& cell : set.cells) {
        EXPECT_EQ(cell.valence, 3);
        EXPECT_EQ(cell.grains.size(), 3u);
        EXPECT_EQ(cell.vertices1.size(), 6u);
        EXPECT_NEAR(cell.area, triangle, 1e-12 * triangle);
        EXPECT_NEAR(cell.elongation, 1.0, 1e-6); // equilateral: isotropic second moment
        expectInsideCell(net, cell);
        const auto ac = polygonAreaAndCentroid(cell);
        EXPECT_NEAR(ac[0], cell.area, 1e-12 * triangle);
        EXPECT_NEAR(ac[1], 0.0, 1e-12 * d);
        EXPECT_NEAR(ac[2], 0.0, 1e-12 * d);
        // Each triangle's grains are three distinct mutual neighbours.
        std::vector<std::int32_t> g = cell.grains;
        std::sort(g.begin(), g.end());
        EXPECT_TRUE(g[0] != g[1] && g[1] != g[2]);
    }
}

TEST(VoidCells, RotatedRectangularLatticeGivesElongatedQuadrilaterals) {
    const double a = 2e-3, b = 1e-3, angle = 0.3;
    const ContactNetwork net = rectangularNetwork(6, 9, a, b, angle);
    const VoidCellSet set = computeVoidCells(net);
    EXPECT_TRUE(set.cellular) << set.problem;
    EXPECT_EQ(set.voidCount, 54);
    EXPECT_NEAR(set.meanValence, 4.0, 1e-15);
    EXPECT_NEAR(set.totalArea, net.cellArea(), 1e-12 * net.cellArea());
    for (const VoidCell& cell : set.cells) {
        EXPECT_EQ(cell.valence, 4);
        EXPECT_NEAR(cell.area, a * b, 1e-12 * a * b);
        // A rectangle's second moments a^3 b / 12 and a b^3 / 12: axis ratio a / b, major axis
        // along the long side.
        EXPECT_NEAR(cell.elongation, a / b, 1e-9);
        EXPECT_NEAR(cell.direction, angle, 1e-9);
        EXPECT_NEAR(cell.secondMoment[0] + cell.secondMoment[1], a * b * (a * a + b * b) / 12,
                    1e-9 * a * b * a * a);
        expectInsideCell(net, cell);
    }
    // Square lattice: elongation 1.
    const VoidCellSet square = computeVoidCells(rectangularNetwork(5, 5, b, b, 0.0));
    EXPECT_EQ(square.voidCount, 25);
    for (const VoidCell& cell : square.cells) {
        EXPECT_NEAR(cell.area, b * b, 1e-12 * b * b);
        EXPECT_NEAR(cell.elongation, 1.0, 1e-6);
    }
    // Long side along x2: the direction is +-pi/2, reported as +pi/2.
    const VoidCellSet upright = computeVoidCells(rectangularNetwork(6, 6, b, a, 0.0));
    EXPECT_NEAR(upright.cells.at(0).direction, 0.5 * kPi, 1e-9);
}

/// The summary a record takes (no shapes) is the full set's, bit for bit, with no cells kept.
void expectSummaryOfFullSet(const ContactNetwork& net) {
    const LoadBearingGraph graph = loadBearingGraph(net);
    const VoidCellSet full = computeVoidCells(net, graph.contactInGraph);
    const VoidCellSet summary = computeVoidCells(net, graph.contactInGraph, false);
    EXPECT_EQ(full.voidCount, static_cast<std::int32_t>(full.cells.size()));
    EXPECT_TRUE(summary.cells.empty());
    EXPECT_EQ(summary.voidCount, full.voidCount);
    EXPECT_EQ(summary.meanValence, full.meanValence);
    EXPECT_EQ(summary.valenceHistogram, full.valenceHistogram);
    EXPECT_EQ(summary.totalArea, full.totalArea);
    EXPECT_EQ(summary.graphGrains, full.graphGrains);
    EXPECT_EQ(summary.graphContacts, full.graphContacts);
    EXPECT_EQ(summary.faceCount, full.faceCount);
    EXPECT_EQ(summary.eulerCharacteristic, full.eulerCharacteristic);
    EXPECT_EQ(summary.openFaceCount, full.openFaceCount);
    EXPECT_EQ(summary.cellular, full.cellular);
    EXPECT_EQ(summary.problem, full.problem);
    // The same through the measures, as a record asks for them.
    MeasureOptions options;
    options.voidCellShapes = false;
    const MeasureSet m = computeMeasures(net, options);
    EXPECT_TRUE(m.voidCells.cells.empty());
    EXPECT_EQ(m.voidCells.voidCount, full.voidCount);
    EXPECT_EQ(m.voidCells.meanValence, full.meanValence);
}

/// A ring of n touching disks of diameter d around (0.5 L, 0.5 L) in an L x L cell.
ContactNetwork ringNetwork(int n, double d, double L, int extra = 0) {
    ContactNetwork net = emptyNetwork(n + extra, {L, 0.0, 0.0, L});
    const double radius = 0.5 * d / std::sin(kPi / n);
    for (int i = 0; i < n; ++i) {
        net.x1[i] = 0.5 * L + radius * std::cos(2 * kPi * i / n);
        net.x2[i] = 0.5 * L + radius * std::sin(2 * kPi * i / n);
    }
    for (int i = 0; i < n; ++i) {
        addContact(net, i, (i + 1) % n);
    }
    return net;
}

TEST(VoidCells, RingEnclosesOneVoidAndReportsTheOutsideAsOpen) {
    const int n = 8;
    const double d = 1e-3, L = 0.02;
    const ContactNetwork net = ringNetwork(n, d, L);
    const VoidCellSet set = computeVoidCells(net);
    ASSERT_EQ(set.voidCount, 1);
    const double radius = 0.5 * d / std::sin(kPi / n);
    const VoidCell& cell = set.cells[0];
    EXPECT_EQ(cell.valence, n);
    EXPECT_NEAR(cell.area, 0.5 * n * radius * radius * std::sin(2 * kPi / n), 1e-15);
    EXPECT_NEAR(cell.centroid1, 0.5 * L, 1e-13);
    EXPECT_NEAR(cell.centroid2, 0.5 * L, 1e-13);
    EXPECT_NEAR(cell.elongation, 1.0, 1e-6);
    // Counter-clockwise: the grains in increasing angle.
    for (int k = 0; k < n; ++k) {
        EXPECT_EQ(cell.grains[(k + 1) % n], (cell.grains[k] + 1) % n);
    }
    // The outside of the ring is no void cell: the graph does not span the torus.
    EXPECT_FALSE(set.cellular);
    EXPECT_FALSE(set.problem.empty());
    EXPECT_EQ(set.faceCount, 2);
    EXPECT_EQ(set.openFaceCount, 1);
    EXPECT_EQ(set.eulerCharacteristic, 2);
    expectSummaryOfFullSet(net);
}

TEST(VoidCells, DanglingChainIsPrunedAndCreatesNoVoid) {
    // A ring of 12 with a chain of two grains reaching into it from grain 0, and a chain of
    // three hanging outside from grain 6.
    const int n = 12;
    const double d = 1e-3, L = 0.02;
    ContactNetwork net = ringNetwork(n, d, L, 5);
    const double radius = 0.5 * d / std::sin(kPi / n);
    net.x1[12] = 0.5 * L + radius - d;
    net.x2[12] = 0.5 * L;
    net.x1[13] = 0.5 * L + radius - 2 * d;
    net.x2[13] = 0.5 * L;
    for (int k = 0; k < 3; ++k) {
        net.x1[14 + k] = 0.5 * L - radius - (k + 1) * d;
        net.x2[14 + k] = 0.5 * L;
    }
    addContact(net, 0, 12);
    addContact(net, 12, 13);
    addContact(net, 6, 14);
    addContact(net, 14, 15);
    addContact(net, 15, 16);
    const double ringArea = 0.5 * n * radius * radius * std::sin(2 * kPi / n);

    const VoidCellSet set = computeVoidCells(net);
    EXPECT_EQ(set.graphGrains, 12);
    EXPECT_EQ(set.graphContacts, 12);
    ASSERT_EQ(set.voidCount, 1);
    EXPECT_EQ(set.cells[0].valence, 12);
    EXPECT_NEAR(set.cells[0].area, ringArea, 1e-15);
    for (std::int32_t g : set.cells[0].grains) {
        EXPECT_LT(g, 12);
    }
    // Without pruning, the inner chain would be walked around (two more sides each way).
    const std::vector<std::uint8_t> all(net.contacts.size(), 1);
    const VoidCellSet unpruned = computeVoidCells(net, all);
    ASSERT_EQ(unpruned.voidCount, 1);
    EXPECT_EQ(unpruned.cells[0].valence, 16);
    EXPECT_NEAR(unpruned.cells[0].area, ringArea, 1e-15); // the chain has no area
}

TEST(VoidCells, ChainAroundTheTorusIsReportedNotCounted) {
    // A row of grains wrapping along x1: both faces wind around the cell.
    const int n = 10;
    const double d = 1e-3;
    ContactNetwork net = emptyNetwork(n, {n * d, 0.0, 0.0, 5 * d});
    for (int i = 0; i < n; ++i) {
        net.x1[i] = (i + 0.5) * d;
        net.x2[i] = 2.5 * d;
    }
    for (int i = 0; i < n; ++i) {
        addContact(net, i, (i + 1) % n, i + 1 == n ? 1 : 0, 0);
    }
    const VoidCellSet set = computeVoidCells(net);
    EXPECT_EQ(set.graphGrains, n);
    EXPECT_EQ(set.voidCount, 0);
    EXPECT_EQ(set.faceCount, 2);
    EXPECT_EQ(set.openFaceCount, 2);
    EXPECT_FALSE(set.cellular);
    EXPECT_EQ(set.meanValence, 0.0);
}

TEST(VoidCells, InconsistentContactPointsAreFlaggedNotFatal) {
    // Contact points put on the wrong side of their grains: the rotation system no longer
    // describes a planar drawing. No crash, no NaN, and the set says so.
    ContactNetwork net = hexagonalNetwork(6, 6, 1e-3);
    for (std::size_t c = 0; c < net.contacts.size(); c += 7) {
        net.contacts[c].point1 = -net.contacts[c].point1;
        net.contacts[c].point2 = -net.contacts[c].point2;
    }
    VoidCellSet set;
    ASSERT_NO_THROW(set = computeVoidCells(net));
    EXPECT_FALSE(set.cellular);
    EXPECT_FALSE(set.problem.empty());
    for (const VoidCell& cell : set.cells) {
        EXPECT_GT(cell.area, 0.0);
        EXPECT_GE(cell.elongation, 1.0);
    }
    // Grains stacked on one point (zero-length contacts): still no crash.
    ContactNetwork stacked = emptyNetwork(3, {1e-2, 0.0, 0.0, 1e-2});
    for (int i = 0; i < 3; ++i) {
        ContactRecord r;
        r.first = i;
        r.second = (i + 1) % 3;
        stacked.contacts.push_back(r);
    }
    ASSERT_NO_THROW(set = computeVoidCells(stacked));
    EXPECT_EQ(set.voidCount, 0);
    EXPECT_FALSE(set.cellular);
    // Mismatched inputs are programming errors.
    EXPECT_THROW(computeVoidCells(net, std::vector<std::uint8_t>(3, 1)), std::invalid_argument);
}

using test::compactedPacking;

/// The two invariants of docs/measures.md and the consistency of every cell with the network.
void checkInvariants(const ContactNetwork& net) {
    expectSummaryOfFullSet(net);
    const LoadBearingGraph graph = loadBearingGraph(net);
    const VoidCellSet set = computeVoidCells(net);
    ASSERT_TRUE(set.cellular) << set.problem;
    EXPECT_EQ(set.graphGrains, graph.grains);
    EXPECT_EQ(set.graphContacts, graph.contacts);
    // V - E + F = 0 on the torus.
    EXPECT_EQ(set.voidCount, graph.contacts - graph.grains);
    EXPECT_EQ(set.eulerCharacteristic, 0);
    // The cells tile the cell.
    EXPECT_NEAR(set.totalArea, net.cellArea(), 1e-9 * net.cellArea());
    // Every half-edge bounds exactly one cell.
    std::int64_t sides = 0;
    for (const VoidCell& cell : set.cells) {
        EXPECT_GE(cell.valence, 3);
        EXPECT_GT(cell.area, 0.0);
        EXPECT_GE(cell.elongation, 1.0);
        EXPECT_GT(cell.direction, -0.5 * kPi);
        EXPECT_LE(cell.direction, 0.5 * kPi);
        for (std::int32_t g : cell.grains) {
            EXPECT_EQ(graph.grainInGraph[g], 1);
        }
        expectInsideCell(net, cell);
        sides += cell.valence;
    }
    EXPECT_EQ(sides, 2 * graph.contacts);
    EXPECT_NEAR(set.meanValence, 2.0 * graph.contacts / set.voidCount, 1e-12);
}

TEST(VoidCells, DenseOvalPackingSatisfiesEulerAndTilesTheCell) {
    Simulation simulation = compactedPacking(400, 0.6, 7, 60000);
    ASSERT_NEAR(simulation.stress().s11, 1e5, 3e3);
    ASSERT_NEAR(simulation.stress().s22, 1e5, 3e3);
    checkInvariants(simulation.contactNetwork());
}

TEST(VoidCells, DenseDiskPackingSatisfiesEulerAndTilesTheCell) {
    Simulation simulation = compactedPacking(500, 1.0, 3, 60000);
    ASSERT_NEAR(simulation.stress().s11, 1e5, 3e3);
    ASSERT_NEAR(simulation.stress().s22, 1e5, 3e3);
    const ContactNetwork net = simulation.contactNetwork();
    // Frictionless disks: rattlers and dangling grains exist, so the pruning matters here.
    EXPECT_LT(loadBearingGraph(net).grains, net.grainCount);
    checkInvariants(net);
}

TEST(VoidCells, LoosePackingIsReportedGracefully) {
    // Early in compaction the contact graph has isolated clusters and does not span the cell.
    Simulation simulation = compactedPacking(500, 1.0, 3, 10000);
    const ContactNetwork net = simulation.contactNetwork();
    const VoidCellSet set = computeVoidCells(net);
    EXPECT_FALSE(set.cellular);
    EXPECT_FALSE(set.problem.empty());
    EXPECT_TRUE(set.openFaceCount > 0 || set.eulerCharacteristic != 0 || set.graphContacts == 0);
    for (const VoidCell& cell : set.cells) {
        EXPECT_GT(cell.area, 0.0);
    }
    EXPECT_LT(set.totalArea, net.cellArea());
    expectSummaryOfFullSet(net);
    // The measures built on it stay finite and consistent.
    const MeasureSet m = computeMeasures(net);
    EXPECT_EQ(m.voidCells.voidCount, set.voidCount);
    EXPECT_GE(m.loadBearing.coordination, 0.0);
}

} // namespace
} // namespace grainlab
