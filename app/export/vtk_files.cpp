// See vtk_files.h.
#include "export/vtk_files.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "common/markup_text.h"

namespace grainlab {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the .vtp files are written as little-endian");

/// `use(values, type)` with the member that holds `a`'s values (the one its type reads) and the
/// type's name in a .vtp file.
template <class Use>
auto withValues(const VtkArray& a, Use&& use) {
    switch (a.type) {
    case VtkArray::Type::Float64:
        return use(a.float64, "Float64");
    case VtkArray::Type::Int64:
        return use(a.int64, "Int64");
    case VtkArray::Type::Int32:
        return use(a.int32, "Int32");
    default:
        return use(a.uint8, "UInt8");
    }
}

/// The appended data block: each array is a UInt64 byte count followed by its bytes; the XML
/// refers to it by offsets from the block's start (after its leading '_').
class AppendedData {
public:
    /// Adds an array's bytes; returns its offset.
    std::uint64_t add(const void* bytes, std::uint64_t count) {
        const std::uint64_t offset = data_.size();
        const auto* header = reinterpret_cast<const char*>(&count);
        data_.insert(data_.end(), header, header + sizeof count);
        const auto* b = static_cast<const char*>(bytes);
        data_.insert(data_.end(), b, b + count);
        return offset;
    }
    const std::vector<char>& bytes() const { return data_; }

private:
    std::vector<char> data_;
};

std::string arrayElement(const VtkArray& a, AppendedData& appended, bool field,
                         const std::string& indent) {
    const auto [type, offset] = withValues(a, [&](const auto& values, const char* name) {
        return std::pair(name, appended.add(values.data(), values.size() * sizeof values[0]));
    });
    std::string tuples = field ? fmt::format(" NumberOfTuples=\"{}\"", a.tuples()) : std::string();
    return fmt::format("{}<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"{} "
                       "format=\"appended\" offset=\"{}\"/>\n",
                       indent, type, markupEscaped(a.name), a.components, tuples, offset);
}

} // namespace

std::size_t VtkArray::values() const {
    return withValues(*this, [](const auto& v, const char*) { return v.size(); });
}

namespace {

/// An array of `type`, its values in the member `field` (the one that type reads).
template <class T>
VtkArray typedArray(std::string name, VtkArray::Type type, std::vector<T> VtkArray::*field,
                    std::vector<T> values, int components = 1) {
    VtkArray a;
    a.name = std::move(name);
    a.type = type;
    a.components = components;
    a.*field = std::move(values);
    return a;
}

} // namespace

VtkArray float64Array(std::string name, std::vector<double> values, int components) {
    return typedArray(std::move(name), VtkArray::Type::Float64, &VtkArray::float64,
                      std::move(values), components);
}

VtkArray int64Array(std::string name, std::vector<std::int64_t> values) {
    return typedArray(std::move(name), VtkArray::Type::Int64, &VtkArray::int64, std::move(values));
}

VtkArray int32Array(std::string name, std::vector<std::int32_t> values) {
    return typedArray(std::move(name), VtkArray::Type::Int32, &VtkArray::int32, std::move(values));
}

VtkArray uint8Array(std::string name, std::vector<std::uint8_t> values) {
    return typedArray(std::move(name), VtkArray::Type::UInt8, &VtkArray::uint8, std::move(values));
}

void VtkPolyData::addCell(const std::vector<double>& x1, const std::vector<double>& x2) {
    for (std::size_t k = 0; k < x1.size(); ++k) {
        connectivity.push_back(static_cast<std::int64_t>(pointCount()));
        points.insert(points.end(), {x1[k], x2[k], 0.0});
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
}

void writeVtp(const std::string& path, const VtkPolyData& data) {
    for (const VtkArray& a : data.cellData) {
        if (a.values() != data.cellCount() * static_cast<std::size_t>(a.components)) {
            throw std::invalid_argument(fmt::format("{}: cell array {} has {} values for {} cells",
                                                    path, a.name, a.values(), data.cellCount()));
        }
    }
    AppendedData appended;
    const bool lines = data.cells == VtkPolyData::Cells::Lines;
    std::string xml = "<?xml version=\"1.0\"?>\n"
                      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                      "header_type=\"UInt64\">\n"
                      "  <PolyData>\n";
    if (!data.fieldData.empty()) {
        xml += "    <FieldData>\n";
        for (const VtkArray& a : data.fieldData) {
            xml += arrayElement(a, appended, true, "      ");
        }
        xml += "    </FieldData>\n";
    }
    xml +=
        fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" "
                    "NumberOfStrips=\"0\" NumberOfPolys=\"{}\">\n",
                    data.pointCount(), lines ? data.cellCount() : 0, lines ? 0 : data.cellCount());
    xml += "      <CellData>\n";
    for (const VtkArray& a : data.cellData) {
        xml += arrayElement(a, appended, false, "        ");
    }
    xml += "      </CellData>\n      <Points>\n";
    xml += arrayElement(float64Array("Points", data.points, 3), appended, false, "        ");
    xml += "      </Points>\n";
    const char* cellTag = lines ? "Lines" : "Polys";
    xml += fmt::format("      <{}>\n", cellTag);
    // Point indices as Int32 while they fit (VTK reads either): a tenth of a grain file less.
    const bool narrow = data.pointCount() <= std::size_t(std::numeric_limits<std::int32_t>::max());
    const auto indices = [&](const char* name, const std::vector<std::int64_t>& values) {
        return narrow ? int32Array(name, std::vector<std::int32_t>(values.begin(), values.end()))
                      : int64Array(name, values);
    };
    xml += arrayElement(indices("connectivity", data.connectivity), appended, false, "        ");
    xml += arrayElement(indices("offsets", data.offsets), appended, false, "        ");
    xml += fmt::format("      </{}>\n", cellTag);
    xml += "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
    out.write(appended.bytes().data(), static_cast<std::streamsize>(appended.bytes().size()));
    const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
    out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
    out.close();
    if (!out) {
        throw std::runtime_error(
            fmt::format("{}: cannot be written ({})", path, std::strerror(errno)));
    }
}

void writePvd(const std::string& path, const std::vector<PvdEntry>& entries,
              const std::string& comment) {
    std::string xml = "<?xml version=\"1.0\"?>\n";
    if (!comment.empty()) {
        xml += "<!-- " + comment + " -->\n";
    }
    xml += "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const PvdEntry& e : entries) {
        xml += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"{}\" name=\"{}\" "
                           "file=\"{}\"/>\n",
                           e.time, e.part, markupEscaped(e.name), markupEscaped(e.file));
    }
    xml += "  </Collection>\n</VTKFile>\n";
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << xml;
    out.close();
    if (!out) {
        throw std::runtime_error(
            fmt::format("{}: cannot be written ({})", path, std::strerror(errno)));
    }
}

} // namespace grainlab
