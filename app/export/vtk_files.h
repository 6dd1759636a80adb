#pragma once
// VTK XML files written without VTK (docs/paraview.md): a polygon or line data set (.vtp, VTK's
// PolyData) with its cell and field arrays in raw appended binary, and the .pvd collection that
// lists them by time. The format is VTK's "XML File Formats" (vtk.org, VTK file formats):
// little-endian, UInt64 block headers, no compression. Plain data and free functions; any
// thread. The pieces are built by vtk_export.h.

#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

/// One named array of a data set: `components` numbers per tuple, of one type.
struct VtkArray {
    enum class Type { Float64, Int64, Int32, UInt8 };
    std::string name;
    Type type = Type::Float64;
    int components = 1;
    std::vector<double> float64;
    std::vector<std::int64_t> int64;
    std::vector<std::int32_t> int32;
    std::vector<std::uint8_t> uint8;

    std::size_t values() const;
    std::size_t tuples() const { return values() / static_cast<std::size_t>(components); }
};

VtkArray float64Array(std::string name, std::vector<double> values, int components = 1);
VtkArray int64Array(std::string name, std::vector<std::int64_t> values);
VtkArray int32Array(std::string name, std::vector<std::int32_t> values);
VtkArray uint8Array(std::string name, std::vector<std::uint8_t> values);

/// A PolyData piece whose cells are all lines or all polygons (VTK orders a PolyData's cells
/// verts, lines, strips, polys: with one kind the cell arrays follow the cells as given).
struct VtkPolyData {
    enum class Cells { Lines, Polygons };
    Cells cells = Cells::Polygons;
    std::vector<double> points;             ///< x, y, z per point [m]
    std::vector<std::int64_t> connectivity; ///< point indices of every cell, in order
    std::vector<std::int64_t> offsets;      ///< end of each cell in `connectivity`
    std::vector<VtkArray> cellData;         ///< one tuple per cell
    std::vector<VtkArray> fieldData;        ///< of the whole data set (step, eps1, ...)

    std::size_t cellCount() const { return offsets.size(); }
    std::size_t pointCount() const { return points.size() / 3; }
    /// Appends a cell of the points (x1, x2) given as pairs (z = 0).
    void addCell(const std::vector<double>& x1, const std::vector<double>& x2);
};

/// Writes `data` as a .vtp file at `path` (raw appended binary). Throws std::runtime_error
/// naming the file when it cannot be written, or std::invalid_argument when an array's tuple
/// count does not match the cells.
void writeVtp(const std::string& path, const VtkPolyData& data);

/// One file of a .pvd collection: its time, its part (data sets of the same time) and its path
/// relative to the .pvd.
struct PvdEntry {
    double time = 0;
    int part = 0;
    std::string name; ///< the part's name, e.g. "grains"
    std::string file;
};
/// Writes the .pvd collection at `path`; `comment` goes into an XML comment (no "--" in it).
void writePvd(const std::string& path, const std::vector<PvdEntry>& entries,
              const std::string& comment = {});

} // namespace grainlab
