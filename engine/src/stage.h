#pragma once
// A stage of an experiment, as the runner (experiment_runner.cpp) plays it: the runner advances
// the simulation to the stage's next event, lets the stage handle it, and when the stage says it
// has finished, ends it and starts the next stage of the plan (experimentPlan()).
//
// Each stage kind is a class of its own file pair (stage_*.h): compaction (stage_compaction.h)
// and re-equilibration (stage_equilibration.h), both waiting for equilibrium
// (stage_equilibrium.h), the tests that strain axis 1 monotonically while axis 2 follows their
// path: drained, constant volume, constant p, linear stress path (stage_monotonic_test.h), cyclic
// loading (stage_cyclic.h) and stress probes (stage_probes.h). The
// generated assembly is made by stage_generation.h. A stage owns:
//  - how it drives the cell: start() sets each axis's control (Simulation::setAxisControl); a
//    test that changes them during its course does so in handleEvents();
//  - when it has finished, and why: handleEvents() returns true; a stage that cannot finish
//    throws std::runtime_error saying why;
//  - what it records: it calls RunContext::recordNow() at its record points, and
//    initialVoidCount() gives the test's N_vi reference; anything it tracks over its records
//    (the running peak of q/p) is its own state;
//  - what a checkpoint keeps of it: save() and restore() of its RunnerState fields (new fields
//    are new keys: an old file lacks them and must still read), and addToCheckpoint() for data
//    stored beside the checkpoint (the state at the running peak);
//  - its share of the progress estimate (share(), progress_estimate.h).
//
// A new test kind (simple shear, ...) is a new StageKind value (grainlab/stage_kind.h) that
// isTestStage() counts, a class deriving from TestStage, or from LoadingTestStage for a test
// that loads along a path with records and checkpoints at strain intervals (below), in its own
// stage_*.{h,cpp} like MonotonicTestStage, CyclicStage and ProbesStage, a case in makeStage(),
// stageKindOf() and experimentPlan() below, and its kind and keys in the reader of the
// experiment file's `test` (loading_path.cpp). The runner itself does not change.
//
// Called on the thread that drives the runner; one virtual call per stage event, none per step.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/experiment.h"
#include "grainlab/measures.h"
#include "grainlab/run_output.h"
#include "grainlab/simulation_state.h"
#include "grainlab/stage_kind.h"
#include "progress_estimate.h"
#include "run_context.h"
#include "runner_state.h"

namespace grainlab {

/// One entry of a run's plan: a stage kind at a pressure.
struct PlannedStage {
    StageKind kind = StageKind::Compaction;
    /// Compaction: into compaction.pressures. Re-equilibration and test: pressure k's test j is
    /// k * tests.size() + j (k, into shear.pressures, with one test per sample as before).
    int index = 0;
    double pressure = 0; ///< the confining pressure [Pa]
    int test = 0;        ///< into ExperimentConfig::tests (re-equilibration and test)
    std::string series;  ///< the series its records go to ("" for compaction)
};

/// The stage kind that plays a test of `path`.
StageKind stageKindOf(const LoadingPath& path);

/// The stages of an experiment, in order: compaction to each pressure, then for each test
/// pressure and each of its tests (ExperimentConfig::tests) a re-equilibration of the sample and
/// the test.
std::vector<PlannedStage> experimentPlan(const ExperimentConfig& config);
/// Where the stage of a runner state (phase, index) is in `plan`; plan.size() when done.
std::size_t planPosition(const std::vector<PlannedStage>& plan, StageKind kind, int index);

class Stage {
public:
    explicit Stage(const PlannedStage& planned) : planned_(planned) {}
    virtual ~Stage() = default;
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;

    StageKind kind() const { return planned_.kind; }
    int index() const { return planned_.index; }
    double pressure() const { return planned_.pressure; } ///< [Pa]
    int testIndex() const { return planned_.test; }       ///< into ExperimentConfig::tests
    /// The series its records go to.
    virtual std::string test() const { return planned_.series; }
    /// True for a test (its eps1 is the test's axial strain, reported in RunProgress).
    virtual bool isTest() const { return false; }

    /// Sets up a fresh stage (not a resumed one) on ctx.sim, including its first checkpoint
    /// if it writes one.
    virtual void start(RunContext& ctx) = 0;
    /// Steps until the next thing the stage must look at (>= 1).
    virtual std::int64_t stepsToNextEvent(const RunContext& ctx) const = 0;
    /// Looks at the state after a chunk of steps: records, checkpoints; true when finished.
    virtual bool handleEvents(RunContext& ctx) = 0;
    /// What the stage does once finished, before the runner's stage-end checkpoint.
    virtual void finish(RunContext& ctx) { (void)ctx; }
    /// True when its end is a checkpoint of its own marked stage_done (a compaction's sample, a
    /// test's end); false when the next stage follows at once (re-equilibration).
    virtual bool checkpointAtEnd() const = 0;

    /// N_vi of the test for a record made now (measures of that record); 0 outside tests.
    virtual double initialVoidCount(const MeasureSet& measures) const {
        (void)measures;
        return 0;
    }
    /// A record is made with these measures: a test keeps its first record's void count as N_vi.
    virtual void noteRecord(const MeasureSet& measures) { (void)measures; }
    /// Adds what the stage keeps beside a checkpoint (called before the runner state is made).
    virtual void addToCheckpoint(CheckpointData& data) { (void)data; }
    /// Writes the stage's own fields of the runner state.
    virtual void save(RunnerState& state, const RunContext& ctx) const = 0;
    /// Reads them back, before ctx.sim exists. `resumed` is the checkpoint's state and
    /// `runningPeak` the ResumePoint's (used by a test tracking a peak).
    virtual void restore(const RunnerState& state, const RunContext& ctx,
                         const SimulationState& resumed,
                         std::optional<SimulationState> runningPeak) = 0;
    /// Its share of the progress estimate.
    virtual StageShare share(const ExperimentConfig& config) const = 0;

private:
    PlannedStage planned_;
};

/// What every test stage shares: it is a test (its eps1 is the test's), it ends with a
/// checkpoint of its own, and N_vi, the void count of its first record, is the reference of its
/// void-count columns (saved as voids_at_start). A test keeps no running peak in the runner state
/// unless its saveTest() says so.
class TestStage : public Stage {
public:
    using Stage::Stage;
    bool isTest() const override { return true; }
    bool checkpointAtEnd() const override { return true; }
    double initialVoidCount(const MeasureSet& measures) const override {
        return voidsAtStart_ < 0 ? measures.voidCells.voidCount : voidsAtStart_;
    }
    void noteRecord(const MeasureSet& measures) override {
        voidsAtStart_ = initialVoidCount(measures);
    }
    void save(RunnerState& state, const RunContext& ctx) const final;
    void restore(const RunnerState& state, const RunContext& ctx, const SimulationState& resumed,
                 std::optional<SimulationState> runningPeak) final;

protected:
    /// For start(): N_vi is taken again at the first record.
    void forgetInitialVoids() { voidsAtStart_ = -1; }
    /// The test's own fields of the runner state, after N_vi (and an empty peak).
    virtual void saveTest(RunnerState& state, const RunContext& ctx) const = 0;
    /// Reads them back, after N_vi (arguments as restore()'s).
    virtual void restoreTest(const RunnerState& state, const RunContext& ctx,
                             const SimulationState& resumed,
                             std::optional<SimulationState> kept) = 0;

private:
    double voidsAtStart_ = -1; ///< N_vi of the test; -1 before its first record
};

/// What the tests that load the sample along their path share (monotonic and cyclic): they
/// start where the stage starts, with a record there (eps1 = 0: N_vi) and a checkpoint; then a
/// record every record.strain_interval of eps1 and a checkpoint every
/// record.snapshot_strain_interval. Events fall on whole steps counted from the start of the
/// test (each step adds the same engineering strain), so they do not depend on how advance() is
/// chunked.
class LoadingTestStage : public TestStage {
public:
    using TestStage::TestStage;
    void start(RunContext& ctx) final;
    std::int64_t stepsToNextEvent(const RunContext& ctx) const final;

protected:
    /// For start(), after the strain reference: the test's own state afresh, its axis controls
    /// and its first record (recordFirst()), before the start's checkpoint.
    virtual void startTest(RunContext& ctx) = 0;
    /// The first record (eps1 = 0: N_vi), and the schedule of records and checkpoints.
    static void recordFirst(RunContext& ctx);
    /// The next step at which the test itself must look (its end, a reversal, a hand-over),
    /// besides its records and checkpoints.
    virtual std::int64_t nextTestEvent(const RunContext& ctx) const = 0;
    /// A record now, the next one a strain interval on.
    static void record(RunContext& ctx);
    /// A checkpoint now if one is due, the next one a snapshot interval on.
    static void checkpointWhenDue(RunContext& ctx);
};

/// The stage object for a plan entry.
std::unique_ptr<Stage> makeStage(const PlannedStage& planned);

} // namespace grainlab
