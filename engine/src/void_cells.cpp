#include "grainlab/void_cells.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/measures.h"
#include "grainlab/periodic_cell.h"

namespace grainlab {

namespace {

/// Largest reported elongation: a polygon whose minor second moment vanishes (a face pinched to
/// a line by round-off) gets this instead of an infinity.
constexpr double kMaxElongation = 1e6;

/// The graph as half-edges: contact e of the graph gives half-edge 2e out of A (towards B's
/// image) and 2e + 1 out of B (towards A's image); twin(h) = h ^ 1. Each half-edge knows the
/// vectors from its origin's centre to the contact point and to the far centre, and the image
/// shift it crosses, so a walk can be carried on the plane.
struct HalfEdges {
    std::vector<std::int32_t> origin;
    std::vector<double> point1, point2; ///< contact point minus origin centre [m]
    std::vector<double> reach1, reach2; ///< far centre minus origin centre [m]
    std::vector<std::int32_t> shift1, shift2;
    // Rotation system: half-edges out of grain g, counter-clockwise, are
    // rotation[rotationStart[g] .. rotationStart[g + 1]); position[h] is h's index there.
    std::vector<std::int32_t> rotationStart, rotation, position;

    std::size_t size() const { return origin.size(); }

    /// The half-edge after h along its face: at the far grain, the one just clockwise of the
    /// way back, so that the face lies on the left and is traversed counter-clockwise.
    std::int32_t next(std::int32_t h) const {
        const std::int32_t back = h ^ 1;
        const std::int32_t g = origin[back];
        const std::int32_t first = rotationStart[g];
        const std::int32_t degree = rotationStart[g + 1] - first;
        const std::int32_t k = position[back];
        return rotation[first + (k == 0 ? degree - 1 : k - 1)];
    }
};

HalfEdges buildHalfEdges(const ContactNetwork& network, const std::vector<std::uint8_t>& inGraph) {
    HalfEdges he;
    const auto count =
        2 * static_cast<std::size_t>(std::count_if(inGraph.begin(), inGraph.end(),
                                                   [](std::uint8_t k) { return k != 0; }));
    for (auto* v : {&he.point1, &he.point2, &he.reach1, &he.reach2}) {
        v->reserve(count);
    }
    for (auto* v : {&he.origin, &he.shift1, &he.shift2}) {
        v->reserve(count);
    }
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        if (!inGraph[c]) {
            continue;
        }
        const ContactRecord& r = network.contacts[c];
        // Out of A: to the contact point, then on to B's image.
        he.origin.push_back(r.first);
        he.point1.push_back(r.point1);
        he.point2.push_back(r.point2);
        he.reach1.push_back(r.branch1);
        he.reach2.push_back(r.branch2);
        he.shift1.push_back(r.shift1);
        he.shift2.push_back(r.shift2);
        // Out of B's image: the same contact point seen from B, then back to A.
        he.origin.push_back(r.second);
        he.point1.push_back(r.point1 - r.branch1);
        he.point2.push_back(r.point2 - r.branch2);
        he.reach1.push_back(-r.branch1);
        he.reach2.push_back(-r.branch2);
        he.shift1.push_back(-r.shift1);
        he.shift2.push_back(-r.shift2);
    }
    const std::int32_t n = network.grainCount;
    const std::int32_t halfEdgeCount = static_cast<std::int32_t>(he.size());
    he.rotationStart.assign(n + 1, 0);
    for (std::int32_t h = 0; h < halfEdgeCount; ++h) {
        ++he.rotationStart[he.origin[h] + 1];
    }
    for (std::int32_t g = 0; g < n; ++g) {
        he.rotationStart[g + 1] += he.rotationStart[g];
    }
    he.rotation.resize(halfEdgeCount);
    std::vector<std::int32_t> fill(he.rotationStart.begin(), he.rotationStart.end() - 1);
    for (std::int32_t h = 0; h < halfEdgeCount; ++h) {
        he.rotation[fill[he.origin[h]]++] = h;
    }
    std::vector<double> angle(halfEdgeCount);
    for (std::int32_t h = 0; h < halfEdgeCount; ++h) {
        angle[h] = std::atan2(he.point2[h], he.point1[h]);
    }
    he.position.resize(halfEdgeCount);
    for (std::int32_t g = 0; g < n; ++g) {
        const auto begin = he.rotation.begin() + he.rotationStart[g];
        const auto end = he.rotation.begin() + he.rotationStart[g + 1];
        // Ties (never expected from real contacts) are broken by index, for determinism.
        std::sort(begin, end, [&](std::int32_t a, std::int32_t b) {
            return angle[a] < angle[b] || (angle[a] == angle[b] && a < b);
        });
        for (auto it = begin; it != end; ++it) {
            he.position[*it] =
                static_cast<std::int32_t>(it - he.rotation.begin()) - he.rotationStart[g];
        }
    }
    return he;
}

/// Area, centroid, second moment and principal axes of a closed face from its polyline
/// vertices (relative to the walk's first centre); shifts the vertices to the centroid.
/// Returns false, leaving the rest untouched, when the area is not above minimumArea; without
/// `shapes`, stops after the area.
bool fillShape(VoidCell& cell, double origin1, double origin2, const CellMatrix& h,
               double minimumArea, bool shapes) {
    auto& v1 = cell.vertices1;
    auto& v2 = cell.vertices2;
    const std::size_t n = v1.size();
    double twiceArea = 0, c1 = 0, c2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const double cross = v1[i] * v2[j] - v1[j] * v2[i];
        twiceArea += cross;
        c1 += (v1[i] + v1[j]) * cross;
        c2 += (v2[i] + v2[j]) * cross;
    }
    cell.area = 0.5 * twiceArea;
    if (!(cell.area > minimumArea)) {
        return false;
    }
    if (!shapes) {
        return true;
    }
    c1 /= 3.0 * twiceArea;
    c2 /= 3.0 * twiceArea;
    // Second pass about the centroid: the central moments without cancellation.
    double j11 = 0, j22 = 0, j12 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        v1[i] -= c1;
        v2[i] -= c2;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const double cross = v1[i] * v2[j] - v1[j] * v2[i];
        j11 += (v1[i] * v1[i] + v1[i] * v1[j] + v1[j] * v1[j]) * cross;
        j22 += (v2[i] * v2[i] + v2[i] * v2[j] + v2[j] * v2[j]) * cross;
        j12 += (2.0 * v1[i] * v2[i] + v1[i] * v2[j] + v1[j] * v2[i] + 2.0 * v1[j] * v2[j]) * cross;
    }
    j11 /= 12.0;
    j22 /= 12.0;
    j12 /= 24.0;
    cell.secondMoment = {j11, j22, j12};
    const double mean = 0.5 * (j11 + j22);
    const double radius = std::hypot(0.5 * (j11 - j22), j12);
    const double major = mean + radius, minor = mean - radius;
    cell.elongation =
        minor * kMaxElongation * kMaxElongation > major ? std::sqrt(major / minor) : kMaxElongation;
    double direction = 0.5 * std::atan2(2.0 * j12, j11 - j22);
    if (direction <= -0.5 * std::numbers::pi) {
        direction += std::numbers::pi;
    }
    cell.direction = direction;
    // Centroid wrapped into the cell [0, 1)^2 in fractional coordinates.
    const auto s = toFractional(h, origin1 + c1, origin2 + c2);
    const double s1 = s[0] - std::floor(s[0]), s2 = s[1] - std::floor(s[1]);
    cell.centroid1 = h[0] * s1 + h[2] * s2;
    cell.centroid2 = h[1] * s1 + h[3] * s2;
    return true;
}

} // namespace

VoidCellSet computeVoidCells(const ContactNetwork& network,
                             const std::vector<std::uint8_t>& contactInGraph, bool shapes) {
    const std::int32_t n = network.grainCount;
    if (contactInGraph.size() != network.contacts.size()) {
        throw std::invalid_argument(fmt::format("void cells: mask of {} entries for {} contacts",
                                                contactInGraph.size(), network.contacts.size()));
    }
    if (network.x1.size() != static_cast<std::size_t>(n) ||
        network.x2.size() != static_cast<std::size_t>(n)) {
        throw std::invalid_argument(
            fmt::format("void cells: {} positions for {} grains", network.x1.size(), n));
    }
    for (std::size_t c = 0; c < network.contacts.size(); ++c) {
        const ContactRecord& r = network.contacts[c];
        if (r.first < 0 || r.first >= n || r.second < 0 || r.second >= n) {
            throw std::invalid_argument(
                fmt::format("void cells: contact {} joins grains ({}, {}) outside 0..{}", c,
                            r.first, r.second, n - 1));
        }
    }

    const HalfEdges he = buildHalfEdges(network, contactInGraph);
    const std::int32_t halfEdgeCount = static_cast<std::int32_t>(he.size());
    VoidCellSet set;
    set.graphContacts = halfEdgeCount / 2;
    for (std::int32_t g = 0; g < n; ++g) {
        set.graphGrains += he.rotationStart[g + 1] > he.rotationStart[g] ? 1 : 0;
    }

    // Faces of a cellular embedding on the torus: F = E - V (Euler), the cells at most that.
    if (shapes) {
        set.cells.reserve(std::size_t(std::max(0, set.graphContacts - set.graphGrains)));
    }
    // A summary walks every face through this one cell, its vectors reused, instead of keeping
    // three heap blocks per cell.
    VoidCell scratch;
    std::int64_t totalSides = 0;
    std::vector<std::uint8_t> visited(halfEdgeCount, 0);
    for (std::int32_t start = 0; start < halfEdgeCount; ++start) {
        if (visited[start]) {
            continue;
        }
        ++set.faceCount;
        VoidCell fresh;
        VoidCell& cell = shapes ? fresh : scratch;
        cell.grains.clear();
        cell.vertices1.clear();
        cell.vertices2.clear();
        std::size_t sides = 0;
        for (std::int32_t h = start; sides == 0 || h != start; h = he.next(h)) {
            ++sides;
        }
        cell.grains.reserve(sides);
        cell.vertices1.reserve(2 * sides);
        cell.vertices2.reserve(2 * sides);
        double p1 = 0, p2 = 0, scale = 0;
        std::int64_t winding1 = 0, winding2 = 0;
        // next() is a permutation of the half-edges, so the walk returns to `start`.
        for (std::int32_t h = start; !visited[h]; h = he.next(h)) {
            visited[h] = 1;
            cell.grains.push_back(he.origin[h]);
            cell.vertices1.insert(cell.vertices1.end(), {p1, p1 + he.point1[h]});
            cell.vertices2.insert(cell.vertices2.end(), {p2, p2 + he.point2[h]});
            p1 += he.reach1[h];
            p2 += he.reach2[h];
            scale += he.reach1[h] * he.reach1[h] + he.reach2[h] * he.reach2[h];
            winding1 += he.shift1[h];
            winding2 += he.shift2[h];
        }
        // A face that winds around the torus is no void cell (the graph does not span the cell
        // in that direction); neither is one enclosing no positive area (the outside of a
        // cluster, or contacts ordered inconsistently: a non-planar drawing).
        if (winding1 != 0 || winding2 != 0) {
            ++set.openFaceCount;
            continue;
        }
        const std::int32_t o = cell.grains.front();
        if (!fillShape(cell, network.x1[o], network.x2[o], network.cell, 1e-12 * scale, shapes)) {
            ++set.openFaceCount;
            continue;
        }
        cell.valence = static_cast<std::int32_t>(cell.grains.size());
        set.totalArea += cell.area;
        ++set.voidCount;
        totalSides += cell.valence;
        if (static_cast<std::size_t>(cell.valence) >= set.valenceHistogram.size()) {
            set.valenceHistogram.resize(cell.valence + 1, 0);
        }
        ++set.valenceHistogram[cell.valence];
        if (shapes) {
            set.cells.push_back(std::move(cell));
        }
    }

    if (set.voidCount > 0) {
        set.meanValence = static_cast<double>(totalSides) / set.voidCount;
    }
    set.eulerCharacteristic = set.graphGrains - set.graphContacts + set.faceCount;
    if (set.graphContacts == 0) {
        set.problem = "no contacts in the graph";
    } else if (set.openFaceCount > 0) {
        set.problem = fmt::format(
            "{} of {} faces wind around the cell or enclose no area: the graph does not span "
            "the cell, has a separate cluster, or is not drawn planar",
            set.openFaceCount, set.faceCount);
    } else if (set.eulerCharacteristic != 0) {
        set.problem =
            fmt::format("V - E + F = {} - {} + {} = {}, not 0: the graph is not one "
                        "cellular embedding on the torus",
                        set.graphGrains, set.graphContacts, set.faceCount, set.eulerCharacteristic);
    }
    set.cellular = set.problem.empty();
    return set;
}

VoidCellSet computeVoidCells(const ContactNetwork& network) {
    return computeVoidCells(network, loadBearingGraph(network).contactInGraph);
}

} // namespace grainlab
