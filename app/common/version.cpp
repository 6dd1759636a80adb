#include "common/version.h"

#include <fmt/format.h>

#include "grainlab_commit.h" // generated at every build (common/commit_header.cmake)

namespace grainlab {

std::string buildCommit() {
    return GRAINLAB_COMMIT;
}

std::string versionText() {
    return fmt::format("GrainLab {} (commit {})", GRAINLAB_VERSION, buildCommit());
}

} // namespace grainlab
