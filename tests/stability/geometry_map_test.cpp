// The contact-geometry map: its exact overlap against closed forms and the outline, the engine's
// contact read from a two-grain simulation against the kernels, a departure planted in the
// reference found where it was planted and nowhere below, and the real measurement finding no
// departure of the engine's contact up to the overlap guard.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/geometry_map.h"
#include "grainlab/random.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(GeometryMap, SupportIsTheOutlinesLargestProjection) {
    Random random(5);
    for (double eta : {0.4, 0.6, 0.8}) {
        const OvalShape s = makeOval(1.3e-3, eta);
        for (int trial = 0; trial < 200; ++trial) {
            const double angle = random.uniform(-kPi, kPi);
            const double ux = std::cos(angle), uy = std::sin(angle);
            const double h = ovalSupport(s, ux, uy);
            // Attained at the boundary point whose outward normal is u ...
            const auto p = s.boundaryPoint(angle);
            EXPECT_NEAR(h, p[0] * ux + p[1] * uy, 1e-15) << eta << " " << angle;
            // ... and no outline point projects further.
            for (int k = 0; k < 720; ++k) {
                const auto q = s.boundaryPoint(2 * kPi * k / 720);
                ASSERT_LE(q[0] * ux + q[1] * uy, h + 1e-15);
            }
        }
    }
}

TEST(GeometryMap, ExactOverlapOfClosedForms) {
    // Two disks: r_A + r_B - distance, along the line of centres.
    const OvalShape a = makeOval(1e-3, 1.0), b = makeOval(2e-3, 1.0);
    const ExactOverlap disks = exactOvalOverlap(a, 1, 0, b, 1, 0, 1.2e-3, 0.9e-3);
    EXPECT_NEAR(disks.overlap, 1.5e-3 - 1.5e-3, 1e-17);
    const ExactOverlap deep = exactOvalOverlap(a, 1, 0, b, 1, 0, 0.6e-3, 0.8e-3);
    EXPECT_NEAR(deep.overlap, 1.5e-3 - 1e-3, 1e-16);
    EXPECT_NEAR(deep.normalAngle, std::atan2(0.8, 0.6), 1e-7);
    // Two parallel ovals stacked along their minor axes: H - dy (the far sides' false
    // candidate of the arc rule, 1.2 W, is not a minimum of the support overlap).
    const OvalShape s = makeOval(1e-3, 0.6);
    for (double overlap : {1e-9, 1e-5, 0.1e-3, 0.3e-3}) {
        const ExactOverlap e = exactOvalOverlap(s, 1, 0, s, 1, 0, 0.0, s.height - overlap);
        EXPECT_NEAR(e.overlap, overlap, 1e-17) << overlap;
        EXPECT_NEAR(e.normalAngle, kPi / 2, 1e-7);
    }
    // Apart: minus the distance between the outlines.
    const ExactOverlap apart = exactOvalOverlap(s, 1, 0, s, 1, 0, 0.0, s.height + 1e-4);
    EXPECT_NEAR(apart.overlap, -1e-4, 1e-17);
}

TEST(GeometryMap, EngineContactIsTheProductionKernel) {
    Random random(17);
    int touching = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const OvalShape A = makeOval(random.uniform(1e-3, 2e-3), 0.6);
        const OvalShape B = makeOval(random.uniform(1e-3, 2e-3), 0.4);
        const double tA = random.uniform(-kPi, kPi), tB = random.uniform(-kPi, kPi);
        const double direction = random.uniform(-kPi, kPi);
        const double reach = random.uniform(0.5, 1.0) * (A.halfWidth + B.halfWidth);
        const double dx = reach * std::cos(direction), dy = reach * std::sin(direction);
        const KernelContact e = engineContact(A, tA, B, tB, dx, dy);
        const ContactGeometry fast =
            ovalContact(A, std::cos(tA), std::sin(tA), B, std::cos(tB), std::sin(tB), dx, dy);
        ASSERT_EQ(e.touching, fast.overlap > 0.0) << trial;
        if (e.touching) {
            ++touching;
            // The engine's own sines and cosines differ from the C library's by round-off.
            EXPECT_NEAR(e.overlap, fast.overlap, 1e-15) << trial;
        }
    }
    EXPECT_GT(touching, 100);
}

GeometryMapSpec smallMap() {
    GeometryMapSpec spec;
    spec.aspectRatios = {0.6};
    spec.sizeRatios = {1.0, 2.0};
    spec.overlaps = {0.001, 0.05, 0.1, 0.2, 0.3};
    spec.pairs = 25;
    return spec;
}

TEST(GeometryMap, APlantedDepartureIsFoundWhereItWasPlanted) {
    const GeometryMapSpec spec = smallMap();
    // A reference wrong by 3e-9 W from 0.15 W of overlap on: the map must report departures
    // from the 0.2 level, of that size, and none below.
    const auto planted = [](const OvalShape& A, double cA, double sA, const OvalShape& B, double cB,
                            double sB, double dx, double dy) {
        ExactOverlap e = exactOvalOverlap(A, cA, sA, B, cB, sB, dx, dy);
        if (e.overlap > 0.15 * A.width) {
            e.overlap += 3e-9 * A.width;
        }
        return e;
    };
    const auto levels = measureGeometryMap(spec, planted);
    for (const GeometryLevel& l : levels) {
        ASSERT_EQ(l.pairs, spec.pairs) << l.overlap;
        const KernelDeparture& d = l.kernels[int(GeometryKernel::Engine)];
        if (l.overlap < 0.15) {
            EXPECT_EQ(d.departures, 0) << l.overlap;
        } else {
            EXPECT_EQ(d.departures, spec.pairs) << l.overlap;
            EXPECT_NEAR(d.maxDeparture, 3e-9, 1e-12) << l.overlap;
        }
    }
    const auto lines = geometryLines(spec, levels);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].departureStart[int(GeometryKernel::Engine)], 0.2);
}

TEST(GeometryMap, TheEngineDepartsNowhereBelowTheGuard) {
    const GeometryMapSpec spec = smallMap();
    const auto levels = measureGeometryMap(spec);
    for (const GeometryLevel& l : levels) {
        ASSERT_EQ(l.pairs, spec.pairs);
        const KernelDeparture& e = l.kernels[int(GeometryKernel::Engine)];
        const KernelDeparture& all = l.kernels[int(GeometryKernel::SixteenPair)];
        // The exact overlap is found to round-off: the engine and the 16-pair rule agree with
        // it to far below the tolerance, with the same normal.
        EXPECT_EQ(e.departures, 0) << l.overlap;
        EXPECT_EQ(e.wrongNormals, 0) << l.overlap;
        EXPECT_LT(e.maxDeparture, 1e-12) << l.overlap;
        EXPECT_EQ(all.departures, 0) << l.overlap;
    }
    const std::string csv = geometryCsv(levels);
    EXPECT_NE(csv.find("max_departure [-]"), std::string::npos);
    EXPECT_EQ(csv.find("nan"), std::string::npos);
}

} // namespace
} // namespace grainlab
