#pragma once
// The equilibrium rule of a stage held at an isotropic pressure: one check looks at the stress
// (both normal stresses within a relative tolerance of the target) and at the unbalanced-force
// index I_uf (below a threshold), with at least one contact; a stage is in equilibrium after
// `calmChecks` consecutive passing checks `checkInterval` steps apart. The experiment runner
// applies it to every compaction and equilibration stage; the shared scenes compact by it.
// Pure function of the simulation's current state, on the thread that drives the simulation.

#include <cstdint>

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

} // namespace grainlab
