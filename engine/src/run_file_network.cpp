// A checkpoint's contact network in the run file (docs/formats.md, "Contacts", "Void cells",
// "Shape outlines"): what a reader needs to draw force chains, void cells and grains and to
// compute the contact measures without the oval geometry. Written from the engine's own
// ContactNetwork (Simulation::contactNetwork) and VoidCellSet (computeVoidCells), with the
// strong/weak split and the load-bearing graph of measures.h.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "grainlab/measures.h"
#include "grainlab/run_file.h"
#include "run_file_io.h"

namespace grainlab {

namespace hdf5io {

void writeContacts(H5::Group& checkpoint, const ContactNetwork& network) {
    if (checkpoint.nameExists("contacts")) {
        checkpoint.unlink("contacts");
    }
    H5::Group g = checkpoint.createGroup("contacts");
    const std::size_t n = network.contacts.size();
    const ContactColumns c = contactColumns(network);
    // The engine's split (StrongForceThreshold::RmsForce, the measures' default): strong when
    // |f| = sqrt(f_n^2 + f_t^2) exceeds the threshold.
    const double threshold = strongForceThreshold(network, StrongForceThreshold::RmsForce);
    std::vector<std::uint8_t> strong(n);
    for (std::size_t k = 0; k < n; ++k) {
        strong[k] = std::hypot(c.normalForce[k], c.tangentialForce[k]) > threshold ? 1 : 0;
    }
    writeAttribute(g, "count", std::int64_t(n));
    writeAttribute(g, "strong_threshold", threshold);
    writeArray(g, "first", c.first, "-");
    writeArray(g, "second", c.second, "-");
    writeArray(g, "shift1", c.shift1, "-");
    writeArray(g, "shift2", c.shift2, "-");
    writeArray(g, "normal1", c.normal1, "-");
    writeArray(g, "normal2", c.normal2, "-");
    writeArray(g, "point1", c.point1, "m");
    writeArray(g, "point2", c.point2, "m");
    writeArray(g, "branch1", c.branch1, "m");
    writeArray(g, "branch2", c.branch2, "m");
    writeArray(g, "overlap", c.overlap, "m");
    writeArray(g, "normal_force", c.normalForce, "N");
    writeArray(g, "tangential_force", c.tangentialForce, "N");
    writeArray(g, "sliding", c.sliding, "-");
    writeArray(g, "strong", strong, "-");
    writeArray(g, "load_bearing", loadBearingGraph(network).contactInGraph, "-");
    writeArray(g, "centre1", network.x1, "m");
    writeArray(g, "centre2", network.x2, "m");
}

void writeVoidCells(H5::Group& checkpoint, const VoidCellSet& cells) {
    if (checkpoint.nameExists("void_cells")) {
        checkpoint.unlink("void_cells");
    }
    H5::Group g = checkpoint.createGroup("void_cells");
    std::vector<std::int32_t> valence, grains;
    std::vector<std::int64_t> offsets{0}, vertexOffsets{0};
    std::vector<double> area, elongation, direction, centroid1, centroid2;
    std::vector<double> j11, j22, j12, vertices1, vertices2;
    for (const VoidCell& c : cells.cells) {
        valence.push_back(c.valence);
        area.push_back(c.area);
        elongation.push_back(c.elongation);
        direction.push_back(c.direction);
        centroid1.push_back(c.centroid1);
        centroid2.push_back(c.centroid2);
        j11.push_back(c.secondMoment[0]);
        j22.push_back(c.secondMoment[1]);
        j12.push_back(c.secondMoment[2]);
        grains.insert(grains.end(), c.grains.begin(), c.grains.end());
        offsets.push_back(static_cast<std::int64_t>(grains.size()));
        // The polygon about its wrapped centroid: contiguous, and near the cell.
        for (std::size_t k = 0; k < c.vertices1.size(); ++k) {
            vertices1.push_back(c.centroid1 + c.vertices1[k]);
            vertices2.push_back(c.centroid2 + c.vertices2[k]);
        }
        vertexOffsets.push_back(static_cast<std::int64_t>(vertices1.size()));
    }
    writeArray(g, "valence", valence, "-");
    writeArray(g, "area", area, "m^2");
    writeArray(g, "elongation", elongation, "-");
    writeArray(g, "direction", direction, "rad");
    writeArray(g, "centroid1", centroid1, "m");
    writeArray(g, "centroid2", centroid2, "m");
    writeArray(g, "second_moment11", j11, "m^4");
    writeArray(g, "second_moment22", j22, "m^4");
    writeArray(g, "second_moment12", j12, "m^4");
    writeArray(g, "grains", grains, "-");
    writeArray(g, "grain_offsets", offsets, "-");
    writeArray(g, "vertices1", vertices1, "m");
    writeArray(g, "vertices2", vertices2, "m");
    writeArray(g, "vertex_offsets", vertexOffsets, "-");
    writeArray(g, "valence_histogram", cells.valenceHistogram, "-");
    writeAttribute(g, "mean_valence", cells.meanValence);
    writeAttribute(g, "cellular", static_cast<std::int32_t>(cells.cellular));
}

void writeShapeOutlines(H5::Group& checkpoint, const std::vector<OvalShape>& shapes) {
    constexpr int k = kShapeOutlinePoints;
    std::vector<double> x(shapes.size() * k), y(shapes.size() * k);
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        for (int i = 0; i < k; ++i) {
            // Even in the normal's angle: more points where the outline bends most (the ends).
            const auto p = shapes[s].boundaryPoint(2.0 * std::numbers::pi * i / k);
            x[s * k + i] = p[0];
            y[s * k + i] = p[1];
        }
    }
    writeMatrix(checkpoint, "shape_outline1", x, shapes.size(), k, "m");
    writeMatrix(checkpoint, "shape_outline2", y, shapes.size(), k, "m");
}

} // namespace hdf5io

using namespace hdf5io;

namespace {

template <class F>
auto withCheckpoint(const std::string& path, const std::string& name, const std::string& what,
                    F&& f) {
    return guarded(path, what + " of checkpoint " + name, [&] {
        const H5::H5File file = openRunFileToRead(path);
        return f(file.openGroup(checkpointGroup(name)));
    });
}

/// Refuses a column whose length is not `n` (a damaged or foreign file).
template <class T>
std::vector<T> column(const H5::Group& g, const std::string& name, std::size_t n) {
    std::vector<T> v = readArray<T>(g, name);
    if (v.size() != n) {
        throw std::runtime_error(fmt::format("dataset {}/{} has {} values, expected {}",
                                             objectName(g), name, v.size(), n));
    }
    return v;
}

/// A column of a group and the values it is read into.
template <class T>
struct Column {
    const char* name;
    std::vector<T>& values;
};
template <class T>
Column(const char*, std::vector<T>&) -> Column<T>;

/// Reads the column `first` and then each of `rest`, which must have as many values; returns
/// that count.
template <class T, class... U>
std::size_t readColumns(const H5::Group& g, Column<T> first, Column<U>... rest) {
    first.values = readArray<T>(g, first.name);
    const std::size_t n = first.values.size();
    ((rest.values = column<U>(g, rest.name, n)), ...);
    return n;
}

/// Reads the group `group` of checkpoint `name` with `read`; a T of its own when the checkpoint
/// has none (a file written before the group was).
template <class T, class Read>
T readCheckpointGroup(const std::string& path, const std::string& name, const char* group,
                      const std::string& what, Read read) {
    return withCheckpoint(path, name, what, [&](const H5::Group& cp) {
        return cp.nameExists(group) ? read(cp.openGroup(group)) : T{};
    });
}

/// Refuses CSR offsets that do not run from 0 to `size` without decreasing.
void checkOffsets(const std::vector<std::int64_t>& offsets, std::size_t size,
                  const std::string& what) {
    bool ok = !offsets.empty() && offsets.front() == 0 &&
              offsets.back() == static_cast<std::int64_t>(size);
    for (std::size_t k = 1; ok && k < offsets.size(); ++k) {
        ok = offsets[k] >= offsets[k - 1];
    }
    if (!ok) {
        throw std::runtime_error(
            fmt::format("{}: offsets that do not index {} values", what, size));
    }
}

} // namespace

StoredContacts readContacts(const std::string& path, const std::string& name) {
    return readCheckpointGroup<StoredContacts>(
        path, name, "contacts", "reading the contacts", [](const H5::Group& g) {
            StoredContacts c;
            readColumns(g, Column{"first", c.first}, Column{"second", c.second},
                        Column{"shift1", c.shift1}, Column{"shift2", c.shift2},
                        Column{"normal1", c.normal1}, Column{"normal2", c.normal2},
                        Column{"point1", c.point1}, Column{"point2", c.point2},
                        Column{"branch1", c.branch1}, Column{"branch2", c.branch2},
                        Column{"overlap", c.overlap}, Column{"normal_force", c.normalForce},
                        Column{"tangential_force", c.tangentialForce}, Column{"sliding", c.sliding},
                        Column{"strong", c.strong}, Column{"load_bearing", c.loadBearing});
            readColumns(g, Column{"centre1", c.centre1}, Column{"centre2", c.centre2});
            c.strongThreshold = readAttribute<double>(g, "strong_threshold");
            return c;
        });
}

StoredVoidCells readVoidCells(const std::string& path, const std::string& name) {
    return readCheckpointGroup<StoredVoidCells>(
        path, name, "void_cells", "reading the void cells", [](const H5::Group& g) {
            StoredVoidCells v;
            const std::size_t n =
                readColumns(g, Column{"valence", v.valence}, Column{"area", v.area},
                            Column{"centroid1", v.centroid1}, Column{"centroid2", v.centroid2},
                            Column{"elongation", v.elongation}, Column{"direction", v.direction});
            v.grains = readArray<std::int32_t>(g, "grains");
            v.grainOffsets = column<std::int64_t>(g, "grain_offsets", n + 1);
            checkOffsets(v.grainOffsets, v.grains.size(), objectName(g) + "/grain_offsets");
            v.valenceHistogram = readArray<std::int32_t>(g, "valence_histogram");
            if (g.nameExists("vertices1")) { // format 3 on
                v.secondMoment11 = column<double>(g, "second_moment11", n);
                v.secondMoment22 = column<double>(g, "second_moment22", n);
                v.secondMoment12 = column<double>(g, "second_moment12", n);
                readColumns(g, Column{"vertices1", v.vertices1}, Column{"vertices2", v.vertices2});
                v.vertexOffsets = column<std::int64_t>(g, "vertex_offsets", n + 1);
                checkOffsets(v.vertexOffsets, v.vertices1.size(),
                             objectName(g) + "/vertex_offsets");
            }
            return v;
        });
}

} // namespace grainlab
