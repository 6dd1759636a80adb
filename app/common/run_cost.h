#pragma once
// What a run folder's run has cost so far, kept beside its run file as cost.json and updated by
// every `grainlab run` process that works on it (a resumed run adds to what the earlier
// processes spent): wall and processor seconds, steps, grain-steps, threads, how many processes,
// and whether the run has finished. The study commands read it; a user can too (docs/formats.md).
// Main thread.

#include <chrono>
#include <cstdint>
#include <string>

#include "grainlab/experiment_runner.h"

namespace grainlab {

struct RunCostRecord {
    bool finished = false;       ///< the experiment ran to its end
    double wallSeconds = 0;      ///< [s], summed over processes
    double cpuSeconds = 0;       ///< user + system time of every thread [s], summed
    std::int64_t steps = 0;      ///< time steps computed, summed (repeated work included)
    std::int64_t grainSteps = 0; ///< steps times grains stepped
    int threads = 0;             ///< engine threads of the last process
    int processes = 0;           ///< processes that worked on the run
    /// Where the wall time went [s], summed over processes (ExperimentRunner::times): stepping,
    /// records, checkpoints and the stages' other events. Zero in a record written before these
    /// were kept. The rest of wall_seconds is the process's own (reading the experiment, opening
    /// the run file, starting up).
    RunnerTimes times;
};

/// cost.json in `runFolder`; all zeros (not finished) when there is none. Throws
/// std::runtime_error naming the file when it exists but cannot be read.
RunCostRecord readRunCost(const std::string& runFolder);

/// Replaces cost.json in `runFolder` (through a temporary file and a rename).
void writeRunCost(const std::string& runFolder, const RunCostRecord& cost);

/// The path of cost.json in `runFolder`.
std::string runCostPath(const std::string& runFolder);

/// Keeps cost.json of one run folder up to date while this process works on the run: what
/// earlier processes spent (read at construction when continuing a run) plus this process's
/// wall time, processor time (all its threads) and steps.
class RunCostMeter {
public:
    RunCostMeter(std::string runFolder, bool continuing);
    /// What this process has done so far: its steps, where its runner's time went.
    struct Work {
        std::int64_t steps = 0, grains = 0;
        int threads = 0;
        RunnerTimes times;
    };
    /// Writes cost.json now.
    void save(const Work& work, bool finished);
    /// Writes it when `interval` seconds have passed since the last write.
    void saveEvery(double interval, const Work& work);

private:
    std::string folder_;
    RunCostRecord before_;
    std::chrono::steady_clock::time_point start_, lastSave_;
};

} // namespace grainlab
