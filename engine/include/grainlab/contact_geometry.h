#pragma once
// Narrow-phase contact geometry: disks, and ovals by admissible arc pairs with the minimum-overlap
// rule (of the arc pairs whose common normal lies in both arcs' angular ranges, the one with the
// smallest overlap decides). Small inline functions of plain numbers, called per neighbour pair in
// the hot loop on the engine's threads, and by the tests against brute force.
//
// Conventions: A is the first grain, B the second at the periodic image nearest to A; (dx, dy)
// is the branch vector x_B - x_A [m]. The normal points from A to B. The contact point lies at
// mid-overlap on the line of the two arc centres and is returned relative to A's centre.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "grainlab/oval_shape.h"

namespace grainlab {

struct ContactGeometry {
    double overlap = -std::numeric_limits<double>::infinity(); ///< delta [m]; contact iff > 0
    double normalX = 0;                                        ///< unit normal from A to B
    double normalY = 0;
    double pointX = 0; ///< contact point minus A's centre [m]
    double pointY = 0;
};

/// Disk-disk contact: one arc each, always admissible. `radiusSum` = r_A + r_B [m] (the pair loop
/// keeps it per pair). Written without branches, so that the engine's pair loop vectorises: a
/// coincident pair (distance 0) gets a zero normal and must be excluded by the caller (the pair
/// loop tests d^2 > 0); every number stays finite.
inline ContactGeometry diskContact(double radiusA, double radiusSum, double dx, double dy) {
    ContactGeometry g;
    const double distance = std::sqrt(dx * dx + dy * dy);
    const double inv = 1.0 / std::max(distance, std::numeric_limits<double>::min());
    g.overlap = radiusSum - distance;
    g.normalX = dx * inv;
    g.normalY = dy * inv;
    const double reach = radiusA - 0.5 * g.overlap;
    g.pointX = reach * g.normalX;
    g.pointY = reach * g.normalY;
    return g;
}

namespace detail {

/// Tests arc `i` of A against arc `j` of B and keeps the pair if admissible with a smaller
/// overlap than the current best. (cA, sA), (cB, sB) are cos/sin of the orientations.
inline void tryArcPair(const OvalShape& A, double cA, double sA, int i, const OvalShape& B,
                       double cB, double sB, int j, double dx, double dy, ContactGeometry& best) {
    const Arc arcA = A.arcs()[i];
    const Arc arcB = B.arcs()[j];
    // Arc centres in the world frame, relative to A's centre.
    const double ax = cA * arcA.centreX - sA * arcA.centreY;
    const double ay = sA * arcA.centreX + cA * arcA.centreY;
    const double bx = dx + cB * arcB.centreX - sB * arcB.centreY;
    const double by = dy + sB * arcB.centreX + cB * arcB.centreY;
    const double wx = bx - ax, wy = by - ay;
    const double distance = std::sqrt(wx * wx + wy * wy);
    if (!(distance > 0.0)) {
        return;
    }
    const double ux = wx / distance, uy = wy / distance;
    // u in A's body frame must lie in arc i's normal range; -u in B's body frame in arc j's.
    if (!arcAdmits(A, i, cA * ux + sA * uy, -sA * ux + cA * uy)) {
        return;
    }
    if (!arcAdmits(B, j, -(cB * ux + sB * uy), -(-sB * ux + cB * uy))) {
        return;
    }
    const double overlap = arcA.radius + arcB.radius - distance;
    if (overlap < best.overlap || best.overlap == -std::numeric_limits<double>::infinity()) {
        best.overlap = overlap;
        best.normalX = ux;
        best.normalY = uy;
        const double reach = arcA.radius - 0.5 * overlap;
        best.pointX = ax + reach * ux;
        best.pointY = ay + reach * uy;
    }
}

} // namespace detail

/// Reference oval-oval contact given the cos and sin of the orientations: all 16 arc pairs, the
/// admissible one with the smallest overlap.
inline ContactGeometry ovalContactAllPairs(const OvalShape& A, double cA, double sA,
                                           const OvalShape& B, double cB, double sB, double dx,
                                           double dy) {
    ContactGeometry best;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            detail::tryArcPair(A, cA, sA, i, B, cB, sB, j, dx, dy, best);
        }
    }
    return best;
}

/// Reference oval-oval contact: all 16 arc pairs, the admissible one with the smallest overlap.
inline ContactGeometry ovalContactAllPairs(const OvalShape& A, double thetaA, const OvalShape& B,
                                           double thetaB, double dx, double dy) {
    return ovalContactAllPairs(A, std::cos(thetaA), std::sin(thetaA), B, std::cos(thetaB),
                               std::sin(thetaB), dx, dy);
}

/// What the quadrant kernel needs of a shape, computed once per shape (or grain) instead of per
/// contact: the arc centres' offsets and radii and the junction direction.
struct OvalArcs {
    double endOffset = 0;   ///< a - r: end arc centres at (+-(a - r), 0), body frame [m]
    double sideOffset = 0;  ///< R - b: side arc centres at (0, -+(R - b)), body frame [m]
    double endRadius = 0;   ///< r [m]
    double sideRadius = 0;  ///< R [m]
    double cosJunction = 1; ///< cos(phi)
    double sinJunction = 0; ///< sin(phi)
    double width = 0;       ///< W [m]
};

inline OvalArcs ovalArcs(const OvalShape& s) {
    // The same expressions as OvalShape::arcs(), so both kernels see the same bits.
    return {s.halfWidth - s.endRadius,
            s.sideRadius - s.halfHeight,
            s.endRadius,
            s.sideRadius,
            s.cosJunction,
            s.sinJunction,
            s.width};
}

/// Tolerance of oneFormArcs on the arcs at half-width 1: one form's constructions at several
/// widths differ by a few 1e-15 (each rounds its own way); 1e-12 of a millimetre grain is a
/// femtometre, far below any overlap.
inline constexpr double kOneFormTolerance = 1e-12;

/// True when every shape is an oval (or disk) of one form: its arcs divided by its half-width
/// equal those of shape 0 within kOneFormTolerance (an assembly of one aspect ratio and closure
/// at several widths). Then `unit` holds shape 0's arcs divided by its half-width (the form at
/// half-width 1, `width` 2), and a grain of half-width a has the arcs a * unit: the engine's pair
/// loop then reads a alone per grain instead of six numbers of arcs.
inline bool oneFormArcs(const std::vector<OvalShape>& shapes, OvalArcs& unit) {
    if (shapes.empty()) {
        return false;
    }
    const auto scaled = [](const OvalShape& s) {
        const OvalArcs arcs = ovalArcs(s);
        const double a = s.halfWidth;
        return OvalArcs{arcs.endOffset / a,
                        arcs.sideOffset / a,
                        arcs.endRadius / a,
                        arcs.sideRadius / a,
                        arcs.cosJunction,
                        arcs.sinJunction,
                        2.0};
    };
    const OvalArcs first = scaled(shapes.front());
    for (const OvalShape& s : shapes) {
        const OvalArcs u = scaled(s);
        const bool same = std::fabs(u.endOffset - first.endOffset) <= kOneFormTolerance &&
                          std::fabs(u.sideOffset - first.sideOffset) <= kOneFormTolerance &&
                          std::fabs(u.endRadius - first.endRadius) <= kOneFormTolerance &&
                          std::fabs(u.sideRadius - first.sideRadius) <= kOneFormTolerance &&
                          std::fabs(u.cosJunction - first.cosJunction) <= kOneFormTolerance &&
                          std::fabs(u.sinJunction - first.sinJunction) <= kOneFormTolerance;
        if (!same) {
            return false;
        }
    }
    unit = first;
    return true;
}

/// The result of the quadrant kernel: the geometry, and whether the 16-pair reference must
/// decide instead.
struct QuadrantContact {
    ContactGeometry geometry;
    bool needsReference = false;
};

/// Oval-oval contact from the 4 arc pairs facing each other (the end arc and the side arc of
/// each grain in the quadrant facing the other grain), written without branches so that the
/// engine's pair loop vectorises (hence plain numbers by value: a struct passed by reference
/// in a simd loop stops GCC 12). Always returns finite numbers; asks for the 16-pair reference
/// when none of the 4 pairs is admissible, or past an overlap of 0.1 W (the quadrant choice
/// equals the reference up to ~0.18 W, tested; past 0.1 W is a blow-up anyway).
/// Per grain: arc offsets, radii and junction as in OvalArcs; (c, s) = cos, sin of orientation;
/// `smallerWidth` = min(W_A, W_B).
inline QuadrantContact ovalContactQuadrant(double endOffsetA, double sideOffsetA, double endRadiusA,
                                           double sideRadiusA, double cosJunctionA,
                                           double sinJunctionA, double cA, double sA,
                                           double endOffsetB, double sideOffsetB, double endRadiusB,
                                           double sideRadiusB, double cosJunctionB,
                                           double sinJunctionB, double cB, double sB, double dx,
                                           double dy, double smallerWidth) {
    // The other grain's direction in each body frame picks the facing end and side arcs.
    const double towardB1 = cA * dx + sA * dy, towardB2 = -sA * dx + cA * dy;
    const double towardA1 = -(cB * dx + sB * dy), towardA2 = -(-sB * dx + cB * dy);
    const double endSignA = towardB1 >= 0 ? 1.0 : -1.0, sideSignA = towardB2 >= 0 ? 1.0 : -1.0;
    const double endSignB = towardA1 >= 0 ? 1.0 : -1.0, sideSignB = towardA2 >= 0 ? 1.0 : -1.0;
    // Arc centres in the world frame relative to A's centre. The side arc facing +y (body) has
    // its centre at (0, -(R - b)).
    const double eA = endSignA * endOffsetA, sdA = sideSignA * sideOffsetA;
    const double eB = endSignB * endOffsetB, sdB = sideSignB * sideOffsetB;
    const double endA1 = cA * eA, endA2 = sA * eA;
    const double sideA1 = sA * sdA, sideA2 = -(cA * sdA);
    const double endB1 = dx + cB * eB, endB2 = dy + sB * eB;
    const double sideB1 = dx + sB * sdB, sideB2 = dy + -(cB * sdB);
    const double tolerance = kArcDirectionTolerance;

    double bestOverlap = 0, bestA1 = 0, bestA2 = 0, bestW1 = 0, bestW2 = 0, bestDistance = 1;
    double bestRadius = 0;
    bool found = false;
    // One candidate pair: arc of A (centre a, radius rA, end or side) against arc of B. The
    // admissibility of the direction u = w / |w| is tested on w itself (u . e >= c  <=>
    // w . e >= c |w|), so that only the chosen candidate is divided by its length.
    const auto consider = [&](double a1, double a2, double rA, bool endOfA, double b1, double b2,
                              double rB, bool endOfB, bool first) {
        const double w1 = b1 - a1, w2 = b2 - a2;
        const double distance = std::sqrt(w1 * w1 + w2 * w2);
        // w in A's body frame must lie in A's arc range, -w in B's body frame in B's.
        const double alongA =
            endOfA ? endSignA * (cA * w1 + sA * w2) : sideSignA * (-sA * w1 + cA * w2);
        const double limitA = (endOfA ? cosJunctionA : sinJunctionA) - tolerance;
        const double alongB =
            endOfB ? endSignB * -(cB * w1 + sB * w2) : sideSignB * -(-sB * w1 + cB * w2);
        const double limitB = (endOfB ? cosJunctionB : sinJunctionB) - tolerance;
        // & and |, not && and ||: no branches, so that the engine's loop vectorises.
        const bool admissible =
            (distance > 0.0) & (alongA >= limitA * distance) & (alongB >= limitB * distance);
        const double overlap = rA + rB - distance;
        // Keep the admissible pair with the smallest overlap (the first on ties); before any
        // is admissible, keep the first pair so that every number stays finite.
        const bool take = first | (admissible & (!found | (overlap < bestOverlap)));
        bestOverlap = take ? overlap : bestOverlap;
        bestA1 = take ? a1 : bestA1;
        bestA2 = take ? a2 : bestA2;
        bestW1 = take ? w1 : bestW1;
        bestW2 = take ? w2 : bestW2;
        bestDistance = take ? distance : bestDistance;
        bestRadius = take ? rA : bestRadius;
        found = found | admissible;
    };
    consider(endA1, endA2, endRadiusA, true, endB1, endB2, endRadiusB, true, true);
    consider(endA1, endA2, endRadiusA, true, sideB1, sideB2, sideRadiusB, false, false);
    consider(sideA1, sideA2, sideRadiusA, false, endB1, endB2, endRadiusB, true, false);
    consider(sideA1, sideA2, sideRadiusA, false, sideB1, sideB2, sideRadiusB, false, false);
    const double inv = 1.0 / std::max(bestDistance, std::numeric_limits<double>::min());
    const double bestU1 = bestW1 * inv, bestU2 = bestW2 * inv;
    QuadrantContact out;
    const double tooDeep = 0.1 * smallerWidth;
    out.needsReference = !found | (bestOverlap > tooDeep);
    out.geometry.overlap = bestOverlap;
    out.geometry.normalX = bestU1;
    out.geometry.normalY = bestU2;
    const double reach = bestRadius - 0.5 * bestOverlap;
    out.geometry.pointX = bestA1 + reach * bestU1;
    out.geometry.pointY = bestA2 + reach * bestU2;
    return out;
}

/// The quadrant kernel for two shapes' precomputed arcs.
inline QuadrantContact ovalContactQuadrant(const OvalArcs& A, double cA, double sA,
                                           const OvalArcs& B, double cB, double sB, double dx,
                                           double dy) {
    return ovalContactQuadrant(A.endOffset, A.sideOffset, A.endRadius, A.sideRadius, A.cosJunction,
                               A.sinJunction, cA, sA, B.endOffset, B.sideOffset, B.endRadius,
                               B.sideRadius, B.cosJunction, B.sinJunction, cB, sB, dx, dy,
                               std::min(A.width, B.width));
}

/// Oval-oval contact as the engine's pair loop decides it: the quadrant kernel (4 arc pairs,
/// minimum overlap; the vector loop calls it directly, with the same bits), and where it asks,
/// the 16-pair reference (the loop's deferred pairs). Agrees with ovalContactAllPairs (tested on
/// random pairs with large overlaps). (cA, sA), (cB, sB): cos and sin of the orientations.
inline ContactGeometry ovalContact(const OvalShape& A, double cA, double sA, const OvalShape& B,
                                   double cB, double sB, double dx, double dy) {
    const OvalArcs a = ovalArcs(A), b = ovalArcs(B);
    const QuadrantContact q = ovalContactQuadrant(a, cA, sA, b, cB, sB, dx, dy);
    return q.needsReference ? ovalContactAllPairs(A, cA, sA, B, cB, sB, dx, dy) : q.geometry;
}

} // namespace grainlab
