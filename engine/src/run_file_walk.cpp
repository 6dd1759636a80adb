// The whole-file check of a run file before a resumed run writes to it: every group, attribute
// and dataset is read once, as h5dump or h5py would. A resume reads only what it continues from
// (the last checkpoint, the samples, the series); damage elsewhere (an older checkpoint's chunk
// index, a group's link table) let it finish a file that no other reader could open. Runs on the
// thread that opens the run file (RunFile::open).
#include <H5Cpp.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "run_file_io.h"

namespace grainlab::hdf5io {

namespace {

/// Deeper than any run file's layout (/checkpoints/NAME/running_peak/grains): a damaged link
/// table that loops is refused instead of followed.
constexpr int kMaxDepth = 16;

/// Throws the damage of `object` with the HDF5 library's cause.
[[noreturn]] void damaged(const std::string& object, const std::string& what) {
    quietLibraryExitAfterDamage();
    std::string cause = hdf5Causes();
    if (cause.empty()) {
        cause = firstHdf5Causes();
    }
    H5Eclear2(H5E_DEFAULT);
    throw Hdf5Error(fmt::format("{} {} cannot be read ({})", object, what,
                                cause.empty() ? "the HDF5 library gave no cause" : cause));
}

void readAttributes(hid_t object, const std::string& name) {
    H5O_info_t info;
    if (H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS) < 0) {
        damaged(name, "(its object header)");
    }
    for (hsize_t k = 0; k < info.num_attrs; ++k) {
        const hid_t byName =
            H5Aopen_by_idx(object, ".", H5_INDEX_NAME, H5_ITER_INC, k, H5P_DEFAULT, H5P_DEFAULT);
        if (byName < 0) {
            damaged(name, fmt::format("(its attribute {})", k));
        }
        const hid_t type = H5Aget_type(byName);
        const hid_t space = H5Aget_space(byName);
        const hssize_t n = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
        const std::size_t size = type >= 0 ? H5Tget_size(type) : 0;
        bool ok = type >= 0 && n >= 0 && size > 0 && H5Tis_variable_str(type) == 0;
        if (ok) {
            std::vector<char> buffer(std::size_t(n) * size + 1);
            ok = H5Aread(byName, type, buffer.data()) >= 0;
        }
        if (type >= 0) {
            H5Tclose(type);
        }
        if (space >= 0) {
            H5Sclose(space);
        }
        H5Aclose(byName);
        if (!ok) {
            damaged(name, fmt::format("(its attribute {})", k));
        }
    }
}

void readDataset(hid_t dataset, const std::string& name) {
    const hid_t type = H5Dget_type(dataset);
    const hid_t space = H5Dget_space(dataset);
    const hssize_t n = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
    const std::size_t size = type >= 0 ? H5Tget_size(type) : 0;
    bool ok = type >= 0 && n >= 0 && size > 0 && H5Tis_variable_str(type) == 0 &&
              std::size_t(n) <= kMaxTextSize;
    if (ok && n > 0) {
        std::vector<char> buffer(std::size_t(n) * size);
        ok = H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) >= 0;
    }
    if (type >= 0) {
        H5Tclose(type);
    }
    if (space >= 0) {
        H5Sclose(space);
    }
    if (!ok) {
        damaged(name, "(its values)");
    }
}

void walk(hid_t group, const std::string& name, int depth) {
    if (depth > kMaxDepth) {
        throw Hdf5Error(fmt::format("{}: groups nested deeper than {} levels", name, kMaxDepth));
    }
    readAttributes(group, name);
    std::vector<std::string> links;
    const auto collect = [](hid_t, const char* link, const H5L_info_t*, void* data) -> herr_t {
        static_cast<std::vector<std::string>*>(data)->emplace_back(link);
        return 0;
    };
    if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &links) < 0) {
        damaged(name, "(its list of members)");
    }
    for (const std::string& link : links) {
        const std::string child = (name == "/" ? "/" : name + "/") + link;
        const hid_t object = H5Oopen(group, link.c_str(), H5P_DEFAULT);
        if (object < 0) {
            damaged(child, "(its object header)");
        }
        const H5I_type_t kind = H5Iget_type(object);
        try {
            if (kind == H5I_GROUP) {
                walk(object, child, depth + 1);
            } else if (kind == H5I_DATASET) {
                readAttributes(object, child);
                readDataset(object, child);
            } else {
                readAttributes(object, child);
            }
        } catch (...) {
            H5Oclose(object);
            throw;
        }
        H5Oclose(object);
    }
}

} // namespace

void quietLibraryExitAfterDamage() {
    // A damaged file that the library cannot close makes its exit handler print "HDF5:
    // infinite loop closing library" and its state after grainlab's own message. Handlers run
    // in reverse order of registration, and the library registered its own at its first call,
    // so this one runs first: everything grainlab says is printed by then.
    static const bool registered = std::atexit([] {
                                       std::fflush(stderr);
                                       const int devNull = ::open("/dev/null", O_WRONLY);
                                       if (devNull >= 0) {
                                           ::dup2(devNull, STDERR_FILENO);
                                           ::close(devNull);
                                       }
                                   }) == 0;
    (void)registered;
}

void readWholeFile(const H5::H5File& file) {
    clearHdf5Causes();
    const hid_t root = H5Gopen2(file.getId(), "/", H5P_DEFAULT);
    if (root < 0) {
        damaged("/", "(the root group)");
    }
    try {
        walk(root, "/", 0);
    } catch (...) {
        H5Gclose(root);
        throw;
    }
    H5Gclose(root);
}

} // namespace grainlab::hdf5io
