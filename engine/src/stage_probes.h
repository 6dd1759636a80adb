#pragma once
// Stress probes: from one state, K small strain increments in directions evenly spread over the
// (d eps1, d eps2) plane (probeDirections(K), path_measures.h), each of size test.increment and
// each started from the same state, bit for bit; the stress response of each gives the
// incremental response envelope (responseEnvelope()).
//
// The start state (test.start) is, for "end", where the sample is when the stage starts: the end
// of the test before it in the experiment's test list, or, first in the list, the
// re-equilibrated sample; for "strain" and "peak", the state the monotonic test before it handed
// over in RunContext::probeStart (stage_monotonic_test.h): at the first step whose eps1 reaches
// test.start_strain, or at its peak of q/p. A probe moves
// both axes under strain control at the drained test's strain per step
// (shear.axial_strain_per_step) in its direction, for increment / strain-per-step steps (at least
// one); then the simulation is made again from the start state (its step counter going on, which
// no physics reads with both axes strain-controlled) for the next probe.
//
// First comes a zero probe: the same steps with both axes held (zero strain rate), whose stress
// change is the drift of the start state (a sample is never exactly at rest); a probe's response
// is its stress change minus that drift, so that a linear response gives opposite responses to
// opposite inputs.
//
// Records: one at the start, one at the zero probe's end, one at each probe's end.
// Checkpoints: at each probe's start. The start state is kept beside the stage's first
// checkpoint (the run file's group running_peak, named by the runner state's peak.kept_in), so
// that a run stopped in the middle of a probe resumes from it. Saved: voids_at_start, probe,
// probe_start_step, peak.
#include "stage.h"

namespace grainlab {

class ProbesStage final : public TestStage {
public:
    using TestStage::TestStage;
    void start(RunContext& ctx) override;
    std::int64_t stepsToNextEvent(const RunContext& ctx) const override;
    bool handleEvents(RunContext& ctx) override;
    /// Lets go of the start state: later stages keep no state beside their checkpoints for it.
    void finish(RunContext& ctx) override {
        (void)ctx;
        keptIn_.clear();
    }
    void addToCheckpoint(CheckpointData& data) override;
    /// K probes and the zero probe, of their steps each.
    StageShare share(const ExperimentConfig& config) const override;

private:
    void saveTest(RunnerState& state, const RunContext& ctx) const override;
    /// The start state is the one kept beside the checkpoint named (`kept`).
    void restoreTest(const RunnerState& state, const RunContext& ctx,
                     const SimulationState& resumed, std::optional<SimulationState> kept) override;
    /// Steps of one probe.
    static std::int64_t probeSteps(const ExperimentConfig& config, const LoadingPath& path);
    /// Makes the simulation again from the start state and drives probe `probe_`.
    void beginProbe(RunContext& ctx);

    SimulationState base_; ///< the start state of every probe
    std::string keptIn_;   ///< the checkpoint keeping base_ beside it
    int probe_ = 0;        ///< the probe under way; -1: the zero probe
    std::int64_t probeStart_ = 0;
};

} // namespace grainlab
