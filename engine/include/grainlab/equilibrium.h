#pragma once
// The equilibrium rule of a stage held at an isotropic pressure: one check looks at the stress
// (both normal stresses within a relative tolerance of the target) and at the unbalanced-force
// index I_uf (below a threshold), with at least one contact; a stage is in equilibrium after
// `calmChecks` consecutive passing checks `checkInterval` steps apart. The experiment runner
// applies it to every compaction and equilibration stage; the shared scenes compact by it. When
// a stage reaches its step cap without calming, whyNotCalm() says why from the history of its
// checks. Pure functions, on the thread that drives the simulation.

#include <array>
#include <cstdint>
#include <string>

#include "grainlab/experiment.h"
#include "grainlab/simulation.h"

namespace grainlab {

struct EquilibriumCheck {
    double stressError = 0;     ///< max_i |sigma_ii - target| / target [-]
    double unbalancedForce = 0; ///< I_uf [%]
    bool pass = false;          ///< both within the criterion and at least one contact
};

/// One check of the rule against `targetPressure` [Pa] (> 0).
EquilibriumCheck checkEquilibrium(const Simulation& simulation, double targetPressure,
                                  const EquilibriumCriterion& criterion);

/// The count of consecutive passing checks after `check`.
inline int calmChecksAfter(int calm, const EquilibriumCheck& check) {
    return check.pass ? calm + 1 : 0;
}

/// What a stage's checks tell about why it does not calm: the lowest I_uf of its checks in each
/// quarter of its step cap.
struct CalmHistory {
    std::array<double, 4> lowest{-1, -1, -1, -1}; ///< [%]; -1: no check in that quarter yet

    /// Notes the I_uf of a check `inStage` steps into a stage capped at `maxSteps` steps.
    void note(std::int64_t inStage, std::int64_t maxSteps, double unbalancedForce);
};

/// Why a stage that ran to its step cap did not calm, and what to change, in words: nothing
/// dissipates energy (no damping, friction 0); the stress is still more than ten tolerances from
/// its target; the I_uf keeps a floor above the criterion (its lowest over the last quarter is
/// not below 90 % of its lowest over the second: the packing jitters, the mark of a time step
/// above the packing's stable limit: the text names the step and its ratio to the engine's
/// limit); or it was still falling (more steps). `state` is the stage's simulation state.
std::string whyNotCalm(const CalmHistory& history, double stressError,
                       const EquilibriumCriterion& criterion, const SimulationState& state);

} // namespace grainlab
