// The run folder is owned by one run (issue 12): a finished run is not run again, a folder in
// use is refused untouched, an existing run is not overwritten without --force, and --force
// leaves none of the old run's files behind.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../engine/child_output.h"
#include "cli_test_files.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using test::CommandOutput;
using test::grainlabOutput;
using test::readText;
using test::resumeOutput;
using test::runOutput;

/// Each test's own empty folder (named after the test), removed at its end unless the test
/// failed (then kept, to be looked at).
class RunFolder : public ::testing::Test {
protected:
    void TearDown() override {
        if (!HasFailure()) {
            fs::remove_all(base);
        }
    }

    const fs::path base = test::freshFolder(
        "folder", ::testing::UnitTest::GetInstance()->current_test_info()->name());
};

/// 120 grains, one pressure, a short shear: a couple of seconds.
fs::path writeTinyExperiment(const fs::path& folder, double targetStrain = 0.002) {
    return test::writeTinyExperiment(folder, "tiny", targetStrain);
}

/// `grainlab run experiment --out out --quiet` started as a child process (its output
/// discarded), not waited for: its pid, or -1.
pid_t startRun(const fs::path& experiment, const fs::path& out) {
    const pid_t child = fork();
    if (child == 0) {
        std::freopen("/dev/null", "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        execl(GRAINLAB_EXE, GRAINLAB_EXE, "run", experiment.c_str(), "--out", out.c_str(),
              "--quiet", static_cast<char*>(nullptr));
        _exit(127);
    }
    return child;
}

/// Every file under `folder` with its bytes.
/// `grainlab run` of `experiment` into `out`, stopped by SIGINT after `steps` steps (the
/// GRAINLAB_TEST_STOP_AFTER_STEPS hook): true when it ended as an interrupted run does (130).
bool interruptedRun(const fs::path& experiment, const fs::path& out, int steps) {
    const std::string command = fmt::format(
        "GRAINLAB_TEST_STOP_AFTER_STEPS={} GRAINLAB_TEST_STOP_SIGNAL=INT {} run {} --out {} "
        "--quiet > /dev/null 2>&1",
        steps, GRAINLAB_EXE, experiment.string(), out.string());
    const int status = std::system(command.c_str());
    return WIFEXITED(status) && WEXITSTATUS(status) == 130;
}

/// `grainlab run --resume out` ends with exit status 0.
void expectResumes(const fs::path& out) {
    const CommandOutput again = resumeOutput(out);
    EXPECT_EQ(again.status, 0) << again.output;
}

std::map<std::string, std::string> folderBytes(const fs::path& folder) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
        if (e.is_regular_file()) {
            out[fs::relative(e.path(), folder).string()] = readText(e.path());
        }
    }
    return out;
}

TEST_F(RunFolder, ARefusedExperimentCreatesNoFolder) {
    const fs::path bad = base / "bad.json";
    std::ofstream(bad) << R"({"name": 3})";
    const fs::path out = base / "new";
    const CommandOutput r =
        grainlabOutput(fmt::format("run {} --out {}", bad.string(), out.string()));
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(bad.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("name"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << "a refused experiment left " << out << " behind";
}

TEST_F(RunFolder, QuietPrintsOnlyTheLastLine) {
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path out = base / "out";
    const CommandOutput r = runOutput(experiment, out);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, fmt::format("grainlab run: finished; outputs in {}\n", out.string()));
}

TEST_F(RunFolder, ResumeOfAFinishedRunChangesNothing) {
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path out = base / "out";
    ASSERT_EQ(runOutput(experiment, out).status, 0);
    const auto before = folderBytes(out);
    const auto checkpoints = listCheckpoints((out / "run.h5").string());
    const CommandOutput r = resumeOutput(out);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("is finished"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
    EXPECT_EQ(folderBytes(out), before) << "a resume of a finished run changed its files";
    EXPECT_EQ(listCheckpoints((out / "run.h5").string()), checkpoints);
}

TEST_F(RunFolder, ASecondRunIntoALiveFolderIsRefusedAndTouchesNothing) {
    const fs::path experiment = writeTinyExperiment(base, 0.1); // long enough to stay alive
    const fs::path out = base / "out";
    const pid_t child = startRun(experiment, out);
    ASSERT_GE(child, 0);
    // Wait until the first run is shearing (its test series exists).
    const fs::path csv = out / "p050kPa" / "series.csv";
    for (int k = 0; k < 1200 && !fs::exists(csv); ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_TRUE(fs::exists(csv));
    const auto size = fs::file_size(out / "run.h5");
    for (const std::string arguments :
         {fmt::format("run {} --out {} --quiet", experiment.string(), out.string()),
          fmt::format("run {} --out {} --force --quiet", experiment.string(), out.string()),
          fmt::format("run --resume {} --quiet", out.string())}) {
        const CommandOutput r = grainlabOutput(arguments);
        EXPECT_EQ(r.status, 2) << arguments << "\n" << r.output;
        EXPECT_NE(r.output.find("another run owns it"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
        // The live run's file was not truncated.
        EXPECT_GE(fs::file_size(out / "run.h5"), size) << arguments;
    }
    kill(child, SIGINT);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130); // interrupted, not an error
    // The first run's files are whole: it resumes (now that it is gone) from its checkpoint.
    const auto checkpoints = listCheckpoints((out / "run.h5").string());
    ASSERT_FALSE(checkpoints.empty());
    EXPECT_NE(checkpoints.back().find("interrupted"), std::string::npos);
    expectResumes(out);
}

// A stop that comes while a new run makes its files (a study stopped just as its pool starts a
// run): at every moment the run is either killed before it made any file, or it ends as an
// interrupted run (130) whose folder resumes to the end; never a run file without a checkpoint.
TEST_F(RunFolder, AStopAsANewRunStartsLeavesNoFolderOrOneThatResumes) {
    const fs::path experiment = writeTinyExperiment(base);
    for (const int delayMs : {0, 2, 5, 10, 20, 40, 80, 160}) {
        SCOPED_TRACE(fmt::format("SIGINT {} ms after the start", delayMs));
        const fs::path out = base / fmt::format("out{}", delayMs);
        const pid_t child = startRun(experiment, out);
        ASSERT_GE(child, 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        kill(child, SIGINT);
        int status = 0;
        waitpid(child, &status, 0);
        if (WIFSIGNALED(status)) {
            EXPECT_EQ(WTERMSIG(status), SIGINT);
            EXPECT_FALSE(fs::exists(out / "run.h5")) << "killed after it made its run file";
            continue;
        }
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_TRUE(WEXITSTATUS(status) == 130 || WEXITSTATUS(status) == 0)
            << "exit " << WEXITSTATUS(status);
        expectResumes(out);
    }
}

TEST_F(RunFolder, OutOfAnExistingRunIsRefusedWithoutForce) {
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path out = base / "out";
    // An interrupted, resumable run.
    ASSERT_TRUE(interruptedRun(experiment, out, 3000));
    const auto before = folderBytes(out);
    const CommandOutput r = runOutput(experiment, out);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(out.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("grainlab run --resume " + out.string()), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
    EXPECT_EQ(folderBytes(out), before) << "a refused run changed the folder";
}

TEST_F(RunFolder, ForceLeavesNoFileOfTheOldRun) {
    const fs::path out = base / "out";
    nlohmann::json j = nlohmann::json::parse(readText(writeTinyExperiment(base)));
    j["compaction"]["pressures"] = {25e3, 50e3};
    j["shear"]["pressures"] = {25e3, 50e3};
    const fs::path two = base / "two.json";
    std::ofstream(two) << j.dump(2);
    ASSERT_EQ(runOutput(two, out).status, 0);
    ASSERT_TRUE(fs::exists(out / "p025kPa" / "series.csv"));
    std::ofstream(out / "notes.txt") << "the user's own file";
    const fs::path one = base / "experiment.json"; // 50 kPa only
    const CommandOutput r =
        grainlabOutput(fmt::format("run {} --out {} --force --quiet", one.string(), out.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(out / "p025kPa")) << "the old run's series lingers";
    EXPECT_TRUE(fs::exists(out / "p050kPa" / "series.csv"));
    EXPECT_TRUE(fs::exists(out / "notes.txt")) << "--force removed a file that is not the run's";
    const std::string file = (out / "run.h5").string();
    EXPECT_EQ(listTests(file), (std::vector<std::string>{"compaction", "p050kPa"}));
    EXPECT_EQ(listSamples(file), std::vector<double>{50e3});
    EXPECT_EQ(readExperimentText(file), readText(one));
}

TEST_F(RunFolder, ThreadsOutsideTheirRangeAreRefused) {
    const fs::path experiment = writeTinyExperiment(base);
    for (const char* threads : {"-1", "0", "2147483647", "1.5"}) {
        const CommandOutput r =
            grainlabOutput(fmt::format("run {} --out {} --threads {} --quiet", experiment.string(),
                                       (base / "out").string(), threads));
        EXPECT_NE(r.status, 0) << threads;
        EXPECT_NE(r.output.find("--threads"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("1 to 1024"), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(base / "out")) << threads;
    }
}

TEST_F(RunFolder, ADamagedRunFileIsRefusedByNameOrResumesToTheSameResult) {
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path whole = base / "whole";
    ASSERT_EQ(runOutput(experiment, whole).status, 0);
    const fs::path stopped = base / "stopped";
    ASSERT_TRUE(interruptedRun(experiment, stopped, 9000));
    const std::string bytes = readText(stopped / "run.h5");
    const auto expected = folderBytes(whole);
    int refused = 0, resumed = 0;
    for (int k = 0; k < 24; ++k) {
        const std::size_t offset = 97 + (bytes.size() - 100) * k / 24;
        const fs::path copy = base / fmt::format("copy{:02d}", k);
        fs::copy(stopped, copy, fs::copy_options::recursive);
        std::string damaged = bytes;
        damaged[offset] = static_cast<char>(damaged[offset] ^ 0x5a);
        std::ofstream(copy / "run.h5", std::ios::binary | std::ios::trunc) << damaged;
        const CommandOutput r = resumeOutput(copy);
        ASSERT_GE(r.status, 0) << "byte " << offset << ": crashed\n" << r.output;
        if (r.status == 0) {
            // Resumed: every series as in the uninterrupted run.
            for (const auto& [name, text] : expected) {
                if (name.ends_with("series.csv")) {
                    EXPECT_EQ(readText(copy / name), text) << "byte " << offset << ": " << name;
                }
            }
            ++resumed;
        } else {
            EXPECT_NE(r.output.find((copy / "run.h5").string()), std::string::npos)
                << "byte " << offset << ": the error does not name the file\n"
                << r.output;
            ++refused;
        }
    }
    EXPECT_GT(refused, 0);
    std::printf("24 damaged run files: %d refused, %d resumed to the same series\n", refused,
                resumed);
}

/// Exit status of a shell command (its output discarded).
int shell(const std::string& command) {
    const int status = std::system((command + " > /dev/null 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Python with h5py: the system one (a user's environment may lack it).
std::string pythonWithH5py() {
    for (const char* python : {"/usr/bin/python3", "python3"}) {
        if (shell(fmt::format("{} -c 'import h5py'", python)) == 0) {
            return python;
        }
    }
    return {};
}

/// Whether h5dump and h5py read every object of the file (each dataset's values too).
std::string otherReadersRefuse(const fs::path& file, const std::string& python) {
    std::string out;
    if (shell(fmt::format("h5dump {}", file.string())) != 0) {
        out += " h5dump fails;";
    }
    const std::string script = "import h5py, sys\n"
                               "f = h5py.File(sys.argv[1], 'r')\n"
                               "def read(name, o):\n"
                               "    list(o.attrs.items())\n"
                               "    if isinstance(o, h5py.Dataset): o[()]\n"
                               "read('/', f)\n"
                               "f.visititems(read)\n";
    const fs::path scriptFile = file.parent_path() / "read_all.py";
    std::ofstream(scriptFile) << script;
    if (shell(fmt::format("{} {} {}", python, scriptFile.string(), file.string())) != 0) {
        out += " h5py fails;";
    }
    fs::remove(scriptFile);
    return out;
}

TEST_F(RunFolder, AResumedRunEndsWithAFileOtherReadersOpenOrIsRefusedNamingTheDamage) {
    const std::string python = pythonWithH5py();
    if (shell("h5dump --version") != 0 || python.empty()) {
        GTEST_SKIP() << "needs h5dump and Python with h5py";
    }
    const fs::path experiment = writeTinyExperiment(base);
    const fs::path stopped = base / "stopped";
    ASSERT_TRUE(interruptedRun(experiment, stopped, 9000));
    const std::string bytes = readText(stopped / "run.h5");
    ASSERT_EQ(otherReadersRefuse(stopped / "run.h5", python), "");
    // Damage where a resume does not read: 4 KB of zeros at byte 6937 (the hostile tester's
    // file), and one bit deep in the first checkpoint (a resume reads only the last one).
    const std::vector<std::string> checkpoints = listCheckpoints((stopped / "run.h5").string());
    ASSERT_GE(checkpoints.size(), 2u);
    const std::vector<double> x1 =
        readState((stopped / "run.h5").string(), checkpointGroup(checkpoints.front())).grains.x1;
    const std::string needle(reinterpret_cast<const char*>(x1.data()), 4 * sizeof(double));
    const std::size_t first = bytes.find(needle);
    ASSERT_NE(first, std::string::npos);
    ASSERT_GT(bytes.size(), 6937u + 4096u);
    struct Damage {
        std::string name;
        std::string bytes;
        bool elsewhere = true; ///< where the resume itself does not read
    };
    // And one byte of the first object headers, which the resume reads: refused there.
    std::vector<Damage> damages{{"zeros", bytes}, {"bit", bytes}, {"header", bytes, false}};
    damages[2].bytes[2000] = static_cast<char>(damages[2].bytes[2000] ^ 0x5a);
    std::fill_n(damages[0].bytes.begin() + 6937, 4096, '\0');
    damages[1].bytes[first + 11] = static_cast<char>(damages[1].bytes[first + 11] ^ 0x10);
    for (const Damage& d : damages) {
        const fs::path copy = base / d.name;
        fs::copy(stopped, copy, fs::copy_options::recursive);
        std::ofstream(copy / "run.h5", std::ios::binary | std::ios::trunc) << d.bytes;
        const CommandOutput r = resumeOutput(copy);
        ASSERT_GE(r.status, 0) << d.name << ": crashed\n" << r.output;
        // Only grainlab's own message: no trace of the HDF5 library's error stack.
        EXPECT_EQ(r.output.find("HDF5-DIAG"), std::string::npos) << d.name << "\n" << r.output;
        EXPECT_EQ(r.output.find("#000:"), std::string::npos) << d.name << "\n" << r.output;
        EXPECT_EQ(r.output.find("closing library"), std::string::npos) << d.name << "\n"
                                                                       << r.output;
        if (r.status == 0) {
            EXPECT_EQ(otherReadersRefuse(copy / "run.h5", python), "")
                << d.name << ": resumed to a file other readers cannot open\n"
                << r.output;
        } else if (!d.elsewhere) {
            EXPECT_NE(r.output.find((copy / "run.h5").string() + ": the file is damaged"),
                      std::string::npos)
                << d.name << "\n"
                << r.output;
        } else {
            EXPECT_NE(r.output.find((copy / "run.h5").string() + ": the run file is damaged: /"),
                      std::string::npos)
                << d.name << "\n"
                << r.output;
            EXPECT_NE(r.output.find("--out NEW_FOLDER"), std::string::npos) << r.output;
            EXPECT_EQ(readText(copy / "run.h5"), d.bytes) << d.name << ": the file was changed";
        }
        std::printf("%s: %s\n", d.name.c_str(), r.status == 0 ? "resumed" : "refused");
    }
}

TEST_F(RunFolder, AFullDiskStopsTheRunCleanlyAndItResumesExactly) {
    const fs::path experiment = writeTinyExperiment(base, 0.004);
    const fs::path whole = base / "whole";
    ASSERT_EQ(runOutput(experiment, whole).status, 0);
    const auto size = fs::file_size(whole / "run.h5");
    // The disk fills at 60 % of the run file: with RLIMIT_FSIZE and SIGXFSZ ignored, a write past
    // the limit fails with EFBIG, as on a full file system.
    const fs::path out = base / "out";
    const auto [status, output] = test::childOutput([&](int fd) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {};
        limit.rlim_cur = limit.rlim_max = size * 6 / 10;
        ::setrlimit(RLIMIT_FSIZE, &limit);
        test::execGrainlab({"run", experiment.string(), "--out", out.string(), "--quiet"});
    });
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status) << "\n" << output;
    EXPECT_EQ(WEXITSTATUS(status), 1) << output;
    EXPECT_NE(output.find((out / "run.h5").string()), std::string::npos) << output;
    EXPECT_NE(output.find("no room"), std::string::npos) << output;
    EXPECT_NE(output.find("grainlab run --resume " + out.string()), std::string::npos) << output;
    // Space freed: the run resumes from its last complete checkpoint to the same bits.
    ASSERT_FALSE(listCheckpoints((out / "run.h5").string()).empty());
    const CommandOutput r = resumeOutput(out);
    ASSERT_EQ(r.status, 0) << r.output;
    for (const auto& [name, text] : folderBytes(whole)) {
        if (name.ends_with("series.csv")) {
            EXPECT_EQ(readText(out / name), text) << name;
        }
    }
    for (const std::string& test : listTests((whole / "run.h5").string())) {
        EXPECT_EQ(readSeries((whole / "run.h5").string(), test).rows,
                  readSeries((out / "run.h5").string(), test).rows)
            << test;
    }
}

} // namespace
} // namespace grainlab
