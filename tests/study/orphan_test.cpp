// A run of a study ends with the study: `kill -9` of a real `grainlab study` leaves no run going
// (an orphan would keep the run folder's lock, so that the study run again finds the run "in
// use", and both would write one log). A run folder's lock left by a run that was killed is
// taken over with a message naming its pid; a lock whose owner still runs is refused, naming it.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_folders.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;
using test::childrenOf;
using test::freshFolder;
using test::processRuns;
using test::run;
using test::text;

const std::string kTinyExperiment = GRAINLAB_SOURCE_DIR "/resources/experiments/tiny.json";

/// A study of the tiny experiment sheared to 60 % instead of 2 %: each run takes far longer
/// than the test waits for it to end (minutes on two cores), so only the end of its pool ends it.
fs::path writeLongStudy(const fs::path& dir) {
    fs::create_directories(dir);
    std::string experiment = text(kTinyExperiment);
    const std::string target = "\"target_axial_strain\": 0.02";
    const auto at = experiment.find(target);
    EXPECT_NE(at, std::string::npos);
    experiment.replace(at, target.size(), "\"target_axial_strain\": 0.6");
    std::ofstream(dir / "long.json") << experiment;
    std::ofstream(dir / "study.json") << R"({
  "name": "long",
  "base": "long.json",
  "knobs": {"time_step_fraction": [0.25, 0.5]},
  "reference": {"time_step_fraction": 0.25},
  "seeds": 1,
  "metrics": {"peak_q_over_p": {"tolerance": 0.05, "relative": true}}
})";
    return dir / "study.json";
}

TEST(StudyOrphans, KillNineOfTheStudyEndsItsRunningRun) {
    const fs::path dir = freshFolder("orphan");
    const fs::path study = writeLongStudy(dir.string() + "-input");
    const fs::path out = dir / "out";
    const pid_t pool = ::fork();
    if (pool == 0) {
        ::execl(GRAINLAB_EXE, GRAINLAB_EXE, "study", study.c_str(), "--out", out.c_str(), "--quiet",
                "--jobs", "1", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Its run has started for real once it has written its run file (the lock is taken first).
    pid_t child = 0;
    fs::path runFolder;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline && runFolder.empty()) {
        const auto children = childrenOf(pool);
        if (children.size() == 1 && fs::exists(out / "runs")) {
            for (const auto& r : fs::directory_iterator(out / "runs")) {
                if (fs::exists(r.path() / "run.h5")) {
                    child = children.front();
                    runFolder = r.path();
                }
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(runFolder.empty()) << "the study started no run";
    ASSERT_TRUE(processRuns(child));
    ::kill(pool, SIGKILL);
    int status = 0;
    ::waitpid(pool, &status, 0);

    const auto ended = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (processRuns(child) && std::chrono::steady_clock::now() < ended) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const bool orphan = processRuns(child);
    if (orphan) {
        ::kill(child, SIGKILL); // leave nothing running behind the test
    }
    ASSERT_FALSE(orphan) << "the run " << child << " outlived its study by 10 s";
    // Its lock is free: the study run again could take it.
    const int fd = ::open((runFolder / "run.lock").c_str(), O_RDWR | O_CLOEXEC);
    ASSERT_GE(fd, 0);
    EXPECT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0) << "the run folder is still locked";
    ::close(fd);
}

TEST(StudyOrphans, AStaleRunLockIsTakenOverWithAMessage) {
    const fs::path dir = freshFolder("stale-lock");
    fs::create_directories(dir);
    // A pid that no longer exists: a child that has ended and been reaped.
    const pid_t gone = ::fork();
    if (gone == 0) {
        ::_exit(0);
    }
    ::waitpid(gone, nullptr, 0);
    std::ofstream(dir / "run.lock") << gone << "\n";
    const std::string log = dir.string() + ".log";
    ASSERT_EQ(run(std::string(GRAINLAB_EXE) + " run " + kTinyExperiment + " --out " + dir.string() +
                  " --quiet > " + log + " 2>&1"),
              0)
        << text(log);
    const std::string said = text(log);
    EXPECT_NE(said.find("taking over the stale lock of process " + std::to_string(gone)),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("no longer exists"), std::string::npos) << said;
    EXPECT_TRUE(fs::exists(dir / "run.h5"));
    // A run that ended cleanly leaves no owner to take over from.
    EXPECT_EQ(text(dir / "run.lock"), "");
}

TEST(StudyOrphans, ALiveRunLockIsStillRefusedNamingItsOwner) {
    const fs::path dir = freshFolder("live-lock");
    fs::create_directories(dir);
    // This test process owns the lock as a run would: the flock, and its pid in the file.
    const int fd = ::open((dir / "run.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    const std::string pid = std::to_string(::getpid()) + "\n";
    ASSERT_EQ(::write(fd, pid.data(), pid.size()), ssize_t(pid.size()));
    const std::string log = dir.string() + ".log";
    EXPECT_EQ(run(std::string(GRAINLAB_EXE) + " run " + kTinyExperiment + " --out " + dir.string() +
                  " --quiet > " + log + " 2>&1"),
              2);
    ::close(fd);
    const std::string said = text(log);
    EXPECT_NE(said.find("is in use"), std::string::npos) << said;
    EXPECT_NE(said.find("process " + std::to_string(::getpid())), std::string::npos) << said;
    EXPECT_FALSE(fs::exists(dir / "run.h5"));
}

} // namespace
} // namespace grainlab
