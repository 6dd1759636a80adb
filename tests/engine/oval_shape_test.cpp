#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "grainlab/oval_shape.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// Area and polar moment of a fine polygon through the outline (shoelace formulas).
void polygonMoments(const OvalShape& s, int vertices, double& area, double& polar) {
    std::vector<std::array<double, 2>> p(vertices);
    for (int k = 0; k < vertices; ++k) {
        p[k] = s.boundaryPoint(2.0 * kPi * k / vertices);
    }
    area = polar = 0;
    for (int k = 0; k < vertices; ++k) {
        const auto& a = p[k];
        const auto& b = p[(k + 1) % vertices];
        const double cross = a[0] * b[1] - b[0] * a[1];
        area += 0.5 * cross;
        polar +=
            cross *
            (a[0] * a[0] + a[0] * b[0] + b[0] * b[0] + a[1] * a[1] + a[1] * b[1] + b[1] * b[1]) /
            12.0;
    }
}

TEST(OvalShape, EqualAreaClosureMatchesSpecNumbers) {
    const OvalShape s = makeOval(1.0, 0.6);
    EXPECT_NEAR(s.endRadius, 0.2173, 5e-4);
    EXPECT_NEAR(s.sideRadius, 0.7417, 5e-4);
    EXPECT_NEAR(s.junctionAngle * 180.0 / kPi, 57.4, 0.05);
    EXPECT_NEAR(s.area, kPi * 0.5 * 0.3, 1e-12);
    EXPECT_NEAR(ovalArea(s.endRadius, s.sideRadius, s.junctionAngle), s.area, 1e-12);
}

TEST(OvalShape, OutlineIsContinuousAtJunctions) {
    for (double eta : {0.3, 0.6, 0.9}) {
        const OvalShape s = makeOval(2e-3, eta);
        for (double angle : {s.junctionAngle, kPi - s.junctionAngle, kPi + s.junctionAngle,
                             2 * kPi - s.junctionAngle}) {
            const auto a = s.boundaryPoint(angle - 1e-7), b = s.boundaryPoint(angle + 1e-7);
            EXPECT_NEAR(a[0], b[0], 1e-9);
            EXPECT_NEAR(a[1], b[1], 1e-9);
        }
        // Extremes: half-width along x, half-height along y.
        EXPECT_NEAR(s.boundaryPoint(0.0)[0], s.halfWidth, 1e-15);
        EXPECT_NEAR(s.boundaryPoint(0.5 * kPi)[1], s.halfHeight, 1e-15);
    }
}

TEST(OvalShape, AreaAndInertiaMatchFinePolygon) {
    for (double eta : {0.35, 0.6, 0.8, 0.99}) {
        for (double ratio : {0.0, 0.1}) {
            if (ratio >= 0.5 * eta) {
                continue;
            }
            const OvalShape s = ratio == 0.0
                                    ? makeOval(1.5e-3, eta)
                                    : makeOval(1.5e-3, eta, OvalClosure::EndRadiusRatio, ratio);
            double area, polar;
            polygonMoments(s, 200000, area, polar);
            EXPECT_NEAR(s.area / area, 1.0, 1e-8) << "eta " << eta << " r/W " << ratio;
            EXPECT_NEAR(s.polarMoment / polar, 1.0, 1e-8) << "eta " << eta << " r/W " << ratio;
            EXPECT_NEAR(ovalArea(s.endRadius, s.sideRadius, s.junctionAngle), s.area,
                        1e-12 * s.area);
        }
    }
}

TEST(OvalShape, DiskIsExact) {
    const OvalShape s = makeOval(2e-3, 1.0);
    EXPECT_TRUE(s.isDisk);
    EXPECT_DOUBLE_EQ(s.area, kPi * 1e-6);
    EXPECT_DOUBLE_EQ(s.polarMoment, 0.5 * kPi * 1e-12);
    EXPECT_FALSE(makeOval(2e-3, 0.999).isDisk);
}

TEST(OvalShape, RefusesBadParametersWithRange) {
    EXPECT_THROW(makeOval(-1.0, 0.6), std::invalid_argument);
    EXPECT_THROW(makeOval(1.0, 1.2), std::invalid_argument);
    try {
        makeOval(1.0, 0.6, OvalClosure::EndRadiusRatio, 0.4);
        FAIL() << "r/W = 0.4 accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("(0, 0.3)"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace grainlab
