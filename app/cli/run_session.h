#pragma once
// One run owning its run folder, as `grainlab run` and the Python module's grainlab.run() play
// it: the folder's lock, its output (run file and CSV series), its cost record and the runner.
// The caller drives advance() and decides what a stop means (Ctrl-C, a callback); the session
// keeps the files valid at every step. Thread: the one that constructed it.

#include <memory>
#include <string>

#include "cli/run_output.h"
#include "common/run_cost.h"
#include "grainlab/experiment.h"
#include "grainlab/experiment_runner.h"

namespace grainlab {

/// A run folder that cannot be taken: a run already there (without `force`), no run file to
/// resume, a lock held by another run. Nothing was read or written.
class RunFolderRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class RunSession {
public:
    /// A new run of `config` into `folder`: takes the folder's lock (creating the folder),
    /// refuses a folder that holds a run unless `force` (which removes that run's files).
    /// `threads` > 0 replaces the experiment's. Throws RunFolderRefused; the runner is not
    /// made yet (start()).
    static std::unique_ptr<RunSession> create(ExperimentConfig config, const std::string& folder,
                                              bool force, int threads = 0);
    /// A run to continue from the last checkpoint of the run file in `folder`. Throws
    /// RunFolderRefused when there is no run file or another run holds the folder.
    static std::unique_ptr<RunSession> resume(const std::string& folder, int threads = 0);
    ~RunSession();

    /// True when the run being resumed had finished: nothing to run (start() must not be
    /// called); finishedAlready() completes a cost record that missed the end.
    bool finishedAlready() const { return finishedBefore_; }
    void completeCostRecord();

    /// Makes the runner (a new run writes its first checkpoint here). Throws what the runner
    /// throws; the run file then keeps its last complete checkpoint (lastCheckpoint()).
    void start();
    /// Advances at most `steps` steps; false once the experiment is finished. Keeps cost.json
    /// up to date every 5 s.
    bool advance(std::int64_t steps);
    /// Writes a checkpoint named "interrupted" and the cost record: the run continues from
    /// there with resume().
    void interrupt();
    /// Closes the run file (complete on disk), then records the run as finished.
    void finish();
    /// Records the cost so far after a failure (never throws).
    void saveCostAfterFailure() noexcept;

    const ExperimentConfig& config() const { return config_; }
    const std::string& folder() const { return folder_; }
    bool resumed() const { return resumed_; }
    ExperimentRunner& runner() { return *runner_; }
    const ExperimentRunner& runner() const { return *runner_; }
    bool started() const { return runner_ != nullptr; }
    std::string runFilePath() const { return output_->runFilePath(); }
    std::string lastCheckpoint() const { return output_->lastCheckpoint(); }

private:
    RunSession() = default;
    void openOutput();
    void saveCost(bool finished);
    /// What this process has done so far, for the cost record.
    RunCostMeter::Work work() const;

    ExperimentConfig config_;
    std::string folder_;
    bool resumed_ = false;
    bool finishedBefore_ = false;
    std::unique_ptr<RunFolderLock> lock_;
    ResumePoint point_;
    std::unique_ptr<RunOutputFolder> output_;
    std::unique_ptr<RunCostMeter> cost_;
    std::unique_ptr<ExperimentRunner> runner_;
};

} // namespace grainlab
