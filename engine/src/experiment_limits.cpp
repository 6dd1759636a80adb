#include "grainlab/experiment_limits.h"

#include <algorithm>
#include <limits>

#include <unistd.h>

namespace grainlab {

std::int64_t maxGrainCount() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGESIZE);
    const std::int64_t memory =
        pages > 0 && pageSize > 0 ? std::int64_t(pages) * std::int64_t(pageSize) : 0;
    const std::int64_t count = memory / kBytesPerGrain;
    return std::clamp<std::int64_t>(count, 1000, std::numeric_limits<std::int32_t>::max());
}

} // namespace grainlab
