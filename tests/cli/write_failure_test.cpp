// A write that fails inside HDF5 itself (issue 12, a full disk): with the room check bypassed
// (GRAINLAB_TEST_NO_ROOM_CHECK=1) and a file size limit at several points of a run, the run
// stops with exit status 1 and a message naming the cause and the checkpoint kept; the file
// stays readable, and once the limit is lifted the run resumes to the series and final state of
// an uninterrupted run, bit for bit.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../engine/child_output.h"
#include "cli_test_files.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using test::execGrainlab;
using test::readText;
using Result = test::ChildOutput; ///< the wait status and the output

/// Runs grainlab with `arguments`, its file size limited to `limit` bytes (0: no limit) and
/// the room check bypassed, so that a write fails inside HDF5. SIGXFSZ keeps its default
/// action: grainlab itself must turn the limit into a failed write.
Result runLimited(const std::vector<std::string>& arguments, rlim_t limit) {
    return test::childOutput([&](int out) {
        ::dup2(out, 1);
        ::dup2(out, 2);
        ::setenv("GRAINLAB_TEST_NO_ROOM_CHECK", "1", 1);
        if (limit > 0) {
            struct rlimit l {};
            l.rlim_cur = l.rlim_max = limit;
            ::setrlimit(RLIMIT_FSIZE, &l);
        }
        execGrainlab(arguments);
    });
}

bool sameBits(const SeriesTable& a, const SeriesTable& b) {
    if (a.rows.size() != b.rows.size() || a.stages != b.stages) {
        return false;
    }
    for (std::size_t r = 0; r < a.rows.size(); ++r) {
        if (a.rows[r].size() != b.rows[r].size() ||
            std::memcmp(a.rows[r].data(), b.rows[r].data(), a.rows[r].size() * 8) != 0) {
            return false;
        }
    }
    return true;
}

TEST(WriteFailure, AFailedWriteInsideHdf5KeepsTheLastCheckpointAndResumesExactly) {
    const fs::path base = test::freshFolder("write-failure", "limits");
    const fs::path experiment = test::writeTinyExperiment(base, "write-failure", 0.004);

    const fs::path whole = base / "whole";
    const Result w =
        runLimited({"run", experiment.string(), "--out", whole.string(), "--quiet"}, 0);
    ASSERT_TRUE(WIFEXITED(w.status) && WEXITSTATUS(w.status) == 0) << w.output;
    const std::string wholeFile = (whole / "run.h5").string();
    const auto size = fs::file_size(wholeFile);
    const std::vector<std::string> tests = listTests(wholeFile);
    const std::vector<std::string> checkpoints = listCheckpoints(wholeFile);
    const SimulationState last = readState(wholeFile, checkpointGroup(checkpoints.back()));

    for (const int percent : {30, 50, 70, 90}) {
        SCOPED_TRACE(fmt::format("file size limit at {} % of the finished run file", percent));
        const fs::path out = base / fmt::format("out{}", percent);
        const std::string file = (out / "run.h5").string();
        const Result r = runLimited({"run", experiment.string(), "--out", out.string(), "--quiet"},
                                    rlim_t(size) * percent / 100);
        ASSERT_TRUE(WIFEXITED(r.status)) << "killed by signal " << WTERMSIG(r.status) << "\n"
                                         << r.output;
        EXPECT_EQ(WEXITSTATUS(r.status), 1) << r.output;
        EXPECT_NE(r.output.find("error: " + file + ": "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("the file size limit is reached"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("keeps its last good checkpoint 0"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("grainlab run --resume " + out.string()), std::string::npos)
            << r.output;
        EXPECT_EQ(r.output.find("failed\n"), std::string::npos) << r.output; // no "H5Dclose failed"
        // The file opens, and its last checkpoint is the one the message names.
        const std::vector<std::string> kept = listCheckpoints(file);
        ASSERT_FALSE(kept.empty());
        EXPECT_NE(r.output.find(fmt::format("checkpoint {} and", kept.back())), std::string::npos)
            << r.output;

        const Result resumed = runLimited({"run", "--resume", out.string(), "--quiet"}, 0);
        ASSERT_TRUE(WIFEXITED(resumed.status) && WEXITSTATUS(resumed.status) == 0)
            << resumed.output;
        EXPECT_EQ(listTests(file), tests);
        for (const std::string& test : tests) {
            EXPECT_EQ(readText(out / test / "series.csv"), readText(whole / test / "series.csv"))
                << test;
            EXPECT_TRUE(sameBits(readSeries(file, test), readSeries(wholeFile, test))) << test;
        }
        EXPECT_TRUE(identicalDynamics(
            readState(file, checkpointGroup(listCheckpoints(file).back())), last));
    }
    fs::remove_all(base);
}

} // namespace
} // namespace grainlab
