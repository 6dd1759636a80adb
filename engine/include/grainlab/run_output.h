#pragma once
// The interface through which the experiment runner hands out what a run produces: series
// records, checkpoints with the identity of their stage, their contacts and void cells,
// compacted samples and the run's warnings.
// Implemented by the run file (run_file.h), the run output folder of `grainlab run`, the
// window's run adapter and tests. Called on the thread that drives the runner.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/contact_network.h"
#include "grainlab/run_warning.h"
#include "grainlab/series.h"
#include "grainlab/simulation_state.h"
#include "grainlab/void_cells.h"

namespace grainlab {

/// What stage a checkpoint belongs to, as data (the run file's checkpoint attributes).
struct StageIdentity {
    std::string kind;       ///< "compaction", "equilibration" or "shear"
    std::string test;       ///< the series its records go to: "compaction", "p100kPa"
    double pressure = 0;    ///< the stage's confining pressure [Pa]
    std::int64_t step = 0;  ///< simulation step of the checkpoint
    double axialStrain = 0; ///< eps1 of the test [-]
    /// Grain orientations at the start of the test, which rotation counts from [rad]: the
    /// sample's as its equilibration starts; the generated assembly's for the compaction.
    std::vector<double> thetaAtTestStart;
    /// True for the checkpoint at the peak of q/p of a shear test (written when the test ends,
    /// with the state of the record at which q/p was largest).
    bool peak = false;
    double peakStressRatio = 0; ///< q/p at that peak [-] (peak checkpoints only)
};

/// Everything of one checkpoint, handed out in one call so that a writer can store it as one
/// unit (a run killed while writing it leaves either all of it or none). The pointers are valid
/// for the call only.
struct CheckpointData {
    std::string name;
    const SimulationState* state = nullptr; ///< the complete state (never null)
    std::string runnerState;                ///< the runner's own state (JSON)
    StageIdentity identity;
    const ContactNetwork* network = nullptr; ///< its touching contacts (null: none stored)
    const VoidCellSet* voidCells = nullptr;  ///< its void cells (null: none stored)
    /// The state at the running maximum of q/p of the shear test so far, when the runner state
    /// names this checkpoint as where it is kept (a resumed run continues the maximum from it;
    /// see ExperimentRunner::runningPeakCheckpoint). Null otherwise.
    const SimulationState* runningPeak = nullptr;
    /// The start state of probes that start at a strain or the peak of the test under way,
    /// when the runner state names this checkpoint as where it is kept (see
    /// ExperimentRunner::probeStartCheckpoint). Null otherwise.
    const SimulationState* probeStart = nullptr;
};

class RunOutput {
public:
    virtual ~RunOutput() = default;
    /// A new record (row) of test `series.test`; `series` holds all rows so far.
    virtual void record(const SeriesTable& series) = 0;
    /// A complete checkpoint (continuing from it gives the same numbers) with its stage's
    /// identity, its contacts, void cells and the running peak.
    virtual void checkpoint(const CheckpointData& data) = 0;
    /// A compacted sample, kept for the shear tests.
    virtual void sample(double pressure, const SimulationState& state) = 0;
    /// Every warning the run has given so far (run_warning.h), after a new one and when a resumed
    /// run starts (its list is what its checkpoint held). By default dropped.
    virtual void warnings(const std::vector<RunWarning>& all) { (void)all; }
};

} // namespace grainlab
