#pragma once
// Room on disk for the writes of a run file (private to the engine), so that a write that fails
// for room (a full disk, a file size limit) never leaves the file unreadable.
//
// HDF5 1.10 updates its metadata in place. Measured with a file size limit at 2 to 98 % of a
// finished run file's size and the room check bypassed (GRAINLAB_TEST_NO_ROOM_CHECK=1): (1) an
// H5Fflush whose chunk writes fail goes on to write the metadata (the parent group's links, the
// superblock) that points at them, and the file no longer opens ("H5Gopen2 failed"); (2)
// closing a file whose flush fails leaves a freed file in the library's table, on which the
// library's clean-up at exit crashed (SIGSEGV in H5F__close_cb). So the writer (run_file.cpp):
// - checks the room for a write before it (ensureRoom), which refuses most writes that would
//   fail with nothing of them written;
// - writes every dataset through (writeThrough() in run_file_io.h): chunks go to disk in
//   H5Dwrite, into new space past the end of the file, or in place for rows appended to a
//   series' chunk (whose earlier rows and checksum on disk stay valid), and a failed one throws
//   there. New metadata waits in HDF5's cache, so a flush writes metadata only;
// - before every flush allocates every block up to HDF5's end of allocation and a margin
//   (allocateToEnd): if the disk or the limit refuses, nothing of the flush is written; if not,
//   the flush writes into allocated blocks only and cannot fail for room;
// - after a failure fences the file (run_file_driver.h): HDF5 can flush and close it, now or at
//   exit, without an error and without touching the file on disk, whose last flush holds the
//   last complete checkpoint.
// With these, each of 33 limits from 2 to 98 % gave exit status 1, a readable file, and a
// resumed run with the series of an uninterrupted one (tests/cli/write_failure_test.cpp).

#include <H5Cpp.h>

#include <cstdint>
#include <string>

namespace grainlab::hdf5io {

/// Refuses (std::runtime_error, nothing written) a write of about `bytes` to the file `path`
/// (open as `file`) that its file system or the file size limit has no room for, and reserves
/// the blocks past its end (its size unchanged) through `reserveFd` (opened when < 0), so that
/// another program filling the disk cannot make the write fail half-way.
void ensureRoom(const std::string& path, hid_t file, int& reserveFd, std::uint64_t bytes,
                const std::string& what);

/// Allocates every block of the file up to HDF5's end of allocation and a margin, the file
/// growing to it (the driver gives back the margin as the flush truncates the file). Throws
/// Hdf5Error naming the cause (the disk is full, the file size limit is reached).
void allocateToEnd(const std::string& path, hid_t file, int& reserveFd);

/// Gives back the blocks reserved past the end of the file (its size unchanged) and closes
/// `reserveFd` (if open).
void releaseReserve(int& reserveFd);

} // namespace grainlab::hdf5io
