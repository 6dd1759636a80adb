#pragma once
// What the stages of a run share, owned by the experiment runner and handed to the stage under
// way (stage.h): the configuration, the simulation, the series and samples, the strain
// references, the record and checkpoint schedule, the warnings, and the services a stage uses to
// record a row, write a checkpoint or give a warning. Stage-kind state lives in the stage
// objects, not here. Used on the thread that drives the runner.

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/experiment.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/measures.h"
#include "grainlab/run_output.h"
#include "grainlab/run_warning.h"
#include "grainlab/series.h"
#include "grainlab/simulation.h"
#include "grainlab/stage_kind.h"
#include "runner_state.h"

namespace grainlab {

class Stage;

/// The series compaction stages record to.
inline constexpr const char* kCompactionSeries = "compaction";

/// Threads a run of `config` uses (experiment_runner.h, engineThreads).
int threadsFor(const ExperimentConfig& config);
/// Steps of the shear test for an axial strain (at least one).
std::int64_t strideOf(const ExperimentConfig& config, double strain);

/// Adds the wall time from its construction to its end to `seconds`.
class AddWallTime {
public:
    explicit AddWallTime(double& seconds)
        : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
    ~AddWallTime() {
        seconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    AddWallTime(const AddWallTime&) = delete;
    AddWallTime& operator=(const AddWallTime&) = delete;

private:
    double& seconds_;
    std::chrono::steady_clock::time_point start_;
};

struct RunContext {
    ExperimentConfig config;
    RunOutput* output = nullptr;
    std::unique_ptr<Simulation> sim;
    std::unique_ptr<Stage> stage; ///< the stage under way; the last one once the run is done
    bool done = false;
    bool stageDone = false;      ///< `stage` has ended; the next one is still to start
    std::int64_t stepsTaken = 0; ///< steps advanced by this runner object (its cost)
    RunnerTimes times;           ///< where this runner object's wall time has gone

    std::int64_t stageStartStep = 0;
    double length1At0 = 0, length2At0 = 0, areaAt0 = 0; ///< strain references [m], [m^2]
    bool haveLast = false;
    double lastEps1 = 0, lastEpsv = 0;
    /// The step of the last record, and the DI reference it was made with (not saved in the
    /// runner state: measures of the step just recorded, ExperimentRunner::measuresNow()).
    std::int64_t lastRecordStep = -1;
    bool haveBeforeLast = false;
    double beforeLastEps1 = 0, beforeLastEpsv = 0;
    std::int64_t nextRecordStep = 0, nextSnapshotStep = 0;
    std::int64_t checkpointCounter = 0;
    /// Grain orientations at the start of the current test [rad]: shared (never modified in
    /// place) so that progress reports and snapshots hand it on without copying.
    std::shared_ptr<const std::vector<double>> thetaAtTestStart =
        std::make_shared<const std::vector<double>>();
    /// The generated assembly's, the compaction's identity [rad].
    std::shared_ptr<const std::vector<double>> thetaAtRunStart =
        std::make_shared<const std::vector<double>>();
    std::map<double, SimulationState> samples;
    std::vector<SeriesTable> series;
    int currentSeries = -1;
    std::vector<RunWarning> warnings; ///< every warning given so far, in order
    /// The runner-state fields of stages no longer under way, with their final values.
    RunnerState carried;
    /// The state the probes after the current test start from (stage_probes.h: their start
    /// strain, or the test's peak of q/p), from when the test passes it until the probes start.
    /// Written beside the first checkpoint after it (the run file's group probe_start of the
    /// checkpoint probeStartKeptIn), so that a run resumed before the probes start has it.
    std::optional<SimulationState> probeStart;
    std::string probeStartKeptIn;

    std::string currentTest() const;
    void warn(const std::string& kind, const std::string& text);
    int seriesIndex(const std::string& name);
    void setStrainReference();
    double eps1() const { return (length1At0 - sim->cell()[0]) / length1At0; }
    double eps2() const { return (length2At0 - sim->cell()[3]) / length2At0; }
    double epsv() const { return (areaAt0 - sim->cellArea()) / areaAt0; }
    /// Steps of the shear test for an axial strain (at least one).
    std::int64_t strideOf(double strain) const { return grainlab::strideOf(config, strain); }

    /// Appends a row of measures now to the current series.
    void recordNow();
    /// What a record made now with these measures would hold beyond them (the strains from the
    /// test's start, the dilatancy index since the last record, N_vi, rates, energies).
    /// With `asLastRecord` at the step of the last record: the inputs that record was made with.
    RecordInputs recordInputs(const MeasureSet& measures, bool asLastRecord = false) const;
    /// "shear 100 kPa"; "done" once the run is.
    std::string stageName() const;
    StageIdentity identity() const;
    std::string checkpointLabel() const;
    /// Writes a checkpoint of now (nothing without an output).
    void checkpoint(const std::string& label);
    void checkpoint(const std::string& label, const StageIdentity& id);
    /// The next checkpoint's name, counting it.
    std::string nextCheckpointName(const std::string& label);
    /// The runner state of now, for a checkpoint (the current stage adds its own fields).
    RunnerState runnerState() const;
    /// Takes back what runnerState() wrote of the run (series must hold the resumed series);
    /// the stage's own fields are the stage's to restore.
    void restore(const RunnerState& state);
};

} // namespace grainlab
