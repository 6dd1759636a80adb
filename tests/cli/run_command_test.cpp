// `grainlab run` end to end (issue 3): the quick experiment's outputs, resume equal to an
// uninterrupted run, Ctrl-C leaving valid files, a failing run keeping its data.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <H5Cpp.h>

#include "cli/run_command.h"
#include "cli/run_output.h"
#include "cli_test_files.h"
#include "grainlab/csv_series.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/measures.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

const std::string kSource = GRAINLAB_SOURCE_DIR;

fs::path freshFolder(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / fmt::format("grainlab-test-{}-{}", name, getpid());
    fs::remove_all(p);
    return p;
}

using test::readText;

/// A tiny experiment: the quick protocol cut to one pressure and a short shear.
nlohmann::json tinyExperiment() {
    nlohmann::json j =
        nlohmann::json::parse(readText(kSource + "/resources/experiments/quick.json"));
    j["name"] = "tiny";
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {50e3};
    j["shear"]["target_axial_strain"] = 0.004;
    j["record"]["strain_interval"] = 2e-4;
    j["record"]["snapshot_strain_interval"] = 1e-3;
    j["record"]["snapshot_step_interval"] = 5000;
    return j;
}

fs::path writeExperiment(const fs::path& folder, const nlohmann::json& j) {
    fs::create_directories(folder);
    const fs::path p = folder / "experiment.json";
    std::ofstream(p) << j.dump(2);
    return p;
}

int runGrainlab(const std::string& arguments) {
    const int status =
        std::system(fmt::format("{} {} > /dev/null 2>&1", GRAINLAB_EXE, arguments).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RunCommand, QuickExperimentEndToEnd) {
    const fs::path out = freshFolder("quick");
    const std::string quick = kSource + "/resources/experiments/quick.json";
    ASSERT_EQ(runGrainlab(fmt::format("run {} --out {} --quiet", quick, out.string())), 0);
    const ExperimentConfig config = readExperimentFile(quick);

    // Every test has a series.csv with the documented header, and the run file the same series.
    std::vector<std::string> header;
    for (const auto& c : seriesColumns()) {
        header.push_back(seriesHeader(c));
    }
    const std::string runFile = (out / "run.h5").string();
    EXPECT_EQ(readExperimentText(runFile), config.sourceText);
    for (double pressure : config.shear.pressures) {
        const std::string test = fmt::format("p{:03d}kPa", int(pressure / 1000));
        const fs::path csv = out / test / "series.csv";
        ASSERT_TRUE(fs::exists(csv)) << csv;
        std::ifstream in(csv);
        std::string first;
        std::getline(in, first);
        std::string expected;
        for (std::size_t k = 0; k < header.size(); ++k) {
            expected += (k ? "," : "") + header[k];
        }
        EXPECT_EQ(first, expected);
        const SeriesTable t = readSeriesCsv(csv.string());
        const SeriesTable h5 = readSeries(runFile, test);
        ASSERT_EQ(t.rows.size(), h5.rows.size());
        ASSERT_GT(t.rows.size(), 100u);
        const int s22 = t.column("sigma22"), e1 = t.column("eps1"), z = t.column("Z");
        ASSERT_GE(s22, 0);
        double lastEps1 = 0;
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            for (double v : t.rows[r]) {
                ASSERT_TRUE(std::isfinite(v));
            }
            if (t.stages[r].rfind("shear", 0) == 0) {
                // Drained shear: lateral stress held within 1 % of the confining pressure.
                EXPECT_NEAR(t.rows[r][s22], pressure, 0.01 * pressure)
                    << test << " row " << r << " eps1 " << t.rows[r][e1];
                EXPECT_GT(t.rows[r][z], 2.0);
                lastEps1 = t.rows[r][e1];
            }
        }
        EXPECT_NEAR(lastEps1, config.shear.targetAxialStrain, 1e-9) << test;
    }
    // Compaction ends at each target stress.
    const SeriesTable c = readSeriesCsv((out / "compaction" / "series.csv").string());
    const int s11 = c.column("sigma11"), s22 = c.column("sigma22");
    for (double pressure : config.compaction.pressures) {
        const std::string stage = fmt::format("compaction {:g} kPa", pressure / 1000);
        int last = -1;
        for (std::size_t r = 0; r < c.rows.size(); ++r) {
            if (c.stages[r] == stage) {
                last = static_cast<int>(r);
            }
        }
        ASSERT_GE(last, 0) << stage;
        EXPECT_NEAR(c.rows[last][s11], pressure, 0.01 * pressure) << stage;
        EXPECT_NEAR(c.rows[last][s22], pressure, 0.01 * pressure) << stage;
    }
    EXPECT_EQ(listSamples(runFile).size(), config.compaction.pressures.size());
    EXPECT_EQ(std::system(fmt::format("h5dump -H {} > /dev/null", runFile).c_str()), 0);
    fs::remove_all(out);
}

TEST(RunCommand, ResumeEqualsUninterruptedRun) {
    const fs::path base = freshFolder("resume");
    const fs::path experiment = writeExperiment(base, tinyExperiment());
    const ExperimentConfig config = readExperimentFile(experiment.string());

    // Uninterrupted.
    RunOptions whole;
    whole.experiment = experiment.string();
    whole.out = (base / "whole").string();
    whole.quiet = true;
    ASSERT_EQ(runExperimentCommand(whole), 0);

    // Interrupted in the middle of the shear (in process: advance, checkpoint, stop), resumed.
    {
        RunOutputFolder output((base / "parts").string(), config.sourceText, false);
        ExperimentRunner runner(config, &output);
        while (runner.progress().stage.rfind("shear", 0) != 0 ||
               runner.progress().axialStrain < 0.0017) {
            ASSERT_TRUE(runner.advance(100));
        }
        runner.advance(37); // not at a record boundary
        runner.checkpointNow("interrupted");
        runner.advance(800); // work done after the checkpoint is lost, and its rows dropped
    }
    RunOptions rest;
    rest.resume = (base / "parts").string();
    rest.quiet = true;
    ASSERT_EQ(runExperimentCommand(rest), 0);

    for (const std::string test : {"compaction", "p050kPa"}) {
        const std::string a = readText(base / "whole" / test / "series.csv");
        const std::string b = readText(base / "parts" / test / "series.csv");
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, b) << test << ": resumed series differ from the uninterrupted run";
        const SeriesTable ha = readSeries((base / "whole" / "run.h5").string(), test);
        const SeriesTable hb = readSeries((base / "parts" / "run.h5").string(), test);
        EXPECT_EQ(ha.rows, hb.rows) << test;
    }
    const auto last = [](const fs::path& folder) {
        const std::string f = (folder / "run.h5").string();
        return readState(f, checkpointGroup(listCheckpoints(f).back()));
    };
    const SimulationState sa = last(base / "whole"), sb = last(base / "parts");
    EXPECT_EQ(sa.step, sb.step);
    {
        // Every checkpoint carries its void cells; their areas tile the cell.
        const std::string f = (base / "whole" / "run.h5").string();
        H5::H5File file(f, H5F_ACC_RDONLY);
        H5::DataSet ds =
            file.openDataSet(checkpointGroup(listCheckpoints(f).back()) + "/void_cells/area");
        hsize_t n = 0;
        ds.getSpace().getSimpleExtentDims(&n);
        std::vector<double> area(n);
        ds.read(area.data(), H5::PredType::NATIVE_DOUBLE);
        double sum = 0;
        for (double a : area) {
            sum += a;
        }
        ASSERT_GT(n, 50u);
        EXPECT_NEAR(sum, sa.cell[0] * sa.cell[3] - sa.cell[1] * sa.cell[2], 1e-9 * sum);
    }
    EXPECT_EQ(sa.grains.x1, sb.grains.x1);
    EXPECT_EQ(sa.grains.omega, sb.grains.omega);
    EXPECT_EQ(sa.pairs.tangentialForce, sb.pairs.tangentialForce);
    fs::remove_all(base);
}

TEST(RunCommand, InterruptLeavesValidFilesAndResumes) {
    const fs::path base = freshFolder("interrupt");
    nlohmann::json j = tinyExperiment();
    j["shear"]["target_axial_strain"] = 0.1; // long enough to be interrupted
    const fs::path experiment = writeExperiment(base, j);
    const fs::path out = base / "out";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::freopen("/dev/null", "w", stderr);
        execl(GRAINLAB_EXE, GRAINLAB_EXE, "run", experiment.c_str(), "--out", out.c_str(),
              "--quiet", static_cast<char*>(nullptr));
        _exit(127);
    }
    // Wait until the run is shearing, then Ctrl-C.
    const std::string csv = (out / "p050kPa" / "series.csv").string();
    for (int k = 0; k < 1200 && !fs::exists(csv); ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    kill(child, SIGINT);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    const std::string runFile = (out / "run.h5").string();
    EXPECT_EQ(std::system(fmt::format("h5dump -H {} > /dev/null", runFile).c_str()), 0);
    const auto checkpoints = listCheckpoints(runFile);
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_NE(checkpoints.back().find("interrupted"), std::string::npos);
    const SeriesTable t = readSeriesCsv(csv);
    EXPECT_GT(t.rows.size(), 0u);
    RunOptions rest;
    rest.resume = out.string();
    rest.quiet = true;
    EXPECT_EQ(runExperimentCommand(rest), 0);
    const SeriesTable done = readSeriesCsv(csv);
    EXPECT_NEAR(done.rows.back()[done.column("eps1")], 0.1, 1e-9);
    fs::remove_all(base);
}

TEST(RunCommand, FailingRunKeepsItsCheckpointAndWritesNoNan) {
    const fs::path base = freshFolder("fail");
    nlohmann::json j = tinyExperiment();
    // An overlap limit no compaction can respect: the run must stop with the documented error.
    j["stability"]["max_overlap_fraction"] = 1e-4;
    j["record"]["snapshot_step_interval"] = 200;
    j["record"]["step_interval"] = 100;
    const fs::path experiment = writeExperiment(base, j);
    const fs::path out = base / "out";
    RunOptions o;
    o.experiment = experiment.string();
    o.out = out.string();
    o.quiet = true;
    EXPECT_EQ(runExperimentCommand(o), 1);
    const std::string runFile = (out / "run.h5").string();
    EXPECT_EQ(std::system(fmt::format("h5dump -H {} > /dev/null", runFile).c_str()), 0);
    EXPECT_FALSE(listCheckpoints(runFile).empty());
    const SeriesTable t = readSeriesCsv((out / "compaction" / "series.csv").string());
    ASSERT_GT(t.rows.size(), 0u);
    for (const auto& row : t.rows) {
        for (double v : row) {
            EXPECT_TRUE(std::isfinite(v));
        }
    }
    fs::remove_all(base);
}

TEST(RunCommand, BadExperimentFileNamesFileAndKey) {
    const fs::path base = freshFolder("bad");
    nlohmann::json j = tinyExperiment();
    j["grains"]["aspect_ratio"] = 1.5;
    const fs::path experiment = writeExperiment(base, j);
    const std::string command = fmt::format("{} run {} --out {} 2>&1", GRAINLAB_EXE,
                                            experiment.string(), (base / "out").string());
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string text;
    char buffer[512];
    while (fgets(buffer, sizeof buffer, pipe)) {
        text += buffer;
    }
    const int status = pclose(pipe);
    EXPECT_NE(WEXITSTATUS(status), 0);
    EXPECT_NE(text.find("experiment.json"), std::string::npos) << text;
    EXPECT_NE(text.find("grains.aspect_ratio"), std::string::npos) << text;
    EXPECT_NE(text.find("1.5"), std::string::npos) << text;
    fs::remove_all(base);
}

} // namespace
} // namespace grainlab
