#pragma once
// Void cells (docs/measures.md): the faces of the load-bearing contact graph embedded on the torus
// of the periodic cell, each edge drawn as the polyline centre -> contact point -> centre (planar
// for convex grains). Faces are found by face traversal of the rotation system: at each grain, its
// graph contacts sorted counter-clockwise by the angle of the contact point about the grain centre.
// Walks are carried in unwrapped coordinates (image shifts accumulated along the walk), so areas
// and shapes are exact on the torus.
//
// Pure functions of an immutable ContactNetwork: called at record or display time on whichever
// thread owns the network (the engine worker in the GUI, the main thread headless); the result
// is plain data and may be handed to any thread.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/contact_network.h"

namespace grainlab {

/// One void cell: a face of the load-bearing graph, traversed counter-clockwise (void on the
/// left), so its area is positive.
struct VoidCell {
    /// Grains met along the boundary walk, in counter-clockwise order. A grain appears twice when
    /// the walk passes it twice (a bridge of the graph inside the face).
    std::vector<std::int32_t> grains;
    std::int32_t valence = 0; ///< number of sides = grains on the walk [-]
    double area = 0;          ///< area enclosed by the centre/contact-point polyline [m^2]
    double centroid1 = 0;     ///< area centroid, wrapped into the cell [m]
    double centroid2 = 0;
    /// Ratio of the principal axes sqrt(J_max / J_min) of the polygon's central second moment of
    /// area (the axis ratio of the ellipse with the same second moment), >= 1 [-].
    double elongation = 1;
    /// Angle of the major principal axis from x1 towards x2, in (-pi/2, pi/2] [rad].
    double direction = 0;
    /// Central second moment of area J = integral of (x - c)(x - c)^T dA: J11, J22, J12 [m^4].
    std::array<double, 3> secondMoment{};
    /// Polygon vertices relative to the centroid, unwrapped (contiguous on the plane), in
    /// counter-clockwise order: grain centre, contact point, grain centre, ... (2 * valence
    /// vertices, the first is the centre of grains[0]) [m].
    std::vector<double> vertices1, vertices2;
};

/// All void cells of one contact network, with the summary the time series records.
struct VoidCellSet {
    std::vector<VoidCell> cells; ///< closed faces only (see openFaceCount); empty for a summary
    std::int32_t voidCount = 0;  ///< N_v, the closed faces (= cells.size() unless a summary) [-]
    double meanValence = 0;      ///< mean number of sides over the cells (0 if none) [-]
    /// valenceHistogram[k] = number of cells with k sides (size = largest valence + 1).
    std::vector<std::int32_t> valenceHistogram;
    double totalArea = 0; ///< sum of the cell areas [m^2]

    std::int32_t graphGrains = 0;         ///< V: grains with at least one graph contact [-]
    std::int32_t graphContacts = 0;       ///< E: contacts in the graph [-]
    std::int32_t faceCount = 0;           ///< F: all faces traced, closed or not [-]
    std::int32_t eulerCharacteristic = 0; ///< V - E + F (0 for a cellular embedding) [-]
    /// Faces that are not void cells: their walk winds around the torus (non-zero accumulated
    /// image shift) or encloses a non-positive area (the outside of a cluster that does not span
    /// the cell, or a degenerate ordering of contacts). Not included in `cells`.
    std::int32_t openFaceCount = 0;
    /// True when the graph is non-empty, V - E + F = 0 and every face is a closed void cell:
    /// then the cells tile the periodic cell and totalArea equals its area.
    bool cellular = false;
    /// Empty when `cellular`; otherwise a short explanation (for logs and the GUI).
    std::string problem;
};

/// Void cells of the subgraph of `network.contacts` selected by `contactInGraph` (one flag per
/// contact, non-zero = edge of the graph). Never throws on geometry: non-planar or
/// non-spanning graphs are reported through `cellular`, `openFaceCount` and `problem`. Throws
/// std::invalid_argument when the mask size or a grain index does not match the network.
/// With `shapes` false the set keeps only its summary (`cells` stays empty; every other field,
/// voidCount included, is what the full set has, bit for bit).
VoidCellSet computeVoidCells(const ContactNetwork& network,
                             const std::vector<std::uint8_t>& contactInGraph, bool shapes = true);

/// Void cells of the load-bearing graph of `network` (see loadBearingGraph in measures.h).
VoidCellSet computeVoidCells(const ContactNetwork& network);

} // namespace grainlab
