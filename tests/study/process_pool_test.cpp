// The local process pool: never more than its slots at once, every job's exit status, signal
// and cost from the kernel, output appended to each job's log, and a stop that sends the
// running processes SIGINT and starts no new one.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "test_folders.h"

#include "common/process_pool.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;
using test::text;

/// A fresh folder (created: the pool writes logs into it).
fs::path freshFolder(const std::string& name) {
    const fs::path dir = test::freshFolder(name);
    fs::create_directories(dir);
    return dir;
}

PoolJob shell(const fs::path& log, const std::string& script) {
    return {{"/bin/sh", "-c", script}, log.string()};
}

TEST(ProcessPool, RunsEveryJobWithItsStatusAndLogAndNeverMoreThanItsSlots) {
    const fs::path dir = freshFolder("slots");
    // Each job marks itself running in a shared folder, counts the marks, and records the most
    // it saw: with 2 slots the most is 2.
    std::vector<PoolJob> jobs;
    for (int k = 0; k < 6; ++k) {
        const std::string mark = (dir / ("running-" + std::to_string(k))).string();
        jobs.push_back(shell(dir / ("job" + std::to_string(k) + ".log"),
                             "touch " + mark + "; sleep 0.2; ls " + dir.string() +
                                 " | grep -c running- >> " + (dir / "seen").string() + "; rm " +
                                 mark + "; echo hello " + std::to_string(k) + "; exit " +
                                 std::to_string(k % 3)));
    }
    std::vector<std::size_t> done;
    const auto results = ProcessPool(2, 64).run(
        jobs, [&](std::size_t job, const PoolResult&) { done.push_back(job); });
    ASSERT_EQ(results.size(), 6u);
    EXPECT_EQ(done.size(), 6u);
    for (int k = 0; k < 6; ++k) {
        EXPECT_TRUE(results[std::size_t(k)].started);
        EXPECT_EQ(results[std::size_t(k)].exitStatus, k % 3) << k;
        EXPECT_EQ(results[std::size_t(k)].succeeded(), k % 3 == 0);
        EXPECT_GE(results[std::size_t(k)].wallSeconds, 0.2);
        EXPECT_EQ(text(dir / ("job" + std::to_string(k) + ".log")),
                  "hello " + std::to_string(k) + "\n");
    }
    std::istringstream seen(text(dir / "seen"));
    int most = 0, count = 0;
    for (int n; seen >> n; ++count) {
        most = std::max(most, n);
    }
    EXPECT_EQ(count, 6);
    EXPECT_EQ(most, 2);
}

TEST(ProcessPool, ProcessorTimeComesFromTheKernelAndSignalsAreReported) {
    const fs::path dir = freshFolder("cost");
    const auto results = ProcessPool(2, 64).run(
        {shell(dir / "busy.log", "i=0; while [ $i -lt 200000 ]; do i=$((i+1)); done"),
         shell(dir / "killed.log", "kill -KILL $$")});
    EXPECT_GT(results[0].cpuSeconds, 0.01);
    EXPECT_LE(results[0].cpuSeconds, results[0].wallSeconds * 2 + 0.05);
    EXPECT_EQ(results[1].exitStatus, -1);
    EXPECT_EQ(results[1].signal, 9);
    EXPECT_FALSE(results[1].succeeded());
}

TEST(ProcessPool, StopInterruptsTheRunningAndStartsNoMore) {
    const fs::path dir = freshFolder("stop");
    std::vector<PoolJob> jobs;
    for (int k = 0; k < 4; ++k) {
        // Each job waits for SIGINT and then says so, as grainlab run writes its checkpoint.
        jobs.push_back(shell(dir / ("job" + std::to_string(k) + ".log"),
                             "trap 'echo interrupted; exit 130' INT; sleep 30 & wait"));
    }
    std::atomic<bool> stop{false};
    std::thread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(400));
        stop.store(true);
    });
    const auto start = std::chrono::steady_clock::now();
    const auto results = ProcessPool(2, 64).run(jobs, {}, {}, &stop);
    stopper.join();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20);
    EXPECT_TRUE(results[0].started);
    EXPECT_TRUE(results[1].started);
    EXPECT_FALSE(results[2].started);
    EXPECT_FALSE(results[3].started);
    EXPECT_EQ(results[0].exitStatus, 130);
    EXPECT_EQ(text(dir / "job0.log"), "interrupted\n");
}

TEST(ProcessPool, JobsShareTheProcessorsByTheirThreads) {
    const fs::path dir = freshFolder("threads");
    // Three 2-thread jobs and one 1-thread job on 3 processors: the 2-thread jobs never overlap
    // each other; a job wider than the machine still runs (alone).
    std::vector<PoolJob> jobs;
    const std::string seen = (dir / "seen").string();
    for (int k = 0; k < 4; ++k) {
        const std::string mark = (dir / ("running-" + std::to_string(k))).string();
        PoolJob job = shell(dir / ("job" + std::to_string(k) + ".log"),
                            "touch " + mark + "; sleep 0.3; ls " + dir.string() +
                                " | grep -c running- >> " + seen + "; rm " + mark);
        job.threads = k == 3 ? 1 : 2;
        jobs.push_back(job);
    }
    PoolJob wide = shell(dir / "wide.log", "true");
    wide.threads = 8;
    jobs.push_back(wide);
    const auto results = ProcessPool(8, 3).run(jobs);
    for (const auto& r : results) {
        EXPECT_TRUE(r.succeeded());
    }
    std::istringstream in(text(dir / "seen"));
    int most = 0;
    for (int n; in >> n;) {
        most = std::max(most, n);
    }
    EXPECT_EQ(most, 2); // a 2-thread job with the 1-thread job, never two 2-thread jobs
}

} // namespace
} // namespace grainlab
