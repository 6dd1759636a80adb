#pragma once
// What the two stages that wait for equilibrium share (compaction, re-equilibration): both
// axes servoed to the stage's pressure, a record every record.step_interval steps, a
// checkpoint every record.snapshot_step_interval steps, and an equilibrium check every
// criterion.check_interval steps counted from the stage's start; the stage has finished after
// criterion.calm_checks passing checks in a row, and fails (std::runtime_error saying why) at
// criterion.max_steps. Saves: calm (the passing checks in a row) and unbalanced_low.

#include "grainlab/equilibrium.h"
#include "stage.h"

namespace grainlab {

class EquilibriumStage : public Stage {
public:
    using Stage::Stage;
    std::int64_t stepsToNextEvent(const RunContext& ctx) const override;
    bool handleEvents(RunContext& ctx) override;
    void save(RunnerState& state, const RunContext& ctx) const override;
    void restore(const RunnerState& state, const RunContext& ctx, const SimulationState& resumed,
                 std::optional<SimulationState> runningPeak) override;

protected:
    /// The stage's equilibrium criterion: the compaction's, or the re-equilibration's.
    virtual const EquilibriumCriterion& criterion(const ExperimentConfig& config) const = 0;
    /// Resets the checks and sets the servo and the record schedule, from the current step: the
    /// first record at the first equilibrium check (events fall on whole steps counted from the
    /// stage's start, never where a caller's advance() happens to end).
    void startWaiting(RunContext& ctx);
    /// A stage's share when it is expected to take `expected` steps (capped by its criterion).
    StageShare settlingShare(double expected, const EquilibriumCriterion& criterion) const;

private:
    int calm_ = 0;            ///< consecutive passing checks
    CalmHistory calmHistory_; ///< of this stage's checks: why it did not calm
};

} // namespace grainlab
