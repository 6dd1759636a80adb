#include "grainlab/equilibrium.h"

#include <algorithm>
#include <cmath>

#include "grainlab/measures.h"

namespace grainlab {

EquilibriumCheck checkEquilibrium(const Simulation& simulation, double targetPressure,
                                  const EquilibriumCriterion& criterion) {
    EquilibriumCheck out;
    const Stress s = simulation.stress();
    out.stressError =
        std::max(std::fabs(s.s11 - targetPressure), std::fabs(s.s22 - targetPressure)) /
        targetPressure;
    out.unbalancedForce = unbalancedForceIndex(simulation.contactNetwork());
    out.pass = out.stressError <= criterion.stressTolerance &&
               out.unbalancedForce <= criterion.unbalancedForceMax && simulation.contactCount() > 0;
    return out;
}

} // namespace grainlab
