#pragma once
// Files, folders and commands for the command-line tests: a file's whole text, a fresh folder per
// test process (ctest runs the tests side by side), and grainlab run as a command or a child.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

/// The quick experiment (resources/experiments/quick.json) made a run of a few seconds: named
/// `name`, 120 grains compacted and sheared at 50 kPa to `targetStrain`, a checkpoint every 0.1 %
/// of strain or 5000 steps. Written to <folder>/experiment.json, whose path it returns.
inline std::filesystem::path writeTinyExperiment(const std::filesystem::path& folder,
                                                 const std::string& name, double targetStrain) {
    nlohmann::json j = nlohmann::json::parse(
        readText(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json"));
    j["name"] = name;
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = targetStrain;
    j["record"]["snapshot_strain_interval"] = 1e-3;
    j["record"]["snapshot_step_interval"] = 5000;
    const std::filesystem::path p = folder / "experiment.json";
    std::ofstream(p) << j.dump(2);
    return p;
}

#ifdef GRAINLAB_EXE
/// How a grainlab command ended and what it said.
struct CommandOutput {
    int status = -1;    ///< exit status, or -1 when it did not exit
    std::string output; ///< stdout and stderr
};

/// Runs `environment grainlab arguments` through the shell and waits for it.
inline CommandOutput grainlabOutput(const std::string& arguments,
                                    const std::string& environment = {}) {
    const std::string command = fmt::format("{} {} {} 2>&1", environment, GRAINLAB_EXE, arguments);
    CommandOutput out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        return out;
    }
    char buffer[1024];
    while (fgets(buffer, sizeof buffer, pipe)) {
        out.output += buffer;
    }
    const int status = pclose(pipe);
    out.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

/// `grainlab run experiment --out out --quiet`: how it ended and what it said.
inline CommandOutput runOutput(const std::filesystem::path& experiment,
                               const std::filesystem::path& out) {
    return grainlabOutput(
        fmt::format("run {} --out {} --quiet", experiment.string(), out.string()));
}

/// `grainlab run --resume folder --quiet`: how it ended and what it said.
inline CommandOutput resumeOutput(const std::filesystem::path& folder) {
    return grainlabOutput(fmt::format("run --resume {} --quiet", folder.string()));
}

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
