#pragma once
// A cyclic test, after the sample's re-equilibration. Strain control (test.control "strain"): axis
// 1 driven along the triangular waveform of CyclicStrainSchedule (loading_path.h) from eps1 = 0 to
// mean + amplitude, then between mean + amplitude and mean - amplitude, at the drained test's
// strain per step (shear.axial_strain_per_step), reversing at exact steps; axis 2 drained (sigma22
// held at the confining pressure by the servo) or at constant volume (the cell's area held
// exactly).
//
// Stress control ("stress"): axis 1 compressed at the same strain per step until q at a record
// reaches mean + amplitude, then extended until q reaches mean - amplitude, and so on: each
// reversal comes at the first record past a bound (so within one record of it).
//
// It ends when the test has made its `cycles` cycles (a cycle: from one upper peak to the next),
// or, checked at each record, when |eps1| exceeds stop_strain_amplitude (stress control) or
// when p' has fallen below stop_pressure_fraction of p0 (p at the
// test's first record: the liquefaction analogue). A stop by the criterion is stated in a
// run notice of kind "test_end" naming the cycles reached, p' and the key. Records fall every
// record.strain_interval of strain travelled and at every peak of the waveform, checkpoints every
// record.snapshot_strain_interval, both on whole steps counted from the test's start.
//
// Saved: voids_at_start (N_vi), and under stress control cyclic_direction and cyclic_reversals.
// p0 is read back from the test's first record.

#include "grainlab/loading_path.h"
#include "stage.h"

namespace grainlab {

class CyclicStage final : public LoadingTestStage {
public:
    using LoadingTestStage::LoadingTestStage;
    bool handleEvents(RunContext& ctx) override;
    /// Strain control: its steps to the last cycle's end (a stop by the criterion ends it
    /// sooner); stress control: a guess that settles.
    StageShare share(const ExperimentConfig& config) const override;

private:
    const LoadingPath& path(const RunContext& ctx) const { return ctx.config.tests[testIndex()]; }
    CyclicStrainSchedule schedule(const RunContext& ctx) const;
    bool stressControl(const RunContext& ctx) const;
    /// Stress control: records, the stop criteria and the reversals decided at each record.
    bool handleStressControlled(RunContext& ctx);
    /// Sets axis 1's strain rate for the direction of the waveform after step n of the test.
    void driveAxis(RunContext& ctx, std::int64_t n) const;
    /// The stop criterion at the record just made: the notice's text, or "".
    std::string stopReason(const RunContext& ctx) const;
    /// Both axes' controls for the start of the waveform; p0 from the first record.
    void startTest(RunContext& ctx) override;
    std::int64_t nextTestEvent(const RunContext& ctx) const override;
    void saveTest(RunnerState& state, const RunContext& ctx) const override;
    /// p0 again from the test's first record in its series.
    void restoreTest(const RunnerState& state, const RunContext& ctx,
                     const SimulationState& resumed, std::optional<SimulationState> kept) override;

    double p0_ = 0;              ///< p at the test's first record [Pa]
    int direction_ = 0;          ///< stress control: +1 compressing, -1 extending; 0 strain control
    std::int64_t reversals_ = 0; ///< stress control: reversals so far
};

} // namespace grainlab
