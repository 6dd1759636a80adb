#pragma once
// A local pool of independent processes: runs a list of commands (each a `grainlab run`), at
// most `maxJobs` at a time and, by default, no more threads at once than the machine has
// processors (a job says how many it uses), each with its output appended to a log file of its
// own, and reports
// every finished process with its exit status and cost (wall and processor seconds, from the
// kernel's accounting of the child). Nothing is distributed: for a cluster the study emits a
// Slurm job array or a GNU parallel job list instead (job_list.h).
//
// Used on the calling thread (the study command's main thread, or the Study window's worker
// thread). While run() is going it polls `stop`: once set, no new process starts and the
// running ones are sent SIGINT (grainlab run then writes a checkpoint and exits), and run()
// returns after they have ended. A run also ends (SIGTERM) when the pool's process or calling
// thread dies, kill -9 included, so that no run outlives its pool.

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace grainlab {

struct PoolJob {
    std::vector<std::string> argv; ///< argv[0] is the program's path
    std::string logPath;           ///< stdout and stderr are appended here
    int threads = 1;               ///< processors the job keeps busy
};

struct PoolResult {
    bool started = false;   ///< false when it was never started (stopped before its turn)
    int exitStatus = -1;    ///< the exit status, or -1 when a signal ended it
    int signal = 0;         ///< the signal that ended it, or 0
    double wallSeconds = 0; ///< [s]
    double cpuSeconds = 0;  ///< user + system time of the process and its threads [s]
    bool succeeded() const { return started && exitStatus == 0; }
};

class ProcessPool {
public:
    /// At most `maxJobs` jobs at once, and at most `maxThreads` threads of them (a job with
    /// more threads than that still runs, alone).
    ProcessPool(int maxJobs, int maxThreads);
    /// Called on the calling thread as each job ends (index into the job list).
    using OnDone = std::function<void(std::size_t job, const PoolResult&)>;
    /// Called about every `tick` seconds while jobs run: (jobs ended, jobs running).
    using OnTick = std::function<void(std::size_t ended, std::size_t running)>;
    /// Runs every job; returns their results in job order. Throws std::runtime_error when a
    /// process cannot be created (fork failed) or a log file cannot be opened.
    std::vector<PoolResult> run(const std::vector<PoolJob>& jobs, const OnDone& onDone = {},
                                const OnTick& onTick = {}, const std::atomic<bool>* stop = nullptr,
                                double tick = 0.5);

private:
    int maxJobs_, maxThreads_;
};

/// The processors of this machine (>= 1).
int processorCount();

} // namespace grainlab
