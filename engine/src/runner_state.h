#pragma once
// The experiment runner's own state, as each checkpoint stores it (the run file's dataset
// runner_state, a JSON object): what a resumed run needs beyond the simulation state to continue
// bit for bit. Flat, one key per field; the keys are those of every run file written so far, so
// old files resume. The runner fills the common fields; each stage kind fills its own (see
// stage.h, Stage::save): a field of a finished stage keeps its final value.
// Plain data; written and read on the thread that drives the runner.

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/run_warning.h"

namespace grainlab {

/// The running maximum of q/p of a shear test under way (stage_monotonic_test.h).
struct RunningPeakRecord {
    double stressRatio = 0; ///< q/p [-]
    std::int64_t step = 0;
    double eps1 = 0; ///< [-]
    /// The checkpoint whose group running_peak holds the state at the peak; "" when the
    /// checkpoint's own state is the peak's.
    std::string keptIn;
};

/// Where the start state of probes that start at a strain or at the peak of the test before them
/// is kept, once that test has passed it (RunContext::probeStart).
struct ProbeStartRecord {
    std::int64_t step = 0;
    /// The checkpoint whose group probe_start holds the state.
    std::string keptIn;
};

struct RunnerState {
    // The runner's position: the stage kind (StageKind as an integer) and its pressure index
    // (into compaction.pressures for a compaction, shear.pressures for a test's stages).
    int phase = 0;
    int index = 0;
    bool stageDone = false; ///< the stage has ended; the next one is still to start
    std::int64_t stageStartStep = 0;
    // Strain references and the last record (for the dilatancy index) [m], [m^2], [-].
    double length1At0 = 0, length2At0 = 0, areaAt0 = 0;
    bool haveLast = false;
    double lastEps1 = 0, lastEpsv = 0;
    std::int64_t nextRecordStep = 0, nextSnapshotStep = 0;
    std::int64_t checkpointCounter = 0;
    std::vector<double> thetaAtTestStart; ///< [rad]
    std::vector<double> thetaAtRunStart;  ///< [rad]; written during compaction only
    std::string currentSeries;            ///< "" before any
    std::map<std::string, std::size_t> seriesRows;
    std::vector<RunWarning> warnings;
    // Equilibrium stages (stage_equilibrium.h).
    int calm = 0;
    std::array<double, 4> unbalancedLow{-1, -1, -1, -1}; ///< CalmHistory::lowest [%]
    // The shear test (stage_monotonic_test.h).
    double voidsAtStart = -1; ///< N_vi of the test; -1 before its first record
    std::optional<RunningPeakRecord> peak;
    // Stress probes (stage_probes.h): the probe under way and the step it started at; their
    // start state is kept beside a checkpoint like a running peak (peak.kept_in).
    int probe = 0;
    std::int64_t probeStartStep = 0;
    /// The start state of the probes after the test under way, once it has passed it.
    std::optional<ProbeStartRecord> probeStartState;
    // A stress-controlled cyclic test (stage_cyclic.h): the axial direction and the reversals.
    int cyclicDirection = 0;
    std::int64_t cyclicReversals = 0;
};

/// The JSON text of a runner state.
std::string runnerStateText(const RunnerState& state);
/// Reads a runner state text; keys that older files lack (warnings, unbalanced_low) keep their
/// defaults. Throws nlohmann::json exceptions on text that is not a runner state.
RunnerState parseRunnerState(const std::string& text);

} // namespace grainlab
