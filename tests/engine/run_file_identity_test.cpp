// Identity as data (issue 11): every checkpoint of a run records its stage kind, test,
// pressure, step, eps1 and the orientations at its test's start; every series row its stage
// kind and pressure. Checked on a real run against what the runner says of itself.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "experiment_fixtures.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

TEST(RunFileIdentity, CheckpointsAndRowsCarryTheirStage) {
    nlohmann::json j = test::quickExperiment();
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {25e3, 50e3};
    j["shear"]["pressures"] = {25e3, 50e3};
    j["shear"]["target_axial_strain"] = 0.002;
    j["record"]["snapshot_strain_interval"] = 1e-3;
    j["record"]["snapshot_step_interval"] = 5000;
    const ExperimentConfig config = parseExperimentText(j.dump(), "identity.json");
    const fs::path dir = fs::temp_directory_path() / fmt::format("grainlab_identity_{}", getpid());
    fs::create_directories(dir);
    const std::string path = (dir / "run.h5").string();

    // What the runner says of itself at each checkpoint, through a recording output.
    struct Recorder : RunFile {
        using RunFile::RunFile;
        std::map<std::string, StageIdentity> seen;
        void checkpoint(const CheckpointData& data) override {
            seen[data.name] = data.identity;
            RunFile::checkpoint(data);
        }
    };
    std::map<std::string, StageIdentity> seen;
    std::vector<double> sample25Theta;
    {
        Recorder file(path, config.sourceText);
        ExperimentRunner runner(config, &file);
        while (runner.advance(500)) {
        }
        seen = file.seen;
    }
    sample25Theta = readState(path, sampleGroup(25e3)).grains.theta;

    const std::vector<CheckpointInfo> infos = listCheckpointInfo(path);
    ASSERT_EQ(infos.size(), seen.size());
    std::map<std::string, int> kinds;
    for (const CheckpointInfo& info : infos) {
        const StageIdentity& id = seen.at(info.name);
        EXPECT_EQ(info.stageKind, id.kind) << info.name;
        EXPECT_EQ(info.test, id.test) << info.name;
        EXPECT_EQ(info.pressure, id.pressure) << info.name;
        EXPECT_EQ(info.axialStrain, id.axialStrain) << info.name;
        EXPECT_EQ(info.step, readState(path, checkpointGroup(info.name)).step) << info.name;
        EXPECT_EQ(readThetaAtTestStart(path, info.name), id.thetaAtTestStart) << info.name;
        // The name says the same thing in words: "000012-shear-25-kPa-step88000".
        EXPECT_NE(info.name.find(fmt::format("{}-{:g}-kPa-step{}", info.stageKind,
                                             info.pressure / 1000, info.step)),
                  std::string::npos)
            << info.name;
        ++kinds[info.stageKind];
        if (info.test == "p025kPa") {
            // Rotation of test p025kPa counts from its sample.
            EXPECT_EQ(readThetaAtTestStart(path, info.name), sample25Theta) << info.name;
        }
        if (info.stageKind == "compaction") {
            EXPECT_EQ(info.test, "compaction");
            EXPECT_FALSE(readThetaAtTestStart(path, info.name).empty());
        }
    }
    EXPECT_GT(kinds["compaction"], 0);
    EXPECT_EQ(kinds["equilibration"], 2);
    EXPECT_GT(kinds["shear"], 2);
    // Every row: the kind and pressure of its stage, as its stage text says.
    for (const std::string& test : listTests(path)) {
        const SeriesTable t = readSeries(path, test);
        ASSERT_EQ(t.stageKinds.size(), t.rows.size());
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            EXPECT_EQ(t.stages[r],
                      fmt::format("{} {:g} kPa", t.stageKinds[r], t.stagePressures[r] / 1000))
                << test << " row " << r;
        }
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace grainlab
