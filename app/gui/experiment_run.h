#pragma once
// What the GUI's simulation controller drives: something that advances in chunks of steps and
// builds immutable snapshots. In the app it is the ExperimentRunner (makeExperimentRun); tests
// may substitute a scripted run. Called only on the controller's worker thread.

#include <cstdint>
#include <memory>
#include <string>

#include "grainlab/experiment.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/snapshot.h"

namespace grainlab::ui {

class SnapshotHistory;

class SteppedRun {
public:
    virtual ~SteppedRun() = default;
    /// Advances by at most `maxSteps` steps; false once the run is finished. May throw.
    virtual bool advance(std::int64_t maxSteps) = 0;
    /// A new snapshot of now, not yet shared, possibly without its measures (Snapshot::measured
    /// false: the controller completes it off the engine's thread).
    virtual std::shared_ptr<Snapshot> snapshot() const = 0;
    virtual RunProgress progress() const = 0;
    /// From now on, adds a snapshot of the run at each of its shear records to `history` (the
    /// ones the history wants; see snapshot_history.h), during advance(). The history
    /// outlives the run. By default a run keeps none.
    virtual void keepRecordSnapshots(SnapshotHistory* history) { (void)history; }
    /// The run folder this run writes (run.h5, <test>/series.csv), or "" when it writes none.
    virtual std::string runFolder() const { return {}; }
    /// The name of the last checkpoint of the run folder a run can continue from (see
    /// RunOutputFolder::lastCheckpoint), or "" when there is none or no folder.
    virtual std::string lastGoodCheckpoint() const { return {}; }
    /// The run ends before its last step (Stop, the window closes): a recorded run writes an
    /// "interrupted" checkpoint, so that `grainlab run --resume` continues it. May throw.
    virtual void interrupt() {}
};

/// The experiment runner behind the SteppedRun interface, writing no files.
std::unique_ptr<SteppedRun> makeExperimentRun(const ExperimentConfig& config);
/// The same, writing the run folder `folder` (which must be new or empty: see
/// window_run_folder.h) exactly as `grainlab run --out folder` does, through the same
/// RunOutputFolder: run.h5 holding config.sourceText as its experiment, and one series.csv per
/// test. Call on the thread that will advance the run (it creates the run file).
std::unique_ptr<SteppedRun> makeRecordedExperimentRun(const ExperimentConfig& config,
                                                      const std::string& folder);
/// The same, continuing from a checkpoint of the experiment (e.g. one taken in memory by a
/// benchmark, so that every timed run starts from the same state).
std::unique_ptr<SteppedRun> makeResumedExperimentRun(const ExperimentConfig& config,
                                                     ResumePoint resume);

} // namespace grainlab::ui
