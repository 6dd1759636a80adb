#pragma once
// The largest stable time step of one scene, by bisection on the time step between a bound that
// must be stable and one that must not be, to a stated relative precision. The probe is a
// function of the time step in the map's unit sqrt(m_min / k_n) (stability_probe.h), so that the
// bisection is tested on closed forms without a scene. Bisects the logarithm of the step (the
// bounds may be decades apart). Assumes one crossing: the bracket returned is what was seen.
// Synchronous, on the caller's thread.

#include <cstdint>
#include <functional>
#include <string>

#include "grainlab/stability_probe.h"

namespace grainlab {

struct StepLimit {
    /// Whether the bounds were as required: `low` stable and `high` unstable. When not, limit
    /// is the bound that failed to hold and `bracketed` is false.
    bool bracketed = false;
    double low = 0;                 ///< the largest step found stable [unit]
    double high = 0;                ///< the smallest step found unstable [unit]
    double limit = 0;               ///< the measured limit: `low` [unit]
    BlowUp detector = BlowUp::None; ///< what fired at `high`
    std::int64_t detectorStep = 0;  ///< at which step of that probe [-]
    std::string detail;             ///< the detector's words at `high`
    int probes = 0;                 ///< probe runs made [-]
};

using StepProbe = std::function<ProbeResult(double step)>;

/// Bisects between `low` (expected stable) and `high` (expected unstable), both > 0, until
/// high / low - 1 <= precision. Throws std::invalid_argument for bad bounds or precision.
StepLimit bisectStableStep(const StepProbe& probe, double low, double high, double precision);

} // namespace grainlab
