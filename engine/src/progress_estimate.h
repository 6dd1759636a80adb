#pragma once
// The estimate of how far a run is, as a fraction of its expected steps: a pure function of the
// plan of stages (each stage's share, StageShare) and where the run is (a stage and the steps
// taken in it). No history: it never decreases while a run goes on, and a resumed run reports
// what the unbroken one did at the same step. Each stage kind states its own share (Stage::share).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace grainlab {

/// One stage's part of the estimate.
struct StageShare {
    /// Its expected steps; a whole number, so that sums of shares are exact and a stage
    /// boundary cannot round backwards.
    double weight = 1;
    /// True for a stage of unknown length (one that waits for equilibrium): its part approaches
    /// the weight as 1 - exp(-steps / weight), so that a longer stage creeps on rather than
    /// stalls, and it is complete when the stage ends. False: its part is its steps, up to the
    /// weight (a test run to a fixed strain).
    bool settles = false;
};

/// The fraction [0, 1] of the run done at `stepsInStage` steps into stage `stage` of `plan`
/// (stage == plan.size(): the run is finished, 1). An empty plan is done.
double progressFraction(const std::vector<StageShare>& plan, std::size_t stage,
                        std::int64_t stepsInStage);

} // namespace grainlab
