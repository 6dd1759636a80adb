#pragma once
// Folders, files and commands for the study and stability tests: a fresh folder per test process
// (ctest runs the tests side by side), a file's whole text, a shell command's exit status, a
// stability preset run, and the processes the pool started (from /proc).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace grainlab::test {

inline std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("grainlab-study-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    return dir;
}

/// The exit status of `command` run by the shell (-1 when a signal ended it).
inline int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The same, its output dropped.
inline int runQuietly(const std::string& command) {
    return run(command + " >/dev/null 2>&1");
}

inline std::string text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

#ifdef GRAINLAB_EXE
/// `grainlab stability <arguments>`, its output dropped: its exit status.
inline int runStability(const std::string& arguments) {
    return runQuietly(std::string(GRAINLAB_EXE) + " stability " + arguments);
}

/// `grainlab stability --preset <preset> --out <out> <then>`, its output dropped: its exit status.
inline int runStabilityPreset(const std::string& preset, const std::filesystem::path& out,
                              const std::string& then = "--quiet") {
    return runStability("--preset " + preset + " --out " + out.string() + " " + then);
}

/// A fresh folder named after the stability preset `preset` with the preset run into it (what
/// the test cannot go on without: std::runtime_error, a failure of the test, when it fails).
inline std::filesystem::path presetRunFolder(const std::string& preset) {
    const std::filesystem::path dir = freshFolder(preset);
    if (const int status = runStabilityPreset(preset, dir); status != 0) {
        throw std::runtime_error("grainlab stability --preset " + preset + " --out " +
                                 dir.string() + ": exit status " + std::to_string(status));
    }
    return dir;
}
#endif

/// The shipped stability preset `name` (resources/stability/<name>.json).
inline std::string stabilityPresetFile(const std::string& name) {
    return std::string(GRAINLAB_SOURCE_DIR) + "/resources/stability/" + name + ".json";
}

/// The result file of the cell `id` in the map folder `dir`.
inline std::filesystem::path cellFile(const std::filesystem::path& dir, const std::string& id) {
    return dir / "cells" / (id + ".json");
}

/// Those of the figures `names` that are not in the folder `dir`/figures. A build without the
/// window draws no figures: then none is missing.
inline std::vector<std::string> missingFigures(const std::filesystem::path& dir,
                                               const std::vector<std::string>& names) {
    std::vector<std::string> missing;
#ifdef GRAINLAB_WITH_GUI
    for (const std::string& name : names) {
        if (!std::filesystem::exists(dir / "figures" / name)) {
            missing.push_back(name);
        }
    }
#else
    (void)dir;
    (void)names;
#endif
    return missing;
}

/// The pids of the processes whose parent is `parent` (from /proc).
inline std::vector<pid_t> childrenOf(pid_t parent) {
    std::vector<pid_t> out;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        const std::string name = entry.path().filename();
        if (name.find_first_not_of("0123456789") != std::string::npos) {
            continue;
        }
        std::istringstream stat(text(entry.path() / "stat"));
        std::string pid, comm, state;
        pid_t ppid = 0;
        stat >> pid >> comm >> state >> ppid;
        if (ppid == parent) {
            out.push_back(pid_t(std::stoi(name)));
        }
    }
    return out;
}

/// Whether `pid` still runs: neither gone nor a zombie waiting to be reaped.
inline bool processRuns(pid_t pid) {
    std::istringstream stat(text(std::filesystem::path("/proc") / std::to_string(pid) / "stat"));
    std::string id, comm, state;
    stat >> id >> comm >> state;
    return !state.empty() && state != "Z" && state != "X";
}

} // namespace grainlab::test
