#pragma once
// The critical time step of central-difference integration for a shape table and material, and
// the check that refuses a time step above the stable limit. Used by the stepper when it is
// built, by the experiment-file reader before a run, by the study (time-step levels) and by the
// stability map (the estimate it measures against). Pure functions, safe on any thread.
//
// The estimate. Central differences are stable for omega_max dt < 2. The stiffest grain with z
// contacts (z the design coordination) has a translational stiffness z max(k_n, k_t) and a
// rotational stiffness of at most z max(k_n, k_t) a^2 (every contact force has a lever arm of at
// most the half-width a), so dt_e = min over shapes of 2 sqrt(m / (z k)) and
// 2 sqrt(I / (z k a^2)). Cundall's local damping adds alpha |F| along F whenever the velocity
// opposes the force, as it does in the highest mode at every step, so that mode sees a stiffness
// (1 + alpha) k: its estimate is dt_e / sqrt(1 + alpha).
//
// The limit. The stability maps (docs/stability.md) measured the largest stable step of dense,
// sheared and loose packings over shape, stiffness ratio and damping; the limit the check
// enforces is the estimate times kTimeStepMargin, below every measured limit.

#include <string>
#include <vector>

#include "grainlab/oval_shape.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// The limit the check enforces, as a fraction of the estimate: below the smallest measured
/// limit of the stability map (kSmallestMeasuredLimit), with a margin for assemblies whose most
/// crowded grain has more contacts than the map's [-].
inline constexpr double kTimeStepMargin = 0.9;
/// The smallest and largest measured stable step of dense and sheared packings in the stability
/// map's full preset (300 grains, eta 1 to 0.4, k_t/k_n 0.25 to 2, no, viscous and local
/// damping), as a fraction of the estimate (docs/stability.md, "Measured maps") [-].
inline constexpr double kSmallestMeasuredLimit = 0.98;
inline constexpr double kLargestMeasuredLimit = 2.0;

/// The critical time step estimate for a shape table and parameters, and the limit enforced.
struct TimeStepLimit {
    double translational = 0; ///< 2 sqrt(m_min / k_eff), times dampingFactor [s]
    double rotational = 0;    ///< 2 sqrt(I_min / K_theta), times dampingFactor [s]
    double dampingFactor = 1; ///< 1 / sqrt(1 + alpha) for Cundall local damping, else 1 [-]
    double estimate = 0;      ///< the smaller of the two [s]
    double limit = 0;         ///< the largest step accepted: kTimeStepMargin * estimate [s]
    int stiffestShape = 0;    ///< shape index that sets the estimate
};
TimeStepLimit criticalTimeStep(const std::vector<OvalShape>& shapes,
                               const SimulationParameters& parameters);

/// Refuses a time step above the limit, or an estimate that is not a finite positive number
/// (throws std::invalid_argument stating the step, the estimate, the margin and the measured
/// limits it stands for); returns a warning text when the step is within 20 % of the limit, an
/// empty string otherwise.
std::string checkTimeStep(const std::vector<OvalShape>& shapes,
                          const SimulationParameters& parameters);

} // namespace grainlab
