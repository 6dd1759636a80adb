#pragma once
// A strain-controlled cyclic test, after the sample's re-equilibration: axis 1 driven along the
// triangular waveform of CyclicStrainSchedule (loading_path.h) from eps1 = 0 to mean +
// amplitude, then between mean + amplitude and mean - amplitude, at the drained test's strain per
// step (shear.axial_strain_per_step), reversing at exact steps; axis 2 drained (sigma22 held at
// the confining pressure by the servo) or at constant volume (the cell's area held exactly).
//
// It ends when the test has made its `cycles` cycles (a cycle: from one upper peak to the next),
// or, checked at each record, when p' has fallen below stop_pressure_fraction of p0 (p at the
// test's first record: the liquefaction analogue). A stop by the criterion is stated in a
// run notice of kind "test_end" naming the cycles reached, p' and the key. Records fall every
// record.strain_interval of strain travelled and at every peak of the waveform, checkpoints every
// record.snapshot_strain_interval, both on whole steps counted from the test's start.
//
// Saved: voids_at_start (N_vi). p0 is read back from the test's first record.

#include "grainlab/loading_path.h"
#include "stage.h"

namespace grainlab {

class CyclicStage final : public TestStage {
public:
    using TestStage::TestStage;
    void start(RunContext& ctx) override;
    std::int64_t stepsToNextEvent(const RunContext& ctx) const override;
    bool handleEvents(RunContext& ctx) override;
    void save(RunnerState& state, const RunContext& ctx) const override;
    void restore(const RunnerState& state, const RunContext& ctx, const SimulationState& resumed,
                 std::optional<SimulationState> runningPeak) override;
    /// Its steps to the last cycle's end (a stop by the criterion ends it sooner).
    StageShare share(const ExperimentConfig& config) const override;

private:
    const LoadingPath& path(const RunContext& ctx) const { return ctx.config.tests[testIndex()]; }
    CyclicStrainSchedule schedule(const RunContext& ctx) const;
    /// Sets axis 1's strain rate for the direction of the waveform after step n of the test.
    void driveAxis(RunContext& ctx, std::int64_t n) const;
    /// The stop criterion at the record just made: the notice's text, or "".
    std::string stopReason(const RunContext& ctx) const;

    double p0_ = 0;            ///< p at the test's first record [Pa]
};

} // namespace grainlab
