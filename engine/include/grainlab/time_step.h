#pragma once
// The critical time step of central-difference integration for a shape table and material, and
// the check that refuses a time step above it. Used by the stepper when it is built and by the
// experiment-file reader before a run; pure functions, safe on any thread.
//
// Central differences are stable for omega_max dt < 2. The stiffest grain with z contacts (z the
// design coordination) has a translational stiffness z max(k_n, k_t) and a rotational stiffness
// of at most z max(k_n, k_t) a^2 (every contact force has a lever arm of at most the half-width
// a), so dt_c = min over shapes of 2 sqrt(m / (z k)) and 2 sqrt(I / (z k a^2)).

#include <string>
#include <vector>

#include "grainlab/oval_shape.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// The critical time step estimate for a shape table and parameters.
struct TimeStepLimit {
    double translational = 0; ///< 2 sqrt(m_min / k_eff) [s]
    double rotational = 0;    ///< 2 sqrt(I_min / K_theta) [s]
    double limit = 0;         ///< the smaller of the two [s]
    int stiffestShape = 0;    ///< shape index that sets the limit
};
TimeStepLimit criticalTimeStep(const std::vector<OvalShape>& shapes,
                               const SimulationParameters& parameters);

/// Refuses a time step above the stable limit, or a limit that is not a finite positive number
/// (throws std::invalid_argument naming the limit); returns a warning text when the step is
/// within 20 % of the limit, an empty string otherwise.
std::string checkTimeStep(const std::vector<OvalShape>& shapes,
                          const SimulationParameters& parameters);

} // namespace grainlab
