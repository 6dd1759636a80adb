#pragma once
// HDF5 helpers of the run file (private to the engine): typed attributes and datasets, UTF-8
// variable-length strings, the state layout of checkpoints and samples, and a checkpoint's
// contacts, void cells and shape outlines (docs/formats.md). Used by run_file.cpp,
// run_file_state.cpp and run_file_network.cpp on the thread that reads or writes the file.

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

#include "grainlab/contact_network.h"
#include "grainlab/run_warning.h"
#include "grainlab/simulation_state.h"
#include "grainlab/void_cells.h"
#include "run_file_driver.h"

namespace grainlab::hdf5io {

// ---- types ---------------------------------------------------------------------------------

/// The HDF5 types of the values the run file stores: in memory (native) and in the file
/// (little-endian).
template <class T>
struct H5Types {
    static const H5::PredType& memory() { return pick(false); }
    static const H5::PredType& file() { return pick(true); }

private:
    static const H5::PredType& pick(bool inFile) {
        using P = H5::PredType;
        if constexpr (std::is_same_v<T, double>) {
            return inFile ? P::IEEE_F64LE : P::NATIVE_DOUBLE;
        } else if constexpr (std::is_same_v<T, std::int32_t>) {
            return inFile ? P::STD_I32LE : P::NATIVE_INT32;
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
            return inFile ? P::STD_I64LE : P::NATIVE_INT64;
        } else {
            static_assert(std::is_same_v<T, std::uint8_t>, "a type the run file does not store");
            return inFile ? P::STD_U8LE : P::NATIVE_UINT8;
        }
    }
};

/// Text is stored as fixed-length UTF-8 strings (NUL-padded): in the checksummed object
/// headers (attributes) or checksummed chunks (datasets). Variable-length strings live in the
/// global heap, which has no checksum, and a damaged heap reference crashed a reader.
inline H5::StrType fixedStringType(std::size_t size) {
    H5::StrType t(H5::PredType::C_S1, std::max<std::size_t>(1, size));
    t.setCset(H5T_CSET_UTF8);
    t.setStrpad(H5T_STR_NULLPAD);
    return t;
}

/// Bytes of one stage name in a series' `stage` column, and of its `stage_kind`.
inline constexpr std::size_t kStageTextSize = 64;
inline constexpr std::size_t kStageKindSize = 16;
/// Largest text a reader accepts (the experiment file, the runner state) [bytes].
inline constexpr std::size_t kMaxTextSize = std::size_t(1) << 28;

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

/// The messages of an HDF5 error stack, innermost last, e.g. "unable to lock file, errno =
/// 11" or "data error detected by Fletcher32 checksum". A failed system call is cut to its
/// call and cause ("file write failed: File too large"), not its buffer addresses.
inline std::string hdf5Causes(hid_t stack = H5E_DEFAULT) {
    std::vector<std::string> messages;
    H5Ewalk2(
        stack, H5E_WALK_UPWARD,
        [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
            auto* out = static_cast<std::vector<std::string>*>(data);
            if (e->desc && *e->desc && out->size() < 8) {
                std::string m = e->desc;
                const std::size_t cause = m.find("error message = '");
                if (cause != std::string::npos) {
                    const std::size_t begin = cause + 17, end = m.find('\'', begin);
                    const std::size_t call = std::min(m.find(':'), m.find(", errno"));
                    m = m.substr(0, call) + ": " + m.substr(begin, end - begin);
                }
                out->push_back(std::move(m));
            }
            return 0;
        },
        &messages);
    std::string out;
    for (const auto& m : messages) {
        if (out.find(m) == std::string::npos) {
            out += (out.empty() ? "" : "; ") + m;
        }
    }
    return out;
}

/// The causes of the first HDF5 call that failed since clearHdf5Causes(). The error stack
/// itself does not keep them: the C++ wrapper's destructors (H5Dclose, H5Gclose) run before an
/// exception reaches its handler, and every call clears the stack.
inline std::string& firstHdf5Causes() {
    static std::string causes;
    return causes;
}

inline void clearHdf5Causes() {
    firstHdf5Causes().clear();
}

/// In place of the library's printing of errors (H5::Exception::dontPrint): records the
/// causes of a failing call, printing nothing.
inline void recordHdf5Causes() {
    H5Eset_auto2(
        H5E_DEFAULT,
        [](hid_t stack, void*) -> herr_t {
            if (firstHdf5Causes().empty()) {
                firstHdf5Causes() = hdf5Causes(stack);
            }
            return 0;
        },
        nullptr);
}

/// Turns an HDF5 library exception into std::runtime_error with the file, the operation and
/// the cause: damage (a checksum that does not match), a file that cannot be locked or opened.
/// An error of the HDF5 library (as opposed to a value refused before anything was written).
class Hdf5Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// After an error of the library on a file: keeps the library's exit from printing after
/// grainlab's message (run_file_walk.cpp).
void quietLibraryExitAfterDamage();

[[noreturn]] inline void throwHdf5(const std::string& path, const std::string& what,
                                   const std::string& detail) {
    quietLibraryExitAfterDamage();
    std::string verdict;
    if (detail.find("checksum") != std::string::npos) {
        verdict = "the file is damaged (a checksum does not match); ";
    } else if (detail.find("File too large") != std::string::npos) {
        verdict = "the file size limit is reached (a write failed); ";
    } else if (detail.find("No space left") != std::string::npos ||
               detail.find("Disk quota") != std::string::npos) {
        verdict = "the disk is full (a write failed); ";
    } else if (detail.find("unable to lock file") != std::string::npos) {
        verdict = "the file is in use by another program (it cannot be locked); ";
    } else if (detail.find("Permission denied") != std::string::npos) {
        verdict = "no permission to open the file this way; ";
    } else if (detail.starts_with("H5") && detail.ends_with("failed")) {
        verdict = "the file is damaged or incomplete (a group, dataset or attribute of the run "
                  "file cannot be opened); ";
    } else if (detail.find("signature") != std::string::npos ||
               detail.find("superblock") != std::string::npos) {
        verdict = "not a readable HDF5 file (damaged or of another kind); ";
    }
    throw Hdf5Error(fmt::format("{}: {}while {}: {}", path, verdict, what, detail));
}

[[noreturn]] inline void rethrowHdf5(const std::string& path, const std::string& what,
                                     const H5::Exception& e) {
    std::string causes = hdf5Causes();
    if (causes.empty()) {
        causes = firstHdf5Causes();
    }
    throwHdf5(path, what, causes.empty() ? e.getDetailMsg() : causes);
}

/// Opens (flags H5F_ACC_RDONLY or H5F_ACC_RDWR) or creates (H5F_ACC_TRUNC) a file through the
/// C API, so that the cause (lock, permission, damage) is read off the error stack before the
/// C++ wrapper clears it.
inline H5::H5File openFile(const std::string& path, unsigned flags,
                           const H5::FileAccPropList& access, const std::string& what) {
    recordHdf5Causes();
    // Small chunk-index nodes: most datasets are a single chunk, and the default node (room
    // for 64 chunks, ~2.3 KB) per dataset of every checkpoint doubled the file.
    H5::FileCreatPropList create;
    create.setIstorek(2);
    const H5::FileAccPropList driven = withRunFileDriver(access);
    const hid_t id = flags == H5F_ACC_TRUNC
                         ? H5Fcreate(path.c_str(), flags, create.getId(), driven.getId())
                         : H5Fopen(path.c_str(), flags, driven.getId());
    if (id < 0) {
        const std::string causes = hdf5Causes();
        H5Eclear2(H5E_DEFAULT);
        throwHdf5(path, what, causes.empty() ? "the HDF5 library gave no cause" : causes);
    }
    H5::H5File file(id); // takes a reference of its own
    H5Idec_ref(id);
    return file;
}

template <class F>
auto guarded(const std::string& path, const std::string& what, F&& f) {
    recordHdf5Causes();
    clearHdf5Causes();
    try {
        return f();
    } catch (const H5::Exception& e) {
        rethrowHdf5(path, what, e);
    } catch (const Hdf5Error& e) {
        const std::string text = e.what();
        if (text.starts_with(path + ":")) {
            throw;
        }
        throw Hdf5Error(fmt::format("{}: while {}: {}", path, what, text));
    } catch (const std::runtime_error& e) {
        // A check of what was read (or written): name the file and the operation.
        const std::string text = e.what();
        if (text.starts_with(path + ":")) {
            throw;
        }
        throw std::runtime_error(fmt::format("{}: while {}: {}", path, what, text));
    }
}

/// Full name of an object, for messages ("/checkpoints/000001-x/grains").
inline std::string objectName(const H5::IdComponent& object) {
    char name[1024] = {};
    const ssize_t n = H5Iget_name(object.getId(), name, sizeof name);
    return n > 0 ? std::string(name) : std::string("?");
}

/// Datasets of at least this many bytes are compressed (a checkpoint's grains, contacts, void
/// cells and runner state); smaller ones are not, nor the series, whose last chunk is rewritten
/// at every record.
constexpr hsize_t kCompressFromBytes = 4096;

/// zlib's level: on a checkpoint of the reference run, level 6 gains 1.6 % of size over level 1
/// for 60 % more time (docs/formats.md).
constexpr unsigned kDeflateLevel = 1;

/// The filters of a dataset's chunks, in the order they are applied on writing: for a large
/// dataset the shuffle (each value's bytes regrouped by significance, so that zlib finds the
/// exponents' repetition) and deflate (zlib, HDF5's own filters: h5py and h5dump read them);
/// then Fletcher32, on the stored bytes, so that damage is found before anything is inflated.
inline void addChunkFilters(H5::DSetCreatPropList& p, hsize_t bytes) {
    if (bytes >= kCompressFromBytes) {
        p.setShuffle();
        p.setDeflate(kDeflateLevel);
    }
    p.setFletcher32();
}

/// Checksummed, chunked layout of a one-dimensional dataset of `n` values of `valueBytes`
/// bytes each, compressed when large.
inline H5::DSetCreatPropList checksummedLayout(hsize_t n, std::size_t valueBytes) {
    H5::DSetCreatPropList p;
    const hsize_t chunk = std::clamp<hsize_t>(n, 1, 65536);
    p.setChunk(1, &chunk);
    addChunkFilters(p, n * valueBytes);
    return p;
}

/// Access to a new dataset without a chunk cache: H5Dwrite writes each chunk at once, so a
/// write that fails (a full disk) fails in H5Dwrite and throws, instead of in the H5Dclose of
/// a destructor, which can only print and let the writer carry on.
inline H5::DSetAccPropList writeThrough() {
    H5::DSetAccPropList p;
    p.setChunkCache(0, 0, 1.0);
    return p;
}

/// FNV-1a of a buffer: stored with every dataset (attribute `checksum`) and checked on reading.
/// Fletcher32 checks each chunk, but not that the chunk index points at the right chunk (a
/// chunk of zeros has a zero Fletcher32).
inline std::int64_t contentHash(const void* data, std::size_t bytes) {
    std::uint64_t h = 1469598103934665603ull;
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
        h = (h ^ p[i]) * 1099511628211ull;
    }
    h ^= bytes;
    return static_cast<std::int64_t>(h);
}

// ---- attributes ----------------------------------------------------------------------------

inline void writeAttribute(H5::H5Object& object, const std::string& name,
                           const std::string& value) {
    const H5::StrType t = fixedStringType(value.size());
    if (object.attrExists(name)) {
        object.removeAttr(name);
    }
    H5::Attribute a = object.createAttribute(name, t, H5::DataSpace(H5S_SCALAR));
    std::vector<char> buffer(t.getSize(), '\0');
    std::copy(value.begin(), value.end(), buffer.begin());
    a.write(t, buffer.data());
}

/// Checks that `type` is a fixed-length string type of at most `maxSize` bytes.
inline std::size_t checkedTextSize(const H5::DataType& type, const std::string& what,
                                   std::size_t maxSize) {
    if (type.getClass() != H5T_STRING) {
        throw std::runtime_error(fmt::format("{} is not text", what));
    }
    const H5::StrType t(type.getId());
    if (t.isVariableStr()) {
        throw std::runtime_error(
            fmt::format("{} is variable-length text, which this format does not write", what));
    }
    const std::size_t size = t.getSize();
    if (size == 0 || size > maxSize) {
        throw std::runtime_error(fmt::format("{} has a text size of {} bytes", what, size));
    }
    return size;
}

/// Text of `count` fixed-length strings of `size` bytes, each up to its first NUL.
inline std::vector<std::string> splitFixedText(const std::vector<char>& buffer, std::size_t size,
                                               std::size_t count) {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < count; ++k) {
        const char* begin = buffer.data() + k * size;
        const char* end = std::find(begin, begin + size, '\0');
        out.emplace_back(begin, end);
    }
    return out;
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
    const std::string what = fmt::format("attribute {} of {}", name, objectName(object));
    const H5::DataType type = a.getDataType();
    const std::size_t size = checkedTextSize(type, what, kMaxTextSize);
    if (a.getSpace().getSimpleExtentNpoints() != 1) {
        throw std::runtime_error(fmt::format("{} is not a single text", what));
    }
    std::vector<char> buffer(size, '\0');
    a.read(type, buffer.data());
    return splitFixedText(buffer, size, 1).front();
}

template <class T>
T readAttribute(const H5::H5Object& object, const std::string& name) {
    H5::Attribute a = object.openAttribute(name);
    const std::string what = fmt::format("attribute {} of {}", name, objectName(object));
    if (a.getSpace().getSimpleExtentNpoints() != 1) {
        throw std::runtime_error(fmt::format("{} is not a scalar", what));
    }
    const H5T_class_t expected = std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
    if (a.getTypeClass() != expected) {
        throw std::runtime_error(
            fmt::format("{} is not {}", what, expected == H5T_FLOAT ? "a number" : "an integer"));
    }
    T value{};
    a.read(H5Types<T>::memory(), &value);
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) {
            throw std::runtime_error(fmt::format("{} is not finite", what));
        }
    }
    return value;
}

inline void writeHash(H5::H5Object& object, const void* data, std::size_t bytes) {
    writeAttribute(object, "checksum", contentHash(data, bytes));
}

/// Refuses values whose hash is not the one stored with them.
inline void checkHash(const H5::H5Object& object, const std::string& what, const void* data,
                      std::size_t bytes) {
    if (!object.attrExists("checksum")) {
        throw std::runtime_error(fmt::format("{} has no checksum attribute", what));
    }
    if (readAttribute<std::int64_t>(object, "checksum") != contentHash(data, bytes)) {
        throw std::runtime_error(fmt::format("{}: the file is damaged (its values do not match "
                                             "their checksum)",
                                             what));
    }
}

inline void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                                     const std::vector<std::string>& values) {
    std::size_t size = 1;
    for (const auto& v : values) {
        size = std::max(size, v.size());
    }
    const H5::StrType t = fixedStringType(size);
    std::vector<char> buffer(size * values.size(), '\0');
    for (std::size_t k = 0; k < values.size(); ++k) {
        std::copy(values[k].begin(), values[k].end(), buffer.begin() + k * size);
    }
    if (object.attrExists(name)) {
        object.removeAttr(name);
    }
    const hsize_t n = values.size();
    H5::Attribute a = object.createAttribute(name, t, H5::DataSpace(1, &n));
    if (n > 0) {
        a.write(t, buffer.data());
    }
}

inline std::vector<std::string> readStringListAttribute(const H5::H5Object& object,
                                                        const std::string& name) {
    H5::Attribute a = object.openAttribute(name);
    const std::string what = fmt::format("attribute {} of {}", name, objectName(object));
    const H5::DataType type = a.getDataType();
    const std::size_t size = checkedTextSize(type, what, 4096);
    const auto n = static_cast<std::size_t>(a.getSpace().getSimpleExtentNpoints());
    if (n > 4096) {
        throw std::runtime_error(fmt::format("{} has {} texts", what, n));
    }
    std::vector<char> buffer(size * n, '\0');
    if (n > 0) {
        a.read(type, buffer.data());
    }
    return splitFixedText(buffer, size, n);
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
    const hsize_t dims = n, unlimited = H5S_UNLIMITED;
    // An empty dataset is extendible (a chunk may not exceed fixed dimensions of 0).
    const H5::DataSpace space =
        n > 0 ? H5::DataSpace(1, &dims) : H5::DataSpace(1, &dims, &unlimited);
    H5::DataSet ds = group.createDataSet(name, H5Types<T>::file(), space,
                                         checksummedLayout(n, sizeof(T)), writeThrough());
    if (n > 0) {
        ds.write(data, H5Types<T>::memory());
    }
    writeHash(ds, data, n * sizeof(T));
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
    const std::string what = fmt::format("dataset {}/{}", objectName(group), name);
    H5::DataSpace space = ds.getSpace();
    if (space.getSimpleExtentNdims() != 1) {
        throw std::runtime_error(fmt::format("{} is not one-dimensional", what));
    }
    const H5T_class_t expected = std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
    if (ds.getTypeClass() != expected) {
        throw std::runtime_error(
            fmt::format("{} is not {}", what, expected == H5T_FLOAT ? "numbers" : "integers"));
    }
    std::vector<T> values(static_cast<std::size_t>(space.getSimpleExtentNpoints()));
    if (!values.empty()) {
        try {
            ds.read(values.data(), H5Types<T>::memory());
        } catch (const H5::Exception& e) {
            rethrowHdf5(what, "reading it", e);
        }
    }
    checkHash(ds, what, values.data(), values.size() * sizeof(T));
    if constexpr (std::is_floating_point_v<T>) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!std::isfinite(values[i])) {
                throw std::runtime_error(fmt::format("{}[{}] is not finite", what, i));
            }
        }
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

/// A text as a one-element dataset of one fixed-length string, chunked and checksummed.
inline void writeStringDataset(H5::Group& group, const std::string& name, const std::string& text) {
    const H5::StrType t = fixedStringType(text.size());
    const hsize_t one = 1;
    H5::DataSet ds = group.createDataSet(name, t, H5::DataSpace(1, &one),
                                         checksummedLayout(1, t.getSize()), writeThrough());
    std::vector<char> buffer(t.getSize(), '\0');
    std::copy(text.begin(), text.end(), buffer.begin());
    ds.write(buffer.data(), t);
    writeHash(ds, buffer.data(), buffer.size());
}

inline std::string readStringDataset(const H5::Group& group, const std::string& name) {
    H5::DataSet ds = group.openDataSet(name);
    const std::string what = fmt::format("dataset {}/{}", objectName(group), name);
    const H5::DataType type = ds.getDataType();
    const std::size_t size = checkedTextSize(type, what, kMaxTextSize);
    if (ds.getSpace().getSimpleExtentNpoints() != 1) {
        throw std::runtime_error(fmt::format("{} is not a single text", what));
    }
    std::vector<char> buffer(size, '\0');
    try {
        ds.read(buffer.data(), type);
    } catch (const H5::Exception& e) {
        rethrowHdf5(what, "reading it", e);
    }
    checkHash(ds, what, buffer.data(), buffer.size());
    return splitFixedText(buffer, size, 1).front();
}

/// Texts as a one-dimensional dataset of fixed-length strings (the longest sets the length),
/// chunked and checksummed; readStringArray() reads it back.
inline void writeStringArray(H5::Group& group, const std::string& name,
                             const std::vector<std::string>& texts) {
    std::size_t size = 1;
    for (const std::string& t : texts) {
        size = std::max(size, t.size());
    }
    const H5::StrType t = fixedStringType(size);
    const hsize_t n = texts.size(), unlimited = H5S_UNLIMITED;
    // An empty dataset is extendible (a chunk may not exceed fixed dimensions of 0).
    const H5::DataSpace space = n > 0 ? H5::DataSpace(1, &n) : H5::DataSpace(1, &n, &unlimited);
    H5::DataSet ds =
        group.createDataSet(name, t, space, checksummedLayout(n, t.getSize()), writeThrough());
    std::vector<char> buffer(size * texts.size(), '\0');
    for (std::size_t k = 0; k < texts.size(); ++k) {
        std::copy(texts[k].begin(), texts[k].end(), buffer.begin() + k * size);
    }
    if (n > 0) {
        ds.write(buffer.data(), t);
    }
    writeHash(ds, buffer.data(), buffer.size());
}

/// The fixed-length strings of a one-dimensional text dataset (a series' stage column).
inline std::vector<std::string> readStringArray(const H5::DataSet& ds, const std::string& what) {
    const H5::DataType type = ds.getDataType();
    const std::size_t size = checkedTextSize(type, what, 4096);
    H5::DataSpace space = ds.getSpace();
    if (space.getSimpleExtentNdims() != 1) {
        throw std::runtime_error(fmt::format("{} is not one-dimensional", what));
    }
    const auto n = static_cast<std::size_t>(space.getSimpleExtentNpoints());
    std::vector<char> buffer(size * n, '\0');
    if (n > 0) {
        try {
            ds.read(buffer.data(), type);
        } catch (const H5::Exception& e) {
            rethrowHdf5(what, "reading it", e);
        }
    }
    checkHash(ds, what, buffer.data(), buffer.size());
    return splitFixedText(buffer, size, n);
}

/// A two-dimensional dataset of `rows` x `columns` values, row-major, chunked and checksummed.
template <class T>
void writeMatrix(H5::Group& group, const std::string& name, const std::vector<T>& values,
                 std::size_t rows, std::size_t columns, const char* unit) {
    if (values.size() != rows * columns) {
        throw std::invalid_argument(
            fmt::format("{}: {} values for {} x {}", name, values.size(), rows, columns));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            throw std::runtime_error(
                fmt::format("{}[{}] is not finite; refusing to write a non-finite value", name, i));
        }
    }
    const hsize_t dims[2] = {rows, columns};
    const hsize_t chunk[2] = {std::max<hsize_t>(1, rows), std::max<hsize_t>(1, columns)};
    H5::DSetCreatPropList layout;
    layout.setChunk(2, chunk);
    addChunkFilters(layout, hsize_t(rows) * columns * sizeof(T));
    H5::DataSet ds = group.createDataSet(name, H5Types<T>::file(), H5::DataSpace(2, dims), layout,
                                         writeThrough());
    if (!values.empty()) {
        ds.write(values.data(), H5Types<T>::memory());
    }
    writeHash(ds, values.data(), values.size() * sizeof(T));
    writeAttribute(ds, "unit", std::string(unit));
}

// ---- the state layout (run_file_state.cpp) --------------------------------------------------

/// Writes every field of `state` into the empty group `g`. Refuses non-finite values.
void writeState(H5::Group& g, const SimulationState& state);
/// Reads a group written by writeState, bit for bit.
SimulationState readState(const H5::Group& g);

// ---- a checkpoint's network (run_file_network.cpp) -------------------------------------------

/// Writes the group `contacts` of checkpoint `g`: every touching contact of `network`, with
/// its strong and load-bearing flags (the engine's measures), and the wrapped grain centres.
void writeContacts(H5::Group& g, const ContactNetwork& network);
/// Writes the group `void_cells` of checkpoint `g` (replacing one already there).
void writeVoidCells(H5::Group& g, const VoidCellSet& cells);
/// Writes shape_outline1/2 of checkpoint `g`: kShapeOutlinePoints points of each shape's
/// outline in its body frame.
void writeShapeOutlines(H5::Group& g, const std::vector<OvalShape>& shapes);

// ---- the run's warnings (run_file_warnings.cpp) ---------------------------------------------

/// Writes /warnings of the file whose root is `root`, replacing the older list whole (the new
/// one is written under a scratch name and moved into place once complete).
void writeWarnings(H5::Group& root, const std::vector<RunWarning>& all);
/// Reads /warnings (none in a file without it).
std::vector<RunWarning> readWarnings(const H5::Group& root);

/// Opens a run file read-only and checks its format version (a readable one).
H5::H5File openRunFileToRead(const std::string& path);

/// Reads every group, attribute and dataset of the file once (run_file_walk.cpp); throws
/// Hdf5Error naming the first object that cannot be read.
void readWholeFile(const H5::H5File& file);

} // namespace grainlab::hdf5io
