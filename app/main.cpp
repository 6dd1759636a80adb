// The grainlab executable: see app/command_line.h.
#include "command_line.h"

#include <cstdlib> // a C library header: defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

/// A run builds buffers of megabytes hundreds of times (each record's contact network and void
/// cells' half-edges, each checkpoint's). By default glibc returns such a buffer to the system
/// when it is freed and the next one is faulted in again page by page, which on a virtual machine
/// can cost more than the arithmetic (docs/benchmarks.md, "Where a run's time goes"). The
/// process keeps what it frees for its next use instead: its memory stays at its peak. (The
/// Python module leaves the interpreter's allocator as it is.)
void keepFreedMemory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

} // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    return grainlab::runCommandLine(argc, argv);
}
