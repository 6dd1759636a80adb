// The run folder is owned by one run (issue 12): a finished run is not run again, a folder in
// use is refused untouched, an existing run is not overwritten without --force, and --force
// leaves none of the old run's files behind.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

fs::path freshFolder(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / fmt::format("grainlab-test-folder-{}-{}", name, getpid());
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

/// 120 grains, one pressure, a short shear: a couple of seconds.
fs::path writeTinyExperiment(const fs::path& folder, double targetStrain = 0.002) {
    nlohmann::json j = nlohmann::json::parse(
        readText(std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json"));
    j["name"] = "tiny";
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = targetStrain;
    j["record"]["snapshot_strain_interval"] = 1e-3;
    j["record"]["snapshot_step_interval"] = 5000;
    const fs::path p = folder / "experiment.json";
    std::ofstream(p) << j.dump(2);
    return p;
}

struct Result {
    int status = -1;    ///< exit status, or -1
    std::string output; ///< stdout and stderr
};

Result runGrainlab(const std::string& arguments) {
    Result r;
    FILE* pipe = popen(fmt::format("{} {} 2>&1", GRAINLAB_EXE, arguments).c_str(), "r");
    if (!pipe) {
        return r;
    }
    char buffer[512];
    while (fgets(buffer, sizeof buffer, pipe)) {
        r.output += buffer;
    }
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// Every file under `folder` with its bytes.
std::map<std::string, std::string> folderBytes(const fs::path& folder) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
        if (e.is_regular_file()) {
            out[fs::relative(e.path(), folder).string()] = readText(e.path());
        }
    }
    return out;
}

TEST(RunFolder, ResumeOfAFinishedRunChangesNothing) {
    const fs::path base = freshFolder("finished");
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path out = base / "out";
    ASSERT_EQ(runGrainlab(fmt::format("run {} --out {} --quiet", experiment.string(), out.string()))
                  .status,
              0);
    const auto before = folderBytes(out);
    const auto checkpoints = listCheckpoints((out / "run.h5").string());
    const Result r = runGrainlab(fmt::format("run --resume {} --quiet", out.string()));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("is finished"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
    EXPECT_EQ(folderBytes(out), before) << "a resume of a finished run changed its files";
    EXPECT_EQ(listCheckpoints((out / "run.h5").string()), checkpoints);
    fs::remove_all(base);
}

} // namespace
} // namespace grainlab
