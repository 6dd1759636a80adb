// See geometry_map.h.
#include "grainlab/geometry_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/csv_series.h"
#include "grainlab/enum_names.h"
#include "grainlab/random.h"
#include "grainlab/simulation.h"
#include "grainlab/strict_json.h"
#include "map_preset.h"

namespace grainlab {
namespace {

constexpr double kPi = std::numbers::pi;

using map_preset::csvNumber;
using map_preset::requiredNumbers;

/// The overlap of the two supports along world direction `angle` [m].
struct SupportOverlap {
    const OvalShape& A;
    const OvalShape& B;
    double cA, sA, cB, sB, dx, dy;

    double operator()(double angle) const { return along(std::cos(angle), std::sin(angle)); }

    double along(double d1, double d2) const {
        // d in A's body frame; -d in B's.
        const double a = ovalSupport(A, cA * d1 + sA * d2, -sA * d1 + cA * d2);
        const double b = ovalSupport(B, -(cB * d1 + sB * d2), -(-sB * d1 + cB * d2));
        return a + b - (d1 * dx + d2 * dy);
    }
};

/// The geometry preset's own keys.
void readGeometryKeys(const std::string& /*file*/, const JsonSection& top, GeometryMapSpec& spec) {
    spec.pairs = int(top.integer("pairs", 1, 1000000, spec.pairs));
    spec.smallestWidth = top.number("smallest_width", closed(1e-9, 1e3), spec.smallestWidth);
    spec.tolerance = top.number("tolerance", open(0, 1), spec.tolerance);
    spec.angleTolerance = top.number("angle_tolerance", open(0, 1), spec.angleTolerance);
    spec.seed = std::uint64_t(top.integer("seed", 0, std::int64_t(1) << 53, 1));
    const JsonSection axes = top.child("axes", {"aspect_ratio", "size_ratio", "overlap"}, true,
                                       "an object with aspect_ratio, size_ratio and overlap");
    spec.aspectRatios = requiredNumbers(axes, "aspect_ratio", Range{0.2, 1.0, true, false});
    spec.sizeRatios = requiredNumbers(axes, "size_ratio", closed(1, 10));
    spec.overlaps = requiredNumbers(axes, "overlap", Range{0, 2, false, true});
    if (!std::is_sorted(spec.overlaps.begin(), spec.overlaps.end())) {
        axes.refuse("overlap", axes.at("overlap"), "fractions in (0, 2], ascending");
    }
}

} // namespace

GeometryMapSpec readGeometryPreset(const std::string& path) {
    return map_preset::readPresetFile(path, parseGeometryPreset);
}

GeometryMapSpec parseGeometryPreset(const std::string& text, const std::string& file) {
    return map_preset::parsePreset<GeometryMapSpec>(
        text, file, "geometry", std::nullopt,
        {"pairs", "smallest_width", "tolerance", "angle_tolerance", "seed", "axes"},
        readGeometryKeys);
}

double ovalSupport(const OvalShape& s, double ux, double uy) {
    // The arc whose normal range holds u supports the oval in direction u; its support is the
    // centre's projection plus the radius (continuous across the junctions by tangency).
    const double end = s.halfWidth - s.endRadius, side = s.sideRadius - s.halfHeight;
    if (ux >= s.cosJunction) {
        return ux * end + s.endRadius;
    }
    if (ux <= -s.cosJunction) {
        return -ux * end + s.endRadius;
    }
    return (uy >= 0.0 ? -uy : uy) * side + s.sideRadius;
}

ExactOverlap exactOvalOverlap(const OvalShape& A, double cA, double sA, const OvalShape& B,
                              double cB, double sB, double dx, double dy, int samples) {
    const SupportOverlap f{A, B, cA, sA, cB, sB, dx, dy};
    auto value = std::vector<double>(std::size_t(samples));
    const double step = 2 * kPi / samples;
    // The scan's directions, once per sample count (most calls use the default).
    static const std::vector<double> defaultTable = [] {
        std::vector<double> t;
        for (int k = 0; k < 1440; ++k) {
            t.push_back(std::cos(k * 2 * kPi / 1440));
            t.push_back(std::sin(k * 2 * kPi / 1440));
        }
        return t;
    }();
    for (int k = 0; k < samples; ++k) {
        value[std::size_t(k)] = samples == 1440 ? f.along(defaultTable[std::size_t(2 * k)],
                                                          defaultTable[std::size_t(2 * k + 1)])
                                                : f(k * step);
    }
    ExactOverlap best{std::numeric_limits<double>::infinity(), 0};
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int k = 0; k < samples; ++k) {
        const double v = value[std::size_t(k)];
        if (v > value[std::size_t((k + 1) % samples)] ||
            v > value[std::size_t((k + samples - 1) % samples)]) {
            continue;
        }
        // A local minimum of the scan: golden section over the two samples either side. The
        // overlap is smooth (the ovals are strictly convex with continuous tangents), so the
        // minimum's value is found to round-off long before the bracket closes.
        double lo = (k - 2) * step, hi = (k + 2) * step;
        double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        double fa = f(a), fb = f(b);
        for (int it = 0; it < 90; ++it) {
            if (fa < fb) {
                hi = b;
                b = a;
                fb = fa;
                a = hi - g * (hi - lo);
                fa = f(a);
            } else {
                lo = a;
                a = b;
                fa = fb;
                b = lo + g * (hi - lo);
                fb = f(b);
            }
        }
        const double angle = 0.5 * (lo + hi);
        const double at = std::min({f(angle), fa, fb});
        if (at < best.overlap) {
            best = {at, std::remainder(angle, 2 * kPi)};
        }
    }
    return best;
}

KernelContact engineContact(const OvalShape& A, double thetaA, const OvalShape& B, double thetaB,
                            double dx, double dy) {
    SimulationState s;
    s.shapes = {A, B};
    s.grains.resize(2);
    // A cell wide enough that B's only image near A is the one at (dx, dy).
    const double side = 10.0 * std::max(A.width, B.width);
    s.cell = {side, 0.0, 0.0, side};
    s.grains.x1 = {0.5 * side, 0.5 * side + dx};
    s.grains.x2 = {0.5 * side, 0.5 * side + dy};
    s.grains.theta = {thetaA, thetaB};
    s.grains.shape = {0, 1};
    s.parameters.friction = 0.0;
    s.parameters.threads = 1;
    // Read the geometry only: no time-step check (nothing is stepped).
    s.parameters.stability.unguarded = true;
    const Simulation sim(std::move(s));
    const ContactNetwork net = sim.contactNetwork();
    KernelContact out;
    if (!net.contacts.empty()) {
        const ContactRecord& c = net.contacts.front();
        out.touching = true;
        out.overlap = c.overlap;
        out.normalAngle = std::atan2(c.normal2, c.normal1);
    }
    return out;
}

std::string geometryKernelName(GeometryKernel kernel) {
    static constexpr EnumName<GeometryKernel> kNames[] = {
        {GeometryKernel::Engine, "engine"},
        {GeometryKernel::SixteenPair, "sixteen_pair"},
        {GeometryKernel::FourPair, "four_pair"}};
    return enumName(kNames, kernel, "engine");
}

std::vector<GeometryLevel> measureGeometryMap(const GeometryMapSpec& spec,
                                              const OverlapReference& reference) {
    std::vector<GeometryLevel> out;
    std::uint64_t stream = 0;
    for (double eta : spec.aspectRatios) {
        for (double ratio : spec.sizeRatios) {
            for (double level : spec.overlaps) {
                // One stream per level, so that a level's pairs do not depend on the others.
                Random random(spec.seed * 0x9e3779b97f4a7c15ULL + (++stream));
                GeometryLevel row;
                row.aspectRatio = eta;
                row.sizeRatio = ratio;
                row.overlap = level;
                const int attempts = 20 * spec.pairs;
                for (int attempt = 0; attempt < attempts && row.pairs < spec.pairs; ++attempt) {
                    const double width = random.uniform(spec.smallestWidth, 2 * spec.smallestWidth);
                    const OvalShape A = makeOval(width, eta), B = makeOval(ratio * width, eta);
                    const double thetaA = random.uniform(-kPi, kPi);
                    const double thetaB = random.uniform(-kPi, kPi);
                    const double direction = random.uniform(-kPi, kPi);
                    const double cA = std::cos(thetaA), sA = std::sin(thetaA);
                    const double cB = std::cos(thetaB), sB = std::sin(thetaB);
                    const double c = std::cos(direction), s = std::sin(direction);
                    const double target = level * A.width;
                    const auto exactAt = [&](double distance) {
                        return exactOvalOverlap(A, cA, sA, B, cB, sB, distance * c, distance * s);
                    };
                    // Apart, the exact overlap is concave in the distance along a fixed
                    // direction, so it crosses the target once between the centres' meeting
                    // (if deep enough there) and the bounding circles' touching.
                    if (!(exactAt(0.0).overlap > target)) {
                        ++row.unreachable;
                        continue;
                    }
                    double lo = 0.0, hi = A.halfWidth + B.halfWidth;
                    for (int it = 0; it < 60; ++it) {
                        const double mid = 0.5 * (lo + hi);
                        (exactAt(mid).overlap > target ? lo : hi) = mid;
                    }
                    const double dx = 0.5 * (lo + hi) * c, dy = 0.5 * (lo + hi) * s;
                    const ExactOverlap exact = reference
                                                   ? reference(A, cA, sA, B, cB, sB, dx, dy)
                                                   : exactOvalOverlap(A, cA, sA, B, cB, sB, dx, dy);
                    ++row.pairs;

                    KernelContact found[3];
                    found[0] = engineContact(A, thetaA, B, thetaB, dx, dy);
                    const ContactGeometry all = ovalContactAllPairs(A, cA, sA, B, cB, sB, dx, dy);
                    found[1] = {all.overlap > 0.0, all.overlap,
                                std::atan2(all.normalY, all.normalX)};
                    // The engine without its overlap threshold: the 4 facing pairs decide
                    // unless none is admissible (an infinite width never asks for the 16).
                    const OvalArcs a = ovalArcs(A), b = ovalArcs(B);
                    const QuadrantContact quad = ovalContactQuadrant(
                        a.endOffset, a.sideOffset, a.endRadius, a.sideRadius, a.cosJunction,
                        a.sinJunction, cA, sA, b.endOffset, b.sideOffset, b.endRadius, b.sideRadius,
                        b.cosJunction, b.sinJunction, cB, sB, dx, dy,
                        std::numeric_limits<double>::infinity());
                    const ContactGeometry four = quad.needsReference ? all : quad.geometry;
                    found[2] = {four.overlap > 0.0, four.overlap,
                                std::atan2(four.normalY, four.normalX)};
                    for (int k = 0; k < 3; ++k) {
                        KernelDeparture& d = row.kernels[k];
                        const double departure =
                            found[k].touching
                                ? std::fabs(found[k].overlap - exact.overlap) / A.width
                                : std::fabs(exact.overlap) / A.width; // the contact was missed
                        const double angle =
                            found[k].touching
                                ? std::fabs(std::remainder(found[k].normalAngle - exact.normalAngle,
                                                           2 * kPi))
                                : kPi;
                        d.maxDeparture = std::max(d.maxDeparture, departure);
                        d.maxNormalError = std::max(d.maxNormalError, angle);
                        d.departures += departure > spec.tolerance ? 1 : 0;
                        d.wrongNormals += angle > spec.angleTolerance ? 1 : 0;
                    }
                }
                out.push_back(row);
            }
        }
    }
    return out;
}

std::vector<GeometryLine> geometryLines(const GeometryMapSpec& spec,
                                        const std::vector<GeometryLevel>& levels) {
    std::vector<GeometryLine> out;
    for (double eta : spec.aspectRatios) {
        GeometryLine line;
        line.aspectRatio = eta;
        for (const GeometryLevel& l : levels) {
            if (l.aspectRatio != eta || l.pairs == 0) {
                continue;
            }
            line.largestMeasured = std::max(line.largestMeasured, l.overlap);
            for (int k = 0; k < 3; ++k) {
                const KernelDeparture& d = l.kernels[k];
                if ((d.departures > 0 || d.wrongNormals > 0) &&
                    (line.departureStart[k] == 0 || l.overlap < line.departureStart[k])) {
                    line.departureStart[k] = l.overlap;
                }
            }
        }
        for (const GeometryLevel& l : levels) {
            for (int k = 0; k < 3; ++k) {
                if (l.aspectRatio == eta && line.departureStart[k] > 0 &&
                    l.overlap >= line.departureStart[k]) {
                    line.departureBeyond[k] =
                        std::max(line.departureBeyond[k], l.kernels[k].maxDeparture);
                }
            }
        }
        out.push_back(line);
    }
    return out;
}

std::string geometryCsv(const std::vector<GeometryLevel>& levels) {
    std::string s = csvLine({"aspect_ratio [-]", "size_ratio [-]", "overlap_fraction [-]", "kernel",
                             "pairs [-]", "unreachable [-]", "max_departure [-]", "departures [-]",
                             "wrong_normals [-]", "max_normal_error [rad]"});
    for (const GeometryLevel& l : levels) {
        for (int k = 0; k < 3; ++k) {
            const KernelDeparture& d = l.kernels[k];
            s += csvLine({csvNumber(l.aspectRatio), csvNumber(l.sizeRatio), csvNumber(l.overlap),
                          geometryKernelName(GeometryKernel(k)), std::to_string(l.pairs),
                          std::to_string(l.unreachable), csvNumber(d.maxDeparture),
                          std::to_string(d.departures), std::to_string(d.wrongNormals),
                          csvNumber(d.maxNormalError)});
        }
    }
    return s;
}

std::string geometryLimitsCsv(const std::vector<GeometryLine>& lines, double guard) {
    std::string s =
        csvLine({"aspect_ratio [-]", "kernel", "departure_found", "departure_start [-]",
                 "departure_beyond [-]", "largest_measured [-]", "guard [-]", "margin [-]"});
    for (const GeometryLine& l : lines) {
        for (int k = 0; k < 3; ++k) {
            const double start = l.departureStart[k];
            // No departure up to the largest level: the margin is at least largest / guard.
            s += csvLine({csvNumber(l.aspectRatio), geometryKernelName(GeometryKernel(k)),
                          start > 0 ? "yes" : "no", start > 0 ? csvNumber(start) : std::string(),
                          start > 0 ? csvNumber(l.departureBeyond[k]) : std::string(),
                          csvNumber(l.largestMeasured), csvNumber(guard),
                          csvNumber((start > 0 ? start : l.largestMeasured) / guard)});
        }
    }
    return s;
}

} // namespace grainlab
