#include "run_file_driver.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

namespace grainlab::hdf5io {

namespace {

/// An open run file. `pub` comes first: HDF5 hands the driver a pointer to it.
struct DriverFile {
    H5FD_t pub{};
    int fd = -1;
    haddr_t eoa = 0; ///< end of the space HDF5 has allocated [bytes]
    haddr_t eof = 0; ///< end of the file as written [bytes]
    dev_t device = 0;
    ino_t inode = 0;
    bool fenced = false;
    /// Writes after the fence, in order: (address, bytes).
    std::vector<std::pair<haddr_t, std::vector<unsigned char>>> held;
};

/// The file named in HDF5's error stack: its name only (no path of the source tree is compiled
/// into GrainLab).
constexpr const char* kThisFile = "run_file_driver.cpp";

DriverFile* of(H5FD_t* file) {
    return reinterpret_cast<DriverFile*>(file);
}
const DriverFile* of(const H5FD_t* file) {
    return reinterpret_cast<const DriverFile*>(file);
}

/// Pushes an error in the POSIX driver's words ("<what>, errno = N, error message = '...'"), so
/// that its cause reads the same in messages.
herr_t failure(const char* function, hid_t minor, const char* what, int cause) {
    H5Epush2(H5E_DEFAULT, kThisFile, function, __LINE__, H5E_ERR_CLS, H5E_VFL, minor,
             "%s, errno = %d, error message = '%s'", what, cause, std::strerror(cause));
    return -1;
}

H5FD_t* driverOpen(const char* name, unsigned flags, hid_t, haddr_t maxaddr) {
    if (name == nullptr || *name == '\0' || maxaddr == 0 || maxaddr == HADDR_UNDEF) {
        H5Epush2(H5E_DEFAULT, kThisFile, "driverOpen", __LINE__, H5E_ERR_CLS, H5E_ARGS,
                 H5E_BADVALUE, "invalid file name or address space");
        return nullptr;
    }
    int o = (flags & H5F_ACC_RDWR) ? O_RDWR : O_RDONLY;
    o |= (flags & H5F_ACC_TRUNC) ? O_TRUNC : 0;
    o |= (flags & H5F_ACC_CREAT) ? O_CREAT : 0;
    o |= (flags & H5F_ACC_EXCL) ? O_EXCL : 0;
    const int fd = ::open(name, o | O_CLOEXEC, 0666);
    if (fd < 0) {
        failure("driverOpen", H5E_CANTOPENFILE, "unable to open file", errno);
        return nullptr;
    }
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        const int cause = errno;
        ::close(fd);
        failure("driverOpen", H5E_BADFILE, "unable to fstat file", cause);
        return nullptr;
    }
    auto* file = new DriverFile;
    file->fd = fd;
    file->eof = static_cast<haddr_t>(info.st_size);
    file->device = info.st_dev;
    file->inode = info.st_ino;
    return &file->pub;
}

herr_t driverClose(H5FD_t* file) {
    DriverFile* f = of(file);
    const int result = ::close(f->fd);
    const int cause = errno;
    delete f;
    return result == 0 ? 0
                       : failure("driverClose", H5E_CANTCLOSEFILE, "unable to close file", cause);
}

int driverCompare(const H5FD_t* a, const H5FD_t* b) {
    const DriverFile* f = of(a);
    const DriverFile* g = of(b);
    if (f->device != g->device) {
        return f->device < g->device ? -1 : 1;
    }
    if (f->inode != g->inode) {
        return f->inode < g->inode ? -1 : 1;
    }
    return 0;
}

herr_t driverQuery(const H5FD_t*, unsigned long* flags) {
    // As the POSIX driver: metadata and small raw data aggregated, metadata accumulated.
    *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
             H5FD_FEAT_AGGREGATE_SMALLDATA | H5FD_FEAT_DEFAULT_VFD_COMPATIBLE;
    return 0;
}

haddr_t driverGetEoa(const H5FD_t* file, H5FD_mem_t) {
    return of(file)->eoa;
}

herr_t driverSetEoa(H5FD_t* file, H5FD_mem_t, haddr_t address) {
    of(file)->eoa = address;
    return 0;
}

haddr_t driverGetEof(const H5FD_t* file, H5FD_mem_t) {
    return of(file)->eof;
}

/// The handle is the driver's own record of the file (for fenceRunFile), not a descriptor.
herr_t driverGetHandle(H5FD_t* file, hid_t, void** handle) {
    *handle = of(file);
    return 0;
}

/// True (with an HDF5 error pushed, named after `function`) when [address, address + size) is
/// not inside the file's allocated space.
bool outsideAllocation(const DriverFile* f, haddr_t address, size_t size, const char* function) {
    if (address != HADDR_UNDEF && address + size <= f->eoa) {
        return false;
    }
    H5Epush2(H5E_DEFAULT, kThisFile, function, __LINE__, H5E_ERR_CLS, H5E_IO, H5E_OVERFLOW,
             "addr overflow, addr = %llu, size = %llu, eoa = %llu",
             static_cast<unsigned long long>(address), static_cast<unsigned long long>(size),
             static_cast<unsigned long long>(f->eoa));
    return true;
}

herr_t driverRead(H5FD_t* file, H5FD_mem_t, hid_t, haddr_t address, size_t size, void* buffer) {
    DriverFile* f = of(file);
    if (outsideAllocation(f, address, size, "driverRead")) {
        return -1;
    }
    auto* out = static_cast<unsigned char*>(buffer);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::pread(f->fd, out + done, size - done, off_t(address + done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            return failure("driverRead", H5E_READERROR, "file read failed", errno);
        }
        if (n == 0) {
            std::memset(out + done, 0, size - done); // past the end of the file: zeros
            break;
        }
        done += std::size_t(n);
    }
    // What was written after the fence, over the file's bytes, in write order.
    for (const auto& [at, bytes] : f->held) {
        const haddr_t begin = std::max(at, address);
        const haddr_t end = std::min<haddr_t>(at + bytes.size(), address + size);
        if (begin < end) {
            std::memcpy(out + (begin - address), bytes.data() + (begin - at), end - begin);
        }
    }
    return 0;
}

herr_t driverWrite(H5FD_t* file, H5FD_mem_t, hid_t, haddr_t address, size_t size,
                   const void* buffer) {
    DriverFile* f = of(file);
    if (outsideAllocation(f, address, size, "driverWrite")) {
        return -1;
    }
    const auto* in = static_cast<const unsigned char*>(buffer);
    if (f->fenced) {
        f->held.emplace_back(address, std::vector<unsigned char>(in, in + size));
    } else {
        std::size_t done = 0;
        while (done < size) {
            const ssize_t n = ::pwrite(f->fd, in + done, size - done, off_t(address + done));
            if (n < 0 && errno == EINTR) {
                continue;
            }
            if (n <= 0) {
                return failure("driverWrite", H5E_WRITEERROR, "file write failed",
                               n < 0 ? errno : EIO);
            }
            done += std::size_t(n);
        }
    }
    f->eof = std::max<haddr_t>(f->eof, address + size);
    return 0;
}

/// Sets the file's length to the end of allocation (at every flush and at close). Unlike the
/// POSIX driver it compares with the length on disk, not only with what HDF5 wrote: the run file
/// allocates blocks past the end before a flush (RunFile), and gives back those not used here.
herr_t driverTruncate(H5FD_t* file, hid_t, hbool_t) {
    DriverFile* f = of(file);
    if (f->fenced) {
        f->eof = f->eoa;
        return 0;
    }
    struct stat info {};
    if (::fstat(f->fd, &info) != 0) {
        return failure("driverTruncate", H5E_SEEKERROR, "unable to fstat file", errno);
    }
    if (haddr_t(info.st_size) != f->eoa && ::ftruncate(f->fd, off_t(f->eoa)) != 0) {
        return failure("driverTruncate", H5E_SEEKERROR, "unable to extend file properly", errno);
    }
    f->eof = f->eoa;
    return 0;
}

herr_t driverLock(H5FD_t* file, hbool_t readWrite) {
    if (::flock(of(file)->fd, (readWrite ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0) {
        return failure("driverLock", H5E_CANTLOCKFILE, "unable to lock file", errno);
    }
    return 0;
}

herr_t driverUnlock(H5FD_t* file) {
    if (::flock(of(file)->fd, LOCK_UN) != 0) {
        return failure("driverUnlock", H5E_CANTUNLOCKFILE, "unable to unlock file", errno);
    }
    return 0;
}

H5FD_class_t makeClass() {
    H5FD_class_t c{};
    c.name = "grainlab_run_file";
    c.maxaddr = (haddr_t(1) << (8 * sizeof(off_t) - 1)) - 1;
    c.fc_degree = H5F_CLOSE_WEAK;
    c.open = driverOpen;
    c.close = driverClose;
    c.cmp = driverCompare;
    c.query = driverQuery;
    c.get_eoa = driverGetEoa;
    c.set_eoa = driverSetEoa;
    c.get_eof = driverGetEof;
    c.get_handle = driverGetHandle;
    c.read = driverRead;
    c.write = driverWrite;
    c.truncate = driverTruncate;
    c.lock = driverLock;
    c.unlock = driverUnlock;
    const H5FD_mem_t map[] = H5FD_FLMAP_DICHOTOMY;
    std::copy(std::begin(map), std::end(map), c.fl_map);
    return c;
}

/// The driver's id, registered once per life of the library.
hid_t driverId() {
    static const H5FD_class_t driverClass = makeClass();
    static hid_t id = H5I_INVALID_HID;
    if (id < 0 || H5Iis_valid(id) <= 0) {
        id = H5FDregister(&driverClass);
    }
    return id;
}

} // namespace

H5::FileAccPropList withRunFileDriver(const H5::FileAccPropList& access) {
    const hid_t copy = H5Pcopy(access.getId());
    H5::FileAccPropList out(copy); // takes a reference of its own
    H5Idec_ref(copy);
    if (H5Pset_driver(out.getId(), driverId(), nullptr) < 0) {
        throw H5::PropListIException("withRunFileDriver", "H5Pset_driver failed");
    }
    return out;
}

bool fenceRunFile(hid_t file) {
    hid_t access = H5Fget_access_plist(file);
    const bool ours = access >= 0 && H5Pget_driver(access) == driverId();
    if (access >= 0) {
        H5Pclose(access);
    }
    void* handle = nullptr;
    if (!ours || H5Fget_vfd_handle(file, H5P_DEFAULT, &handle) < 0 || handle == nullptr) {
        return false;
    }
    static_cast<DriverFile*>(handle)->fenced = true;
    return true;
}

} // namespace grainlab::hdf5io
