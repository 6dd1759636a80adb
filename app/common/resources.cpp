#include "common/resources.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace grainlab {

namespace fs = std::filesystem;

std::string resourceDirectory() {
    if (const char* dir = std::getenv("GRAINLAB_RESOURCES"); dir && *dir) {
        return dir;
    }
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) {
        return "share/grainlab"; // no /proc: relative to the working folder
    }
    return (exe.parent_path().parent_path() / "share" / "grainlab").string();
}

std::string resourcePath(const std::string& relative) {
    return (fs::path(resourceDirectory()) / relative).string();
}

} // namespace grainlab
