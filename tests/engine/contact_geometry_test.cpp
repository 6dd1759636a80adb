// Contact detection against brute force (docs/physics.md): the arc-pair rule with the minimum
// overlap must agree with a separating-axis computation on fine polygons, and the fast 4-pair
// form with the 16-pair reference.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/random.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// The oval outline as a polygon of `vertices` points (body frame), vertices at evenly spaced
/// outward-normal angles so that the polygon hugs the tight end arcs as well as the sides.
std::vector<std::array<double, 2>> outline(const OvalShape& s, int vertices) {
    std::vector<std::array<double, 2>> p(vertices);
    for (int k = 0; k < vertices; ++k) {
        p[k] = s.boundaryPoint(2.0 * kPi * k / vertices);
    }
    return p;
}

/// Support of a polygon placed at (x, y) with orientation theta, in world direction d.
double support(const std::vector<std::array<double, 2>>& poly, double x, double y, double theta,
               double d1, double d2) {
    const double c = std::cos(theta), s = std::sin(theta);
    // Rotate d into the body frame once, then a max over the body-frame vertices.
    const double b1 = c * d1 + s * d2, b2 = -s * d1 + c * d2;
    double best = -1e300;
    for (const auto& v : poly) {
        best = std::max(best, v[0] * b1 + v[1] * b2);
    }
    return best + x * d1 + y * d2;
}

struct BruteContact {
    double overlap, angle;
};

/// Penetration depth by the separating-axis theorem: min over directions d of
/// h_A(d) + h_B(-d) - d . (x_B - x_A); the minimising d is the contact normal.
BruteContact bruteForce(const OvalShape& A, double thetaA, const OvalShape& B, double thetaB,
                        double dx, double dy) {
    const auto coarseA = outline(A, 1024), coarseB = outline(B, 1024);
    const auto fineA = outline(A, 16384), fineB = outline(B, 16384);
    // B's support already contains its offset, so the overlap along d is h_A(d) + h_B(-d).
    auto overlapAt = [&](const auto& pa, const auto& pb, double angle) {
        const double d1 = std::cos(angle), d2 = std::sin(angle);
        return support(pa, 0, 0, thetaA, d1, d2) + support(pb, dx, dy, thetaB, -d1, -d2);
    };
    const int samples = 720;
    std::vector<double> value(samples);
    for (int k = 0; k < samples; ++k) {
        value[k] = overlapAt(coarseA, coarseB, 2 * kPi * k / samples);
    }
    // Refine the three smallest local minima with the fine polygons (golden section).
    std::vector<int> minima;
    for (int k = 0; k < samples; ++k) {
        if (value[k] <= value[(k + 1) % samples] &&
            value[k] <= value[(k + samples - 1) % samples]) {
            minima.push_back(k);
        }
    }
    std::sort(minima.begin(), minima.end(), [&](int a, int b) { return value[a] < value[b]; });
    minima.resize(std::min<std::size_t>(3, minima.size()));
    BruteContact best{1e300, 0};
    for (int k : minima) {
        // The coarse polygons are good to ~1e-8 m: bracket generously around each minimum.
        double lo = 2 * kPi * (k - 8) / samples, hi = 2 * kPi * (k + 8) / samples;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        double fa = overlapAt(fineA, fineB, a), fb = overlapAt(fineA, fineB, b);
        for (int it = 0; it < 70; ++it) {
            if (fa < fb) {
                hi = b;
                b = a;
                fb = fa;
                a = hi - g * (hi - lo);
                fa = overlapAt(fineA, fineB, a);
            } else {
                lo = a;
                a = b;
                fa = fb;
                b = lo + g * (hi - lo);
                fb = overlapAt(fineA, fineB, b);
            }
        }
        const double angle = 0.5 * (lo + hi);
        const double v = overlapAt(fineA, fineB, angle);
        if (v < best.overlap) {
            best = {v, angle};
        }
    }
    return best;
}

struct RandomPair {
    OvalShape A, B;
    double thetaA, thetaB, dx, dy;
};

/// Two random ovals whose bounding circles overlap, at overlaps up to ~0.1 W.
RandomPair randomPair(Random& random, double aspect) {
    RandomPair p{makeOval(random.uniform(1e-3, 2e-3), aspect),
                 makeOval(random.uniform(1e-3, 2e-3), aspect),
                 random.uniform(-kPi, kPi),
                 random.uniform(-kPi, kPi),
                 0,
                 0};
    const double direction = random.uniform(0, 2 * kPi);
    const double reach = p.A.halfHeight + p.B.halfHeight +
                         random.uniform(-0.15, 1.0) *
                             (p.A.halfWidth + p.B.halfWidth - p.A.halfHeight - p.B.halfHeight);
    p.dx = reach * std::cos(direction);
    p.dy = reach * std::sin(direction);
    return p;
}

TEST(ContactGeometry, ArcRuleMatchesSeparatingAxisBruteForce) {
    Random random(7);
    int touching = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        const double aspect = trial % 3 == 0 ? 0.35 : 0.6;
        const RandomPair p = randomPair(random, aspect);
        const ContactGeometry g = ovalContactAllPairs(p.A, p.thetaA, p.B, p.thetaB, p.dx, p.dy);
        const BruteContact b = bruteForce(p.A, p.thetaA, p.B, p.thetaB, p.dx, p.dy);
        const double scale = std::min(p.A.width, p.B.width);
        // The inscribed polygons under-estimate each support by < 2e-8 W.
        ASSERT_NEAR(g.overlap, b.overlap, 1e-7 * scale) << "trial " << trial;
        if (b.overlap > 1e-4 * scale) {
            ++touching;
            const double angle = std::atan2(g.normalY, g.normalX);
            const double diff = std::remainder(angle - b.angle, 2 * kPi);
            ASSERT_LT(std::fabs(diff), 2e-3) << "trial " << trial;
            // Contact point: mid-way between the support points of A along n and B along -n.
            const auto pa = p.A.boundaryPoint(
                std::atan2(-std::sin(p.thetaA) * g.normalX + std::cos(p.thetaA) * g.normalY,
                           std::cos(p.thetaA) * g.normalX + std::sin(p.thetaA) * g.normalY));
            const double ax = std::cos(p.thetaA) * pa[0] - std::sin(p.thetaA) * pa[1];
            const double ay = std::sin(p.thetaA) * pa[0] + std::cos(p.thetaA) * pa[1];
            const auto pb = p.B.boundaryPoint(
                std::atan2(std::sin(p.thetaB) * g.normalX - std::cos(p.thetaB) * g.normalY,
                           -std::cos(p.thetaB) * g.normalX - std::sin(p.thetaB) * g.normalY));
            const double bx = p.dx + std::cos(p.thetaB) * pb[0] - std::sin(p.thetaB) * pb[1];
            const double by = p.dy + std::sin(p.thetaB) * pb[0] + std::cos(p.thetaB) * pb[1];
            ASSERT_NEAR(g.pointX, 0.5 * (ax + bx), 1e-9 * 1e3 * scale) << "trial " << trial;
            ASSERT_NEAR(g.pointY, 0.5 * (ay + by), 1e-9 * 1e3 * scale) << "trial " << trial;
        }
    }
    EXPECT_GT(touching, 600); // the sample really tests contacts, not only separated pairs
}

TEST(ContactGeometry, FourPairFormEqualsSixteenPairReference) {
    Random random(11);
    int touching = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        const RandomPair p = randomPair(random, trial % 2 ? 0.6 : 0.4);
        const ContactGeometry ref = ovalContactAllPairs(p.A, p.thetaA, p.B, p.thetaB, p.dx, p.dy);
        const ContactGeometry fast =
            ovalContact(p.A, std::cos(p.thetaA), std::sin(p.thetaA), p.B, std::cos(p.thetaB),
                        std::sin(p.thetaB), p.dx, p.dy);
        if (ref.overlap > 0.0) {
            ++touching;
        }
        if (ref.overlap > 0.0 || fast.overlap > 0.0) {
            ASSERT_NEAR(fast.overlap, ref.overlap, 1e-15) << "trial " << trial;
            ASSERT_NEAR(fast.normalX, ref.normalX, 1e-12) << "trial " << trial;
            ASSERT_NEAR(fast.normalY, ref.normalY, 1e-12) << "trial " << trial;
        }
    }
    EXPECT_GT(touching, 50000);
}

/// A pair at a chosen overlap: random sizes and orientations, and the distance along a random
/// branch direction at which the 16-pair reference gives `overlapFraction` of the smaller width
/// (bisection; the reference's overlap falls as the grains separate along the branch).
RandomPair pairAtOverlap(Random& random, double aspectA, double aspectB, double overlapFraction) {
    RandomPair p{makeOval(random.uniform(1e-3, 2e-3), aspectA),
                 makeOval(random.uniform(1e-3, 2e-3), aspectB),
                 random.uniform(-kPi, kPi),
                 random.uniform(-kPi, kPi),
                 0,
                 0};
    const double direction = random.uniform(-kPi, kPi);
    const double c = std::cos(direction), s = std::sin(direction);
    const double target = overlapFraction * std::min(p.A.width, p.B.width);
    double lo = 0.0, hi = p.A.halfWidth + p.B.halfWidth; // overlap(lo) > target > overlap(hi)
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        const double overlap =
            ovalContactAllPairs(p.A, p.thetaA, p.B, p.thetaB, mid * c, mid * s).overlap;
        (overlap > target ? lo : hi) = mid;
    }
    p.dx = 0.5 * (lo + hi) * c;
    p.dy = 0.5 * (lo + hi) * s;
    return p;
}

/// The arc pair the 16-pair reference chooses (the admissible one with the smallest overlap,
/// the first on ties), -1 when none is admissible.
std::array<int, 2> referenceArcPair(const RandomPair& p) {
    const double cA = std::cos(p.thetaA), sA = std::sin(p.thetaA);
    const double cB = std::cos(p.thetaB), sB = std::sin(p.thetaB);
    std::array<int, 2> chosen = {-1, -1};
    double best = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            ContactGeometry one;
            detail::tryArcPair(p.A, cA, sA, i, p.B, cB, sB, j, p.dx, p.dy, one);
            const bool admissible = one.overlap != -std::numeric_limits<double>::infinity();
            if (admissible && (chosen[0] < 0 || one.overlap < best)) {
                chosen = {i, j};
                best = one.overlap;
            }
        }
    }
    return chosen;
}

// The oracle for the engine's contact (ovalContact: the quadrant kernel, then the reference
// where it asks, as the pair loop decides): on random pairs at every orientation, from near-tangent
// (|overlap| down to 1e-12 W) to deep (0.3 W) overlaps, ovals of two aspect ratios and the disk
// limit (aspect 1, against ovals and disks), it chooses the reference's arc pair: its overlap
// has the same bits as that pair's, its normal and contact point agree to 4e-16 (the normal is
// divided by the distance in the reference, multiplied by its inverse here).
TEST(ContactGeometry, FastContactEqualsSixteenPairBruteForceEverywhere) {
    Random random(23);
    const std::array<double, 4> aspects = {0.35, 0.6, 0.9, 1.0};
    int touching = 0, nearTangent = 0, deep = 0;
    for (int trial = 0; trial < 60000; ++trial) {
        const double aspectA = aspects[trial % 4], aspectB = aspects[(trial / 4) % 4];
        double fraction;
        switch (trial % 5) {
        case 0: // near-tangent, either side of contact
            fraction =
                (random.uniform() < 0.5 ? -1.0 : 1.0) * std::pow(10.0, random.uniform(-12.0, -6.0));
            ++nearTangent;
            break;
        case 1: // deep
            fraction = random.uniform(0.05, 0.3);
            ++deep;
            break;
        case 2: // apart
            fraction = random.uniform(-0.2, 0.0);
            break;
        default: // as in a packing and beyond
            fraction = random.uniform(0.0, 0.05);
            break;
        }
        const RandomPair p = pairAtOverlap(random, aspectA, aspectB, fraction);
        const double cA = std::cos(p.thetaA), sA = std::sin(p.thetaA);
        const double cB = std::cos(p.thetaB), sB = std::sin(p.thetaB);
        const ContactGeometry ref = ovalContactAllPairs(p.A, cA, sA, p.B, cB, sB, p.dx, p.dy);
        const ContactGeometry fast = ovalContact(p.A, cA, sA, p.B, cB, sB, p.dx, p.dy);
        const std::array<int, 2> arcs = referenceArcPair(p);
        if (arcs[0] < 0) { // no arc pair admissible (far apart): neither finds a contact
            ASSERT_EQ(fast.overlap, ref.overlap) << "trial " << trial;
            continue;
        }
        touching += ref.overlap > 0.0 ? 1 : 0;
        // The chosen arc pair's overlap, bit for bit; and so the same side of contact.
        ContactGeometry chosen;
        detail::tryArcPair(p.A, cA, sA, arcs[0], p.B, cB, sB, arcs[1], p.dx, p.dy, chosen);
        ASSERT_EQ(fast.overlap, chosen.overlap) << "trial " << trial;
        ASSERT_EQ(fast.overlap, ref.overlap) << "trial " << trial;
        const double scale = std::min(p.A.width, p.B.width);
        ASSERT_NEAR(fast.normalX, ref.normalX, 4e-16) << "trial " << trial;
        ASSERT_NEAR(fast.normalY, ref.normalY, 4e-16) << "trial " << trial;
        ASSERT_NEAR(fast.pointX, ref.pointX, 4e-16 * scale) << "trial " << trial;
        ASSERT_NEAR(fast.pointY, ref.pointY, 4e-16 * scale) << "trial " << trial;
    }
    EXPECT_GT(touching, 35000);
    EXPECT_EQ(nearTangent, 12000);
    EXPECT_EQ(deep, 12000);
}

TEST(ContactGeometry, OneFormArcsScaleToEachShapesArcs) {
    for (const OvalClosure closure : {OvalClosure::EqualArea, OvalClosure::EndRadiusRatio}) {
        for (const double aspect : {0.35, 0.6, 0.9, 1.0}) {
            std::vector<OvalShape> shapes;
            for (int k = 0; k <= 10; ++k) {
                shapes.push_back(makeOval(1e-3 + 1e-4 * k, aspect, closure, 0.3 * aspect));
            }
            OvalArcs unit;
            ASSERT_TRUE(oneFormArcs(shapes, unit)) << "aspect " << aspect;
            for (const OvalShape& s : shapes) {
                const OvalArcs own = ovalArcs(s);
                const double a = s.halfWidth, tight = 1e-14 * a;
                EXPECT_NEAR(a * unit.endOffset, own.endOffset, tight);
                EXPECT_NEAR(a * unit.sideOffset, own.sideOffset, tight);
                EXPECT_NEAR(a * unit.endRadius, own.endRadius, tight);
                EXPECT_NEAR(a * unit.sideRadius, own.sideRadius, tight);
                EXPECT_NEAR(unit.cosJunction, own.cosJunction, 1e-14);
                EXPECT_NEAR(unit.sinJunction, own.sinJunction, 1e-14);
            }
        }
    }
    OvalArcs unit;
    EXPECT_FALSE(oneFormArcs({}, unit));
    EXPECT_FALSE(oneFormArcs({makeOval(1e-3, 0.6), makeOval(2e-3, 0.6 + 1e-9)}, unit));
    EXPECT_FALSE(oneFormArcs({makeOval(1e-3, 0.6), makeOval(2e-3, 1.0)}, unit));
    EXPECT_FALSE(oneFormArcs(
        {makeOval(1e-3, 0.6), makeOval(2e-3, 0.6, OvalClosure::EndRadiusRatio, 0.2)}, unit));
}

// The engine's one-form kernel (the quadrant kernel on a * unit arcs) against the 16-pair
// reference on each shape's own arcs, from near-tangent to deep overlaps at every orientation:
// where it decides, the same contact to round-off (the arcs differ by that much).
TEST(ContactGeometry, OneFormKernelEqualsSixteenPairReference) {
    Random random(31);
    const std::array<double, 3> aspects = {0.35, 0.6, 0.9};
    int decided = 0, touching = 0;
    const int trials = 30000;
    for (int trial = 0; trial < trials; ++trial) {
        const double aspect = aspects[trial % 3];
        const double fraction = trial % 4 == 0 ? (random.uniform() < 0.5 ? -1.0 : 1.0) *
                                                     std::pow(10.0, random.uniform(-12.0, -6.0))
                                               : random.uniform(-0.05, 0.08);
        const RandomPair p = pairAtOverlap(random, aspect, aspect, fraction);
        OvalArcs u;
        ASSERT_TRUE(oneFormArcs({p.A, p.B}, u));
        const double cA = std::cos(p.thetaA), sA = std::sin(p.thetaA);
        const double cB = std::cos(p.thetaB), sB = std::sin(p.thetaB);
        const double a = p.A.halfWidth, b = p.B.halfWidth;
        const QuadrantContact q = ovalContactQuadrant(
            a * u.endOffset, a * u.sideOffset, a * u.endRadius, a * u.sideRadius, u.cosJunction,
            u.sinJunction, cA, sA, b * u.endOffset, b * u.sideOffset, b * u.endRadius,
            b * u.sideRadius, u.cosJunction, u.sinJunction, cB, sB, p.dx, p.dy,
            std::min(p.A.width, p.B.width));
        const ContactGeometry ref = ovalContactAllPairs(p.A, cA, sA, p.B, cB, sB, p.dx, p.dy);
        if (q.needsReference) {
            continue;
        }
        ++decided;
        touching += ref.overlap > 0.0 ? 1 : 0;
        const double scale = std::min(p.A.width, p.B.width);
        ASSERT_NEAR(q.geometry.overlap, ref.overlap, 1e-14 * scale) << "trial " << trial;
        ASSERT_NEAR(q.geometry.normalX, ref.normalX, 1e-12) << "trial " << trial;
        ASSERT_NEAR(q.geometry.normalY, ref.normalY, 1e-12) << "trial " << trial;
        ASSERT_NEAR(q.geometry.pointX, ref.pointX, 1e-12 * scale) << "trial " << trial;
        ASSERT_NEAR(q.geometry.pointY, ref.pointY, 1e-12 * scale) << "trial " << trial;
    }
    EXPECT_GT(decided, 0.9 * trials);
    EXPECT_GT(touching, 0.5 * trials);
}

TEST(ContactGeometry, JunctionDirectionsAreAdmittedByBothArcs) {
    // Two ovals placed so that the line of centres passes exactly through A's junction normal.
    const OvalShape s = makeOval(1e-3, 0.6);
    const double phi = s.junctionAngle;
    const auto pa = s.boundaryPoint(phi);
    // B a disk touching A at its junction point, along the junction normal.
    const OvalShape disk = makeOval(1e-3, 1.0);
    const double gap = -2e-6; // overlap 2 micrometre
    const double dx = pa[0] + (disk.halfWidth + gap) * std::cos(phi);
    const double dy = pa[1] + (disk.halfWidth + gap) * std::sin(phi);
    const ContactGeometry g = ovalContactAllPairs(s, 0.0, disk, 0.0, dx, dy);
    EXPECT_NEAR(g.overlap, -gap, 1e-12);
    EXPECT_NEAR(std::atan2(g.normalY, g.normalX), phi, 1e-6);
}

TEST(ContactGeometry, FarSideFalseCandidateIsRejected) {
    // Two parallel ovals stacked along their minor axes, overlapping by s. A's bottom side arc
    // and B's top side arc (far sides) are admissible too, with an overlap near 1.2 W: taking
    // any pair but the minimum would create an enormous false force.
    const OvalShape s = makeOval(1e-3, 0.6);
    const double overlap = 3e-6;
    const double dy = s.height - overlap;
    int admissibleFarSide = 0;
    {
        ContactGeometry far;
        detail::tryArcPair(s, 1.0, 0.0, kBottomSide, s, 1.0, 0.0, kTopSide, 0.0, dy, far);
        if (far.overlap > 1.0 * s.width) {
            ++admissibleFarSide;
        }
    }
    ASSERT_EQ(admissibleFarSide, 1) << "the scene must contain the false candidate";
    const ContactGeometry g = ovalContactAllPairs(s, 0.0, s, 0.0, 0.0, dy);
    EXPECT_NEAR(g.overlap, overlap, 1e-15);
    EXPECT_NEAR(g.normalY, 1.0, 1e-15);
    const ContactGeometry fast = ovalContact(s, 1.0, 0.0, s, 1.0, 0.0, 0.0, dy);
    EXPECT_NEAR(fast.overlap, overlap, 1e-15);
}

TEST(ContactGeometry, DiskThroughOvalKernelEqualsDiskKernel) {
    Random random(3);
    for (int trial = 0; trial < 10000; ++trial) {
        const OvalShape a = makeOval(random.uniform(1e-3, 2e-3), 1.0);
        const OvalShape b = makeOval(random.uniform(1e-3, 2e-3), 1.0);
        const double angle = random.uniform(-kPi, kPi);
        const double distance = (a.halfWidth + b.halfWidth) * random.uniform(0.9, 1.01);
        const double dx = distance * std::cos(angle), dy = distance * std::sin(angle);
        const double ta = random.uniform(-kPi, kPi), tb = random.uniform(-kPi, kPi);
        const ContactGeometry disk = diskContact(a.halfWidth, a.halfWidth + b.halfWidth, dx, dy);
        const ContactGeometry oval =
            ovalContact(a, std::cos(ta), std::sin(ta), b, std::cos(tb), std::sin(tb), dx, dy);
        ASSERT_NEAR(oval.overlap, disk.overlap, 1e-18);
        ASSERT_NEAR(oval.normalX, disk.normalX, 1e-14);
        ASSERT_NEAR(oval.pointX, disk.pointX, 1e-18);
        ASSERT_NEAR(oval.pointY, disk.pointY, 1e-18);
    }
}

} // namespace
} // namespace grainlab
