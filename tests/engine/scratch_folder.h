#pragma once
// A fresh folder per test process for the tests that write files (ctest runs the tests side by
// side).
#include <unistd.h>

#include <filesystem>
#include <string>

namespace grainlab::test {

/// An empty folder grainlab_<kind>_<name>_<pid> in the temporary folder.
inline std::filesystem::path scratchFolder(const std::string& kind, const std::string& name) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() /
        ("grainlab_" + kind + "_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

} // namespace grainlab::test
