#pragma once
// Runs an experiment's stages (docs/experiment-file.md): generation, isotropic compaction to each
// confining pressure (saving a sample at each), then for each sample: friction on, re-equilibration
// and drained biaxial shear, each shear a separate test with its own series. Records the measures,
// writes checkpoints and outputs through an optional RunOutput, and builds snapshots.
// Each stage kind is an object of its own (engine/src/stage.h says what one owns and where a new
// test kind goes); the runner plays them in order. Its state in checkpoints: runner_state.h.
//
// Synchronous: advance() runs on the caller's thread (the GUI's worker thread, or the main
// thread headless). snapshot() returns an immutable object that any thread may read.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/experiment.h"
#include "grainlab/run_output.h"
#include "grainlab/series.h"
#include "grainlab/simulation.h"
#include "grainlab/snapshot.h"
#include "grainlab/stage_kind.h"
#include "grainlab/void_cells.h"

namespace grainlab {

/// Where a run is: which stage of which test.
struct RunProgress {
    std::string stage; ///< for display: "compaction 15 kPa", "equilibration 100 kPa", "done"
    StageKind kind = StageKind::Compaction; ///< the stage's kind, as data
    double pressure = 0;                    ///< the stage's confining pressure [Pa]
    std::string test;                       ///< series the current records go to, e.g. "p100kPa"
    /// Grain orientations at the start of the current test, which rotation counts from [rad]
    /// (empty during compaction). Shared, never modified: copies of a RunProgress share it.
    std::shared_ptr<const std::vector<double>> thetaAtTestStart;
    double axialStrain = 0; ///< eps1 of the current test [-]
    double fraction = 0;    ///< of the whole experiment, estimated [0, 1]
    std::int64_t step = 0;  ///< steps of the current simulation
    bool finished = false;
};

/// What a run needs to continue from a checkpoint (read back from the run file).
struct ResumePoint {
    SimulationState state;                     ///< the checkpoint
    std::string runnerState;                   ///< the runner's own state, as checkpoint() wrote it
    std::map<double, SimulationState> samples; ///< compacted samples by pressure [Pa]
    std::vector<SeriesTable> series;           ///< the series as recorded up to the checkpoint
    /// The state at the running maximum of q/p of the shear test under way, when the runner
    /// state names a checkpoint that keeps it (runningPeakCheckpoint(); the run file's group
    /// running_peak of that checkpoint). Empty otherwise.
    std::optional<SimulationState> runningPeak;
    /// The start state of probes that start at a strain or the peak of the test before them,
    /// when the runner state names a checkpoint that keeps it (probeStartCheckpoint(); the run
    /// file's group probe_start of that checkpoint). Empty otherwise.
    std::optional<SimulationState> probeStart;
};

/// The engine threads a run of `config` uses: its `threads`, but one thread per 2000 grains at
/// most (a small assembly gains nothing from a second thread). Results are the same bits for any.
int engineThreads(const ExperimentConfig& config);

/// Where a runner object's wall time has gone [s]: stepping (Simulation::advance), records (the
/// measures of each record, void cells included, and handing the row to the output), checkpoints
/// (copying the state, its contact network and void cells, and writing them), and the rest of
/// the stages' events (equilibrium checks, servo changes, stage starts and ends). Measured, not
/// estimated: what a run spends beyond stepping is records + checkpoints + events.
struct RunnerTimes {
    double stepping = 0, records = 0, checkpoints = 0, events = 0;

    /// Adds each part of `other` to this one's.
    RunnerTimes& operator+=(const RunnerTimes& other);
    /// The parts summed: stepping + records + checkpoints + events.
    double total() const;
};

/// One part of RunnerTimes, by the name cost.json's "seconds" and Python's Runner.times give it.
struct RunnerTimesPart {
    const char* name;
    double RunnerTimes::*seconds;
};

/// RunnerTimes' parts in that order: what reads, writes, adds or sums them goes through this list.
inline constexpr std::array<RunnerTimesPart, 4> kRunnerTimesParts{{
    {"stepping", &RunnerTimes::stepping},
    {"records", &RunnerTimes::records},
    {"checkpoints", &RunnerTimes::checkpoints},
    {"events", &RunnerTimes::events},
}};

inline RunnerTimes& RunnerTimes::operator+=(const RunnerTimes& other) {
    for (const RunnerTimesPart& part : kRunnerTimesParts) {
        this->*part.seconds += other.*part.seconds;
    }
    return *this;
}

inline double RunnerTimes::total() const {
    double sum = 0;
    for (const RunnerTimesPart& part : kRunnerTimesParts) {
        sum += this->*part.seconds;
    }
    return sum;
}

class ExperimentRunner {
public:
    explicit ExperimentRunner(ExperimentConfig config, RunOutput* output = nullptr);
    /// Continues from a checkpoint written by a previous run of the same experiment. Series
    /// rows recorded after the checkpoint are dropped (see seriesRowsAtCheckpoint()).
    ExperimentRunner(ExperimentConfig config, ResumePoint resume, RunOutput* output = nullptr);
    ~ExperimentRunner();

    /// Advances by at most `maxSteps` steps; returns false once the experiment is finished.
    /// Throws SimulationError (blow-up) or std::runtime_error (a stage that cannot finish).
    bool advance(std::int64_t maxSteps);
    bool finished() const;
    /// Time steps this runner object has advanced (a resumed run counts from its resumption).
    std::int64_t stepsTaken() const;
    /// Where this runner object's wall time has gone (a resumed run counts from its resumption).
    RunnerTimes times() const;
    RunProgress progress() const;
    const ExperimentConfig& config() const;
    /// The simulation of the current stage (valid until the next advance()).
    const Simulation& simulation() const;
    /// Every test's series so far.
    const std::vector<SeriesTable>& series() const;
    /// The numeric values a record made now would hold (the columns of seriesColumns() without
    /// `stage`), computed as a record computes them; nothing is recorded. At the step of the
    /// last record: the values that record holds (its DI counts from the record before it).
    std::vector<double> measuresNow() const;
    /// Every warning given so far (run_warning.h), in order; a resumed run's include those of
    /// its checkpoint.
    const std::vector<RunWarning>& warnings() const;
    /// Builds an immutable snapshot of now (measures computed here, not per step, unless
    /// `measures` is Later: see addSnapshotMeasures()).
    /// The snapshot is new and not yet shared: the caller may complete it before publishing.
    std::shared_ptr<Snapshot> snapshot(SnapshotMeasures measures = SnapshotMeasures::Now) const;
    /// Writes a checkpoint of now through the output (e.g. on Ctrl-C).
    void checkpointNow(const std::string& name);
    /// True when a runner state string holds a finished run (its last checkpoint).
    static bool finishedAt(const std::string& runnerState);
    /// Rows per test in a runner state string: what a resumed run keeps of each series.
    static std::map<std::string, std::size_t>
    seriesRowsAtCheckpoint(const std::string& runnerState);
    /// The checkpoint whose running peak (the state at the largest q/p so far of the shear test
    /// under way) a run resumed from this runner state needs in ResumePoint::runningPeak; ""
    /// when it needs none (no test under way, or the peak is at the checkpoint's own step).
    static std::string runningPeakCheckpoint(const std::string& runnerState);
    /// The checkpoint whose probe start state (of probes that start at a strain or the peak of
    /// the test before them, once that test has passed it) a run resumed from this runner state
    /// needs in ResumePoint::probeStart; "" when it needs none.
    static std::string probeStartCheckpoint(const std::string& runnerState);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace grainlab
