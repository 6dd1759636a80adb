#pragma once
// The servo probe: runs a prepared dense sample through a short drained biaxial shear (x1 strain
// controlled, x2 held at the confining pressure by the servo at one setting of gain and
// interval) and classifies how the lateral stress control behaved, from the error of sigma22
// against its target after every step. The classification is a pure function of that error
// series, so that it is tested on closed forms without a scene. Used by the servo map of
// `grainlab stability` (docs/stability.md). The engine itself accepts any gain: the bound on it
// is the experiment reader's, so the probe, which builds its states directly, is not held by
// it. Synchronous, on the caller's thread.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/simulation_state.h"

namespace grainlab {

/// How the lateral stress control behaved after the transient.
enum class ServoResponse {
    Steady,      ///< |error| within the band at every step
    Lagging,     ///< out of the band, but without oscillating (the servo cannot keep up)
    Oscillating, ///< a sustained alternating error above the oscillation threshold
    Diverging,   ///< the alternating error grew far beyond the band, or the run stopped
};
/// "steady", "lagging", "oscillating", "diverging".
std::string servoResponseName(ServoResponse response);
/// The inverse of servoResponseName; throws std::invalid_argument for another name.
ServoResponse servoResponseFromName(const std::string& name);
/// Oscillating or diverging: the setting is past the servo's stability limit.
inline bool servoUnstable(ServoResponse r) {
    return r == ServoResponse::Oscillating || r == ServoResponse::Diverging;
}

/// The classification's thresholds, as fractions of the target stress.
struct ServoThresholds {
    double band = 0.01; ///< steady: |error| <= band at every step after the transient [-]
    /// Oscillating: the alternating amplitude (ServoErrorStats::alternating) above this [-].
    double oscillation = 0.01;
    /// Diverging: the alternating amplitude above this, or the run stopped [-].
    double divergence = 0.1;
    double transient = 0.25; ///< the leading fraction of the run not judged [-]
};

/// The error e = (sigma22 - target) / target, after the transient unless said otherwise.
struct ServoErrorStats {
    double transientMax = 0; ///< largest |e| during the transient [-]
    double maxError = 0;     ///< largest |e| [-]
    double meanError = 0;    ///< mean e (positive: sigma22 above its target) [-]
    double rmsError = 0;     ///< root mean square of e [-]
    /// Root mean square of (e_{k+1} - 2 e_k + e_{k-1}) / 4 over consecutive servo updates k:
    /// the amplitude of an error that alternates in sign from one update to the next (the mode
    /// in which a sampled proportional loop becomes unstable, its root crossing the unit circle
    /// at z = -1); a constant lag or a steady drift of the error contributes nothing [-].
    double alternating = 0;
    /// Sign changes of e between consecutive servo updates, per update [-].
    double reversals = 0;
    std::int64_t steps = 0;   ///< steps run [-]
    std::int64_t updates = 0; ///< servo updates judged (after the transient) [-]
    bool stopped = false;     ///< the run stopped (engine error or a non-finite stress)
    std::string stopCause;
};

/// The error series of one run: e after every step, and e as each servo update read it.
struct ServoErrorSeries {
    std::vector<double> perStep;   ///< e after step k = index + 1 [-]
    std::vector<double> perUpdate; ///< e read by the servo's updates, in order [-]
    /// The step count (since the run began) of each update [-].
    std::vector<std::int64_t> updateStep;
};

/// The statistics of `series` after the leading `thresholds.transient` of its steps (updates
/// judged: those at or after that step). `stopped` marks a run that ended early.
ServoErrorStats servoErrorStats(const ServoErrorSeries& series, const ServoThresholds& thresholds,
                                bool stopped = false, const std::string& stopCause = {});

/// Diverging when stopped or alternating > divergence; steady when maxError <= band;
/// oscillating when alternating > oscillation; else lagging.
ServoResponse classifyServo(const ServoErrorStats& stats, const ServoThresholds& thresholds);

/// One setting of the servo.
struct ServoSetting {
    double gain = 0.3;          ///< g [-]
    int interval = 1;           ///< steps between servo updates [-]
    double integralGain = 0.05; ///< g_I [-]
};

struct ServoShear {
    double pressure = 0;         ///< lateral target sigma22 [Pa]
    double strainPerStep = 1e-6; ///< axial engineering strain per step [-]
    double maxStrainRate = 50.0; ///< the servo's rate cap [1/s]
    std::int64_t steps = 5000;   ///< steps of shear [-]
};

struct ServoProbeResult {
    ServoErrorStats stats;
    ServoResponse response = ServoResponse::Steady;
    ServoErrorSeries error; ///< as long as the run lasted
};

/// Shears `base` (its time step, friction and damping as given; its servo integral cleared) at
/// `setting` and classifies the lateral control. The engine's guards stay on: a run they stop
/// counts as diverging.
ServoProbeResult runServoProbe(SimulationState base, const ServoSetting& setting,
                               const ServoShear& shear, const ServoThresholds& thresholds);

} // namespace grainlab
