#pragma once
// The file driver of run files (private to the engine): HDF5's POSIX driver (sec2) with one
// addition, a fence. After a write of the run file failed half-way (a full disk, a file size
// limit), fenceRunFile() makes every later write of HDF5 to that file succeed without reaching
// the disk: HDF5 keeps what it writes in memory, reads see it, and truncation is skipped. The
// library can then flush and close the file as if nothing failed, while the file on disk stays
// exactly as its last complete flush left it.
//
// Why a driver: HDF5 1.10 cannot abandon a file. Closing a file whose flush fails leaves a
// freed file in the library's table, and the library's clean-up at exit crashed on it
// (SIGSEGV in H5F__close_cb); a file never closed is closed (and flushed) by that clean-up. And
// no descriptor swapped in for the file takes every write: a memory file obeys the file size
// limit too, /dev/null cannot be truncated.
//
// Files written with it are plain HDF5 files (the driver stores nothing in them); every run
// file of this process is opened with it, so that a reader and the writer of the same file
// share it as they would with the POSIX driver.

#include <H5Cpp.h>

namespace grainlab::hdf5io {

/// A copy of `access` that opens the file with the run-file driver.
H5::FileAccPropList withRunFileDriver(const H5::FileAccPropList& access);

/// From now on, writes of HDF5 to the open file `file` (opened with the run-file driver) stay in
/// memory. False if the file was opened with another driver.
bool fenceRunFile(hid_t file);

} // namespace grainlab::hdf5io
