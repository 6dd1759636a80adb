#pragma once
// Files and folders for the command-line tests: a file's whole text and a fresh folder per test
// process (ctest runs the tests side by side).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace grainlab::test {

inline std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// An empty folder grainlab-test-<kind>-<name>-<pid> in the temporary folder.
inline std::filesystem::path freshFolder(const std::string& kind, const std::string& name) {
    const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                    fmt::format("grainlab-test-{}-{}-{}", kind, name, getpid());
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p;
}

#ifdef GRAINLAB_EXE
/// In a forked child: replaces it by grainlab with `arguments` (exit status 127 if that fails).
[[noreturn]] inline void execGrainlab(const std::vector<std::string>& arguments) {
    std::vector<char*> argv{const_cast<char*>(GRAINLAB_EXE)};
    for (const auto& a : arguments) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    execv(GRAINLAB_EXE, argv.data());
    _exit(127);
}
#endif

} // namespace grainlab::test
