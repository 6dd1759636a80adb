#include "run_file_room.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "run_file_io.h"

namespace grainlab::hdf5io {

void ensureRoom(const std::string& path, hid_t file, int& reserveFd, std::uint64_t bytes,
                const std::string& what) {
    constexpr std::uint64_t kMargin = std::uint64_t(1) << 19; // HDF5 metadata, new chunks
    const std::uint64_t needed = bytes + bytes / 4 + kMargin;
    std::uint64_t room = std::numeric_limits<std::uint64_t>::max();
    std::string where;
    struct statvfs fsinfo {};
    const std::string folder = std::filesystem::path(path).parent_path().string();
    if (::statvfs(folder.empty() ? "." : folder.c_str(), &fsinfo) == 0) {
        room = std::uint64_t(fsinfo.f_bavail) * fsinfo.f_frsize;
        where = "free on its file system";
    }
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        std::error_code error;
        const std::uint64_t size = std::filesystem::file_size(path, error);
        std::uint64_t end = error ? 0 : size;
        haddr_t eoa = 0;
        if (H5Fget_filesize(file, reinterpret_cast<hsize_t*>(&eoa)) >= 0) {
            end = std::max<std::uint64_t>(end, eoa);
        }
        const std::uint64_t left = limit.rlim_cur > end ? limit.rlim_cur - end : 0;
        if (left < room) {
            room = left;
            where = "left under the file size limit";
        }
    }
    // Reserve the blocks past the file's end (its size unchanged): another program filling
    // the disk between this check and the write can then not make the write fail half-way.
    // A file system without fallocate() gets the statvfs() check only.
    if (room >= needed) {
        if (reserveFd < 0) {
            reserveFd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        }
        std::error_code error;
        const std::uint64_t size = std::filesystem::file_size(path, error);
        if (reserveFd >= 0 && !error &&
            ::fallocate(reserveFd, FALLOC_FL_KEEP_SIZE, off_t(size), off_t(needed)) != 0 &&
            (errno == ENOSPC || errno == EDQUOT)) {
            room = 0;
            where = "that the file system could reserve";
        }
    }
    if (room < needed) {
        throw std::runtime_error(fmt::format(
            "{}: no room to write {} (about {:.1f} MB needed, {:.1f} MB {}); nothing of it "
            "was written and the file keeps everything written before",
            path, what, needed / 1e6, room / 1e6, where));
    }
}

void allocateToEnd(const std::string& path, hid_t file, int& reserveFd) {
    hsize_t end = 0;
    if (H5Fget_filesize(file, &end) < 0) {
        throw hdf5io::Hdf5Error(fmt::format("{}: cannot read the size of the file", path));
    }
    if (reserveFd < 0) {
        reserveFd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    }
    if (reserveFd < 0) {
        throw hdf5io::Hdf5Error(fmt::format("{}: cannot open the file to allocate its "
                                            "blocks: {}",
                                            path, std::strerror(errno)));
    }
    // HDF5 gives some metadata its place in the file only as it flushes it (the fractal
    // heaps of a group's links and attributes): a flush at 53 % of a run file's size wrote
    // past the end of allocation measured before it. Measured growth during a flush: at
    // most 6 KB (60 and 1500 grains); the margin leaves room for a heap block of 64 KB.
    constexpr hsize_t kFlushMargin = hsize_t(256) << 10;
    end += kFlushMargin;
    if (::fallocate(reserveFd, 0, 0, off_t(end)) != 0) {
        const int cause = errno;
        if (cause == EOPNOTSUPP || cause == ENOSYS) {
            return; // a file system without fallocate(): the room check only
        }
        const std::string needed = fmt::format("{:.1f} MB needed in all", end / 1e6);
        throw hdf5io::Hdf5Error(
            cause == EFBIG
                ? fmt::format("the file size limit is reached (File too large; {})", needed)
            : cause == ENOSPC || cause == EDQUOT
                ? fmt::format("the disk is full ({}; {})", std::strerror(cause), needed)
                : fmt::format("no room to write ({}; {})", std::strerror(cause), needed));
    }
}

void releaseReserve(int& reserveFd) {
    if (reserveFd < 0) {
        return;
    }
    struct stat info {};
    if (::fstat(reserveFd, &info) == 0) {
        (void)::ftruncate(reserveFd, info.st_size);
    }
    ::close(reserveFd);
    reserveFd = -1;
}

} // namespace grainlab::hdf5io
