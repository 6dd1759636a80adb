#pragma once
// The contact-geometry map of `grainlab stability` (a preset with "kind": "geometry",
// docs/stability.md): the overlap, as a fraction of the smaller width, at which the engine's
// four-arc contact departs from the exact overlap of the two ovals, or chooses another normal.
// Pairs of ovals at random orientations are placed at chosen exact overlaps; the exact overlap
// is the separating-axis definition itself (the penetration depth of two convex bodies is the
// smallest, over directions d, of h_A(d) + h_B(-d) - d . (x_B - x_A), h the support function),
// minimised numerically over d; the engine's overlap is read from a two-grain Simulation, so
// the map measures the production path (quadrant kernel, 16-pair fallback).
// The 16-pair reference, and the engine without the overlap threshold past which it hands a
// pair to the 16 (0.1 W), are measured beside it. Pure functions
// and plain data, any thread; the map runs in one process.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "grainlab/oval_shape.h"

namespace grainlab {

struct GeometryMapSpec {
    std::string name = "geometry";
    std::string sourcePath, sourceText;
    std::vector<double> aspectRatios{0.6};   ///< eta of both grains [-]
    std::vector<double> sizeRatios{1.0};     ///< W_B / W_A >= 1 [-]
    std::vector<double> overlaps{0.01, 0.1}; ///< exact overlap / smaller width, ascending [-]
    int pairs = 100;                         ///< random pairs per (eta, size ratio, overlap)
    double smallestWidth = 1e-3;             ///< W_A is drawn in [this, 2 this] [m]
    double tolerance = 1e-9;                 ///< a departure: |delta - exact| above this W_A [-]
    /// A wrong normal: the kernel's normal more than this from the exact one [rad].
    double angleTolerance = 1e-6;
    std::uint64_t seed = 1;
};

GeometryMapSpec readGeometryPreset(const std::string& path);
GeometryMapSpec parseGeometryPreset(const std::string& text, const std::string& sourceName);

/// The exact support function of an oval in body-frame unit direction (ux, uy): the supporting
/// arc's centre projected on u plus its radius [m].
double ovalSupport(const OvalShape& shape, double ux, double uy);

/// The exact penetration depth of two ovals and its direction: the minimum over d of
/// h_A(d) + h_B(-d) - d . (dx, dy), found by a scan of `samples` directions and a golden-section
/// refinement of every local minimum. Negative when apart (minus the distance). (cA, sA),
/// (cB, sB): cos and sin of the orientations; (dx, dy) = x_B - x_A [m].
struct ExactOverlap {
    double overlap = 0;     ///< [m]
    double normalAngle = 0; ///< of d, from A towards B [rad]
};
ExactOverlap exactOvalOverlap(const OvalShape& A, double cA, double sA, const OvalShape& B,
                              double cB, double sB, double dx, double dy, int samples = 1440);

/// The contact a kernel computed for one pair.
struct KernelContact {
    bool touching = false;  ///< the kernel reports a contact (overlap > 0)
    double overlap = 0;     ///< [m]
    double normalAngle = 0; ///< [rad]
};

/// The engine's contact of A at the origin with orientation thetaA and B at (dx, dy) with
/// thetaB, read from a two-grain Simulation's contact network (the production pair loop).
KernelContact engineContact(const OvalShape& A, double thetaA, const OvalShape& B, double thetaB,
                            double dx, double dy);

/// Which computation a row measures.
enum class GeometryKernel {
    Engine,      ///< the engine's pair loop, fallbacks included
    SixteenPair, ///< ovalContactAllPairs: every arc pair, the smallest admissible overlap
    /// The engine without its overlap threshold: the 4 facing arc pairs (ovalContactQuadrant)
    /// decide at every overlap, the 16 pairs only when none of the 4 is admissible.
    FourPair,
};
/// "engine", "sixteen_pair", "four_pair".
std::string geometryKernelName(GeometryKernel kernel);

/// What one kernel did over the pairs of one (eta, size ratio, overlap) level.
struct KernelDeparture {
    double maxDeparture = 0;   ///< largest |delta - exact| / W_A [-]
    int departures = 0;        ///< pairs with |delta - exact| > tolerance W_A (or no contact)
    int wrongNormals = 0;      ///< pairs whose normal is more than angleTolerance off
    double maxNormalError = 0; ///< largest normal angle error [rad]
};

struct GeometryLevel {
    double aspectRatio = 0, sizeRatio = 0, overlap = 0; ///< overlap / W_A [-]
    int pairs = 0;                                      ///< pairs measured
    int unreachable = 0; ///< pairs drawn whose orientation cannot overlap that much (skipped)
    KernelDeparture kernels[3]; ///< by GeometryKernel
};

/// The overlap each kernel is compared with; exactOvalOverlap unless a test plants another.
using OverlapReference =
    std::function<ExactOverlap(const OvalShape& A, double cA, double sA, const OvalShape& B,
                               double cB, double sB, double dx, double dy)>;

/// Measures every level of the map (seconds to minutes). Pairs are placed at each level's exact
/// overlap; the kernels are compared with `reference` (empty: the exact overlap).
std::vector<GeometryLevel> measureGeometryMap(const GeometryMapSpec& spec,
                                              const OverlapReference& reference = {});

/// The result of one aspect ratio over its size ratios.
struct GeometryLine {
    double aspectRatio = 0;
    /// The smallest overlap level at which the kernel departed (or chose another normal);
    /// 0 when none did up to the largest level measured.
    double departureStart[3] = {0, 0, 0};
    /// The largest departure over the levels at or beyond departureStart [-].
    double departureBeyond[3] = {0, 0, 0};
    double largestMeasured = 0; ///< the largest level with pairs [-]
};
std::vector<GeometryLine> geometryLines(const GeometryMapSpec& spec,
                                        const std::vector<GeometryLevel>& levels);

/// geometry.csv: one row per level and kernel; geometry_limits.csv: one row per aspect ratio
/// and kernel, with `guard` (the engine's overlap guard, a fraction of the smaller width) and
/// the margin: departure start / guard, or, when nothing departed, largest measured / guard (a
/// lower bound).
std::string geometryCsv(const std::vector<GeometryLevel>& levels);
std::string geometryLimitsCsv(const std::vector<GeometryLine>& lines, double guard);

} // namespace grainlab
