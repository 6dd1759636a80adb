#pragma once
// A test that strains axis 1 monotonically, after the sample's re-equilibration: axis 1
// shortened at a constant engineering strain per step (shear.axial_strain_per_step) to
// shear.target_axial_strain, or lengthened as much in extension (test.direction), axis 2
// following the test's path (its stage kind):
//  - Shear, the drained biaxial test: sigma22 servoed to the confining pressure;
//  - ConstantVolume: the cell's area held at its value at the start (exactly, AxisMode
//    ConstantArea), the undrained analogue;
//  - StressPath: sigma22 servoed to P + a (sigma11 - sigma11_0) (AxisMode StressPath), P the
//    confining pressure and sigma11_0 the axial stress at the start; ConstantP is a = -1,
//    which keeps p = (sigma11 + sigma22) / 2 at (P + sigma11_0) / 2. Events fall on whole steps
//    counted from its start: a record every
// record.strain_interval of eps1, a checkpoint every record.snapshot_strain_interval.
//
// It records N_vi at its start (the reference of the void-count columns) and tracks the running
// maximum of q/p over its records (of -q/p in extension); at its end it writes that state as the
// test's peak checkpoint. Saved: voids_at_start and peak (with the state at the peak kept beside
// the first checkpoint after it, the run file's group running_peak).
//
// When the next test in the experiment's list is a set of probes that starts at a strain of this
// test or at its peak (stage_probes.h), it hands their start state over in RunContext::probeStart:
// the state at the first step whose eps1 reaches their start_strain, or, at its end, the state at
// its peak of q/p.
//
// The model for a new test kind: its axis controls in startTest() (or changed in handleEvents()),
// its stop criterion in handleEvents(), its records and tracked measures, its
// saveTest()/restoreTest().

#include "stage.h"

namespace grainlab {

class MonotonicTestStage final : public LoadingTestStage {
public:
    using LoadingTestStage::LoadingTestStage;
    bool handleEvents(RunContext& ctx) override;
    void finish(RunContext& ctx) override;
    void addToCheckpoint(CheckpointData& data) override;
    /// Exactly its steps to the target strain (it moves linearly).
    StageShare share(const ExperimentConfig& config) const override;

private:
    /// The running maximum of q/p, at record points. The peak is known only when the test
    /// ends: until then the state of the largest q/p so far is kept here, and written as the
    /// peak checkpoint at the end. A checkpoint written in between keeps the maximum in its
    /// runner state (and the state beside the checkpoint, see keptIn), so that a resumed run
    /// continues it and writes the same peak checkpoint as an unbroken run.
    struct RunningPeak {
        bool active = false;
        RunningPeakRecord at;  ///< q/p, step, eps1, and the checkpoint keeping the state
        SimulationState state; ///< at that record
    };

    /// Axis 2's control for the test's path, from the state at its start.
    AxisControl lateralControl(const RunContext& ctx) const;
    std::int64_t endStep(const RunContext& ctx) const;
    void trackPeak(RunContext& ctx);
    /// +1 in compression (axis 1 shortened), -1 in extension.
    double direction(const RunContext& ctx) const;
    /// The probes after this test, when they start at a strain of it or at its peak; else null.
    const LoadingPath* probesAfter(const RunContext& ctx) const;
    /// The step at which the probes after it start (start "strain"); -1 for none.
    std::int64_t handOverStep(const RunContext& ctx) const;
    void peakCheckpoint(RunContext& ctx);

    void startTest(RunContext& ctx) override;
    std::int64_t nextTestEvent(const RunContext& ctx) const override;
    void saveTest(RunnerState& state, const RunContext& ctx) const override;
    void restoreTest(const RunnerState& state, const RunContext& ctx,
                     const SimulationState& resumed, std::optional<SimulationState> kept) override;

    RunningPeak peak_;
};

} // namespace grainlab
