#pragma once
// HDF5 helpers of the run file (private to the engine): typed attributes and datasets, UTF-8
// variable-length strings, and the state layout of checkpoints and samples (docs/formats.md).
// Used by run_file.cpp and run_file_state.cpp on the thread that reads or writes the file.

#include <H5Cpp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "grainlab/simulation_state.h"

namespace grainlab::hdf5io {

// ---- types ---------------------------------------------------------------------------------

template <class T>
struct H5Types;
template <>
struct H5Types<double> {
    static const H5::PredType& memory() { return H5::PredType::NATIVE_DOUBLE; }
    static const H5::PredType& file() { return H5::PredType::IEEE_F64LE; }
};
template <>
struct H5Types<std::int32_t> {
    static const H5::PredType& memory() { return H5::PredType::NATIVE_INT32; }
    static const H5::PredType& file() { return H5::PredType::STD_I32LE; }
};
template <>
struct H5Types<std::int64_t> {
    static const H5::PredType& memory() { return H5::PredType::NATIVE_INT64; }
    static const H5::PredType& file() { return H5::PredType::STD_I64LE; }
};
template <>
struct H5Types<std::uint8_t> {
    static const H5::PredType& memory() { return H5::PredType::NATIVE_UINT8; }
    static const H5::PredType& file() { return H5::PredType::STD_U8LE; }
};

inline H5::StrType stringType() {
    H5::StrType t(H5::PredType::C_S1, H5T_VARIABLE);
    t.setCset(H5T_CSET_UTF8);
    return t;
}

/// Group and dataset names may not contain '/'.
inline std::string linkName(const std::string& name) {
    std::string out = name.empty() ? "_" : name;
    for (char& c : out) {
        if (c == '/') {
            c = '_';
        }
    }
    if (out == ".") {
        out = "_";
    }
    return out;
}

/// Turns an HDF5 library exception into std::runtime_error with the file and the operation.
[[noreturn]] inline void rethrowHdf5(const std::string& path, const std::string& what,
                                     const H5::Exception& e) {
    throw std::runtime_error(fmt::format("{}: HDF5 error while {}: {} ({})", path, what,
                                         e.getDetailMsg(), e.getFuncName()));
}

template <class F>
auto guarded(const std::string& path, const std::string& what, F&& f) {
    H5::Exception::dontPrint();
    try {
        return f();
    } catch (const H5::Exception& e) {
        rethrowHdf5(path, what, e);
    }
}

// ---- attributes ----------------------------------------------------------------------------

inline void writeAttribute(H5::H5Object& object, const std::string& name,
                           const std::string& value) {
    const H5::StrType t = stringType();
    if (object.attrExists(name)) {
        object.removeAttr(name);
    }
    H5::Attribute a = object.createAttribute(name, t, H5::DataSpace(H5S_SCALAR));
    a.write(t, value);
}

template <class T>
void writeAttribute(H5::H5Object& object, const std::string& name, T value) {
    if constexpr (std::is_same_v<T, double>) {
        if (!std::isfinite(value)) {
            throw std::runtime_error(fmt::format("attribute {} is {}; refusing to write a "
                                                 "non-finite value",
                                                 name, std::isnan(value) ? "NaN" : "infinite"));
        }
    }
    if (object.attrExists(name)) {
        object.removeAttr(name);
    }
    H5::Attribute a = object.createAttribute(name, H5Types<T>::file(), H5::DataSpace(H5S_SCALAR));
    a.write(H5Types<T>::memory(), &value);
}

inline std::string readStringAttribute(const H5::H5Object& object, const std::string& name) {
    H5::Attribute a = object.openAttribute(name);
    std::string value;
    a.read(a.getStrType(), value);
    return value;
}

template <class T>
T readAttribute(const H5::H5Object& object, const std::string& name) {
    H5::Attribute a = object.openAttribute(name);
    if (a.getSpace().getSimpleExtentNpoints() != 1) {
        throw std::runtime_error(fmt::format("attribute {} is not a scalar", name));
    }
    T value{};
    a.read(H5Types<T>::memory(), &value);
    return value;
}

inline void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                                     const std::vector<std::string>& values) {
    const H5::StrType t = stringType();
    std::vector<const char*> pointers;
    for (const auto& v : values) {
        pointers.push_back(v.c_str());
    }
    if (object.attrExists(name)) {
        object.removeAttr(name);
    }
    const hsize_t n = values.size();
    H5::Attribute a = object.createAttribute(name, t, H5::DataSpace(1, &n));
    if (n > 0) {
        a.write(t, pointers.data());
    }
}

inline std::vector<std::string> readStringListAttribute(const H5::H5Object& object,
                                                        const std::string& name) {
    H5::Attribute a = object.openAttribute(name);
    const H5::StrType t = stringType();
    H5::DataSpace space = a.getSpace();
    const auto n = static_cast<std::size_t>(space.getSimpleExtentNpoints());
    std::vector<char*> buffer(n, nullptr);
    std::vector<std::string> out;
    if (n == 0) {
        return out;
    }
    a.read(t, buffer.data());
    for (char* s : buffer) {
        out.emplace_back(s ? s : "");
    }
    H5Dvlen_reclaim(t.getId(), space.getId(), H5P_DEFAULT, buffer.data());
    return out;
}

// ---- fixed-size datasets -------------------------------------------------------------------

template <class T>
void writeArray(H5::Group& group, const std::string& name, const T* data, std::size_t n,
                const char* unit) {
    if constexpr (std::is_same_v<T, double>) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(data[i])) {
                throw std::runtime_error(fmt::format("{}[{}] is {}; refusing to write a "
                                                     "non-finite value",
                                                     name, i,
                                                     std::isnan(data[i]) ? "NaN" : "infinite"));
            }
        }
    }
    const hsize_t dims = n;
    H5::DataSet ds = group.createDataSet(name, H5Types<T>::file(), H5::DataSpace(1, &dims));
    if (n > 0) {
        ds.write(data, H5Types<T>::memory());
    }
    if (unit) {
        writeAttribute(ds, "unit", std::string(unit));
    }
}

template <class T>
void writeArray(H5::Group& group, const std::string& name, const std::vector<T>& values,
                const char* unit) {
    writeArray(group, name, values.data(), values.size(), unit);
}

template <class T, std::size_t N>
void writeArray(H5::Group& group, const std::string& name, const std::array<T, N>& values,
                const char* unit) {
    writeArray(group, name, values.data(), N, unit);
}

template <class T>
std::vector<T> readArray(const H5::Group& group, const std::string& name) {
    H5::DataSet ds = group.openDataSet(name);
    H5::DataSpace space = ds.getSpace();
    if (space.getSimpleExtentNdims() != 1) {
        throw std::runtime_error(fmt::format("dataset {} is not one-dimensional", name));
    }
    std::vector<T> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
    if (!values.empty()) {
        ds.read(values.data(), H5Types<T>::memory());
    }
    return values;
}

template <class T, std::size_t N>
std::array<T, N> readFixed(const H5::Group& group, const std::string& name) {
    const std::vector<T> v = readArray<T>(group, name);
    if (v.size() != N) {
        throw std::runtime_error(
            fmt::format("dataset {} has {} values, expected {}", name, v.size(), N));
    }
    std::array<T, N> out{};
    std::copy(v.begin(), v.end(), out.begin());
    return out;
}

inline void writeStringDataset(H5::Group& group, const std::string& name, const std::string& text) {
    const H5::StrType t = stringType();
    H5::DataSet ds = group.createDataSet(name, t, H5::DataSpace(H5S_SCALAR));
    ds.write(text, t);
}

inline std::string readStringDataset(const H5::Group& group, const std::string& name) {
    H5::DataSet ds = group.openDataSet(name);
    std::string text;
    ds.read(text, ds.getStrType());
    return text;
}

inline std::vector<std::string> readStringArray(const H5::DataSet& ds) {
    const H5::StrType t = stringType();
    H5::DataSpace space = ds.getSpace();
    const auto n = static_cast<std::size_t>(space.getSimpleExtentNpoints());
    std::vector<std::string> out;
    if (n == 0) {
        return out;
    }
    std::vector<char*> buffer(n, nullptr);
    ds.read(buffer.data(), t);
    for (char* s : buffer) {
        out.emplace_back(s ? s : "");
    }
    H5Dvlen_reclaim(t.getId(), space.getId(), H5P_DEFAULT, buffer.data());
    return out;
}

// ---- the state layout (run_file_state.cpp) --------------------------------------------------

/// Writes every field of `state` into the empty group `g`. Refuses non-finite values.
void writeState(H5::Group& g, const SimulationState& state);
/// Reads a group written by writeState, bit for bit.
SimulationState readState(const H5::Group& g);

} // namespace grainlab::hdf5io
