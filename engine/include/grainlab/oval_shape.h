#pragma once
// The four-arc oval (docs/physics.md): two end arcs of radius r and two side arcs of radius R
// joined with a common tangent. Owns the geometry of one grain shape in its body frame: arc
// centres, radii, the junction angle, area and polar moment. Pure functions of plain numbers; used
// by the contact kernels (hot loop), the generator, the measures and the renderers on any thread.
//
// Body frame: the major axis (width W = 2a) along x, the minor axis (height H = 2b) along y.

#include <array>
#include <string>

namespace grainlab {

/// Which free parameter closes the four-arc construction.
enum class OvalClosure {
    EqualArea,      ///< r chosen so that the oval's area equals the ellipse's, pi a b (default)
    EndRadiusRatio, ///< r = endRadiusRatio * W, given
};

/// One circular arc of an oval in the body frame.
struct Arc {
    double centreX; ///< arc centre, body frame [m]
    double centreY; ///< arc centre, body frame [m]
    double radius;  ///< [m]
};

/// Index of the four arcs: right end, top side, left end, bottom side.
enum ArcIndex : int { kRightEnd = 0, kTopSide = 1, kLeftEnd = 2, kBottomSide = 3 };

struct OvalShape {
    double width = 0;         ///< W = 2a [m]
    double height = 0;        ///< H = 2b [m]
    double halfWidth = 0;     ///< a [m], also the bounding-circle radius
    double halfHeight = 0;    ///< b [m]
    double endRadius = 0;     ///< r [m]
    double sideRadius = 0;    ///< R [m]
    double junctionAngle = 0; ///< phi [rad]: end arcs cover normals -phi..phi
    double cosJunction = 1;   ///< cos(phi)
    double sinJunction = 0;   ///< sin(phi)
    double area = 0;          ///< [m^2]
    double polarMoment = 0;   ///< J = integral of |x|^2 dA about the centre [m^4]
    bool isDisk = false;      ///< aspect ratio 1: a disk of radius a (fast path)

    /// The four arcs in order: right end, top side, left end, bottom side.
    std::array<Arc, 4> arcs() const;
    /// Equivalent diameter sqrt(4 A / pi) [m].
    double equivalentDiameter() const;
    /// Point of the outline whose outward normal has angle `normalAngle` (body frame) [m].
    std::array<double, 2> boundaryPoint(double normalAngle) const;
};

/// Builds an oval of width `width` [m] and aspect ratio `aspectRatio` = H/W in (0, 1].
/// With OvalClosure::EndRadiusRatio, `endRadiusRatio` = r/W must lie in (0, aspectRatio/2).
/// Throws std::invalid_argument naming the parameter and its allowed range otherwise.
OvalShape makeOval(double width, double aspectRatio, OvalClosure closure = OvalClosure::EqualArea,
                   double endRadiusRatio = 0.0);

/// Area of a four-arc oval from its arc parameters [m^2], in closed form:
/// A = 2 phi r^2 + (pi - 2 phi) R^2 - (R - r)^2 sin 2 phi.
double ovalArea(double endRadius, double sideRadius, double junctionAngle);

/// Tolerance on direction tests so that a junction direction belongs to both arcs.
inline constexpr double kArcDirectionTolerance = 1e-9;

/// True when the body-frame unit direction (dx, dy) lies in arc `arc`'s normal range.
inline bool arcAdmits(const OvalShape& s, int arc, double dx, double dy) {
    switch (arc) {
    case kRightEnd:
        return dx >= s.cosJunction - kArcDirectionTolerance;
    case kTopSide:
        return dy >= s.sinJunction - kArcDirectionTolerance;
    case kLeftEnd:
        return dx <= -s.cosJunction + kArcDirectionTolerance;
    default:
        return dy <= -s.sinJunction + kArcDirectionTolerance;
    }
}

} // namespace grainlab
