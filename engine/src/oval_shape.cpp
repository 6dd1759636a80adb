#include "grainlab/oval_shape.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

/// Side radius and junction angle that close the construction for a given end radius.
void closeArcs(double a, double b, double r, double& sideRadius, double& junctionAngle) {
    sideRadius = (a * a - 2.0 * a * r + b * b) / (2.0 * (b - r));
    junctionAngle = std::atan2(sideRadius - b, a - r);
}

/// Normal-angle interval [t0, t1] covered by each arc, counter-clockwise.
std::array<std::array<double, 2>, 4> arcIntervals(double phi) {
    return {{{-phi, phi}, {phi, kPi - phi}, {kPi - phi, kPi + phi}, {kPi + phi, 2 * kPi - phi}}};
}

// 16-point Gauss-Legendre nodes and weights on [-1, 1]. The Green integrands below are
// trigonometric polynomials of degree <= 4 over arcs shorter than pi: the rule is exact to
// round-off there (checked against a fine polygon in tests/engine/oval_shape_test.cpp).
constexpr std::array<double, 8> kGaussNodes = {
    0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
    0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
constexpr std::array<double, 8> kGaussWeights = {
    0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
    0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};

/// Area and polar moment by Green's theorem along the arcs:
/// A = 1/2 \oint (x dy - y dx),  J = 1/3 \oint (x^3 dy - y^3 dx).
void integrateOutline(const OvalShape& s, double& area, double& polarMoment) {
    area = 0;
    polarMoment = 0;
    const auto arcs = s.arcs();
    const auto intervals = arcIntervals(s.junctionAngle);
    for (int k = 0; k < 4; ++k) {
        const double t0 = intervals[k][0], t1 = intervals[k][1];
        const double half = 0.5 * (t1 - t0), mid = 0.5 * (t1 + t0);
        for (int q = 0; q < 16; ++q) {
            const double node = (q < 8 ? -kGaussNodes[7 - q] : kGaussNodes[q - 8]);
            const double weight = (q < 8 ? kGaussWeights[7 - q] : kGaussWeights[q - 8]) * half;
            const double t = mid + half * node;
            const double rho = arcs[k].radius;
            const double x = arcs[k].centreX + rho * std::cos(t);
            const double y = arcs[k].centreY + rho * std::sin(t);
            const double dx = -rho * std::sin(t), dy = rho * std::cos(t);
            area += weight * 0.5 * (x * dy - y * dx);
            polarMoment += weight * (x * x * x * dy - y * y * y * dx) / 3.0;
        }
    }
}

} // namespace

std::array<Arc, 4> OvalShape::arcs() const {
    const double endOffset = halfWidth - endRadius;
    const double sideOffset = sideRadius - halfHeight;
    return {{{endOffset, 0.0, endRadius},
             {0.0, -sideOffset, sideRadius},
             {-endOffset, 0.0, endRadius},
             {0.0, sideOffset, sideRadius}}};
}

double OvalShape::equivalentDiameter() const {
    return std::sqrt(4.0 * area / kPi);
}

std::array<double, 2> OvalShape::boundaryPoint(double normalAngle) const {
    const double dx = std::cos(normalAngle), dy = std::sin(normalAngle);
    const auto all = arcs();
    for (int k = 0; k < 4; ++k) {
        if (arcAdmits(*this, k, dx, dy)) {
            return {all[k].centreX + all[k].radius * dx, all[k].centreY + all[k].radius * dy};
        }
    }
    return {halfWidth * dx, halfHeight * dy}; // unreachable: the four ranges cover the circle
}

double ovalArea(double r, double R, double phi) {
    return 2.0 * phi * r * r + (kPi - 2.0 * phi) * R * R - (R - r) * (R - r) * std::sin(2.0 * phi);
}

OvalShape makeOval(double width, double aspectRatio, OvalClosure closure, double endRadiusRatio) {
    if (!(width > 0.0) || !std::isfinite(width)) {
        throw std::invalid_argument(fmt::format("oval width {} m: must be > 0", width));
    }
    if (!(aspectRatio > 0.0 && aspectRatio <= 1.0)) {
        throw std::invalid_argument(
            fmt::format("oval aspect ratio {}: allowed range is (0, 1]", aspectRatio));
    }
    OvalShape s;
    s.width = width;
    s.height = aspectRatio * width;
    s.halfWidth = 0.5 * width;
    s.halfHeight = 0.5 * s.height;
    const double a = s.halfWidth, b = s.halfHeight;

    if (aspectRatio == 1.0) {
        // A disk: every arc is the full circle of radius a; phi = 0 so the side arcs cover
        // every direction. The oval kernels handle it exactly; the disk fast path skips them.
        s.isDisk = true;
        s.endRadius = s.sideRadius = a;
        s.junctionAngle = 0.0;
    } else if (closure == OvalClosure::EndRadiusRatio) {
        if (!(endRadiusRatio > 0.0 && endRadiusRatio < 0.5 * aspectRatio)) {
            throw std::invalid_argument(fmt::format(
                "end-arc radius ratio r/W = {}: allowed range is (0, {}) for aspect ratio {}",
                endRadiusRatio, 0.5 * aspectRatio, aspectRatio));
        }
        s.endRadius = endRadiusRatio * width;
        closeArcs(a, b, s.endRadius, s.sideRadius, s.junctionAngle);
    } else {
        // Equal-area closure: the area grows monotonically with r from the lens (r -> 0) to
        // the stadium (r -> b), bracketing the ellipse's pi a b. Bisection to round-off.
        const double target = kPi * a * b;
        double lo = 1e-9 * b, hi = b * (1.0 - 1e-12);
        for (int it = 0; it < 200 && hi - lo > 1e-16 * b; ++it) {
            const double mid = 0.5 * (lo + hi);
            double R, phi;
            closeArcs(a, b, mid, R, phi);
            (ovalArea(mid, R, phi) < target ? lo : hi) = mid;
        }
        s.endRadius = 0.5 * (lo + hi);
        closeArcs(a, b, s.endRadius, s.sideRadius, s.junctionAngle);
    }
    s.cosJunction = std::cos(s.junctionAngle);
    s.sinJunction = std::sin(s.junctionAngle);
    if (s.isDisk) {
        s.area = kPi * a * a;
        s.polarMoment = 0.5 * kPi * a * a * a * a;
    } else {
        integrateOutline(s, s.area, s.polarMoment);
    }
    return s;
}

} // namespace grainlab
