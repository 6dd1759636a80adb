#pragma once
// The stability probe: runs a prepared scene for a fixed number of steps at one time step with
// the engine's own guards switched off (SimulationParameters::stability.unguarded: no refusal
// of a step above the estimate, no overlap or runaway stop), and decides stable or unstable with
// a blow-up detector of its own. The detector looks at what an explicit scheme does past its
// limit: a non-finite state, a grain that travels a large part of its size in one step, an
// overlap beyond any physical meaning, kinetic energy or the energy-balance residual growing far
// beyond what the run began with, and the quiet mode of a dense packing, which may only jitter:
// the unbalanced-force index keeps a floor that does not fall where a stable step lets it fall.
// Used by the bisection (stability_bisection.h) and `grainlab stability`. Synchronous, on the
// caller's thread; pure apart from the simulation it runs.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/simulation_state.h"

namespace grainlab {

/// Which detector decided that a run was unstable.
enum class BlowUp {
    None,            ///< stable
    NonFinite,       ///< a position, velocity or energy is not a finite number
    Displacement,    ///< a grain moved more than maxTravel of its half-height in one step
    Overlap,         ///< an overlap above maxOverlap of the smaller width
    KineticEnergy,   ///< kinetic energy grew far above what the run began with
    EnergyResidual,  ///< the energy-balance residual grew far above what the run began with
    UnbalancedFloor, ///< the unbalanced-force index kept a floor that did not fall (jitter)
    EngineStop,      ///< the engine stopped the run itself (e.g. the cell became too narrow)
};
/// "none", "non_finite", "displacement", "overlap", "kinetic_energy", "energy_residual",
/// "unbalanced_force_floor", "engine_stop".
std::string blowUpName(BlowUp kind);

/// The detector's thresholds. Energies are compared with E_ref: the mechanical energy at the
/// start (kinetic + elastic) plus the work the cell has put in since, positive part.
struct BlowUpThresholds {
    double maxTravel = 0.5;    ///< travel in one step / half-height [-]
    double maxOverlap = 0.25;  ///< overlap / smaller width [-]
    double catastrophic = 1e4; ///< E_kin above this times E_ref, at once [-]
    /// |residual| above this times E_ref, at once: the scheme made (or lost) more energy than
    /// the run ever held [-].
    double maxResidual = 1.0;
    /// At step k: E_kin above `growth` times the larger of its maximum over steps [0, k/4] and
    /// kineticFloor E_ref; |residual| likewise with residualFloor. A stable explicit scheme
    /// keeps both bounded (they fluctuate, they do not grow); an unstable one grows
    /// exponentially, so the ratio exceeds any bound.
    double growth = 100;
    double kineticFloor = 1e-6;  ///< [-]
    double residualFloor = 1e-3; ///< [-]
    /// Dense packings only: at the end, the smallest I_uf over the last quarter of the run above
    /// both floorIndex and floorRise times I_uf at the start: the packing jitters.
    bool unbalancedFloor = false;
    double floorIndex = 5.0; ///< [%]
    double floorRise = 2.0;  ///< [-]
};

struct ProbeSettings {
    std::int64_t steps = 2000;       ///< steps of one probe run
    std::int64_t checkInterval = 10; ///< steps between the energy, overlap and I_uf checks
    BlowUpThresholds thresholds;
    bool trace = false; ///< keep every check in ProbeResult::trace
};

/// One check of a probe run.
struct ProbeCheck {
    std::int64_t step = 0; ///< steps since the probe began [-]
    double kinetic = 0;    ///< E_kin / E_ref [-]
    double residual = 0;   ///< energy-balance residual / E_ref (signed) [-]
    double unbalanced = 0; ///< I_uf [%]
    double maxOverlap = 0; ///< largest overlap / smaller width [-]
};

struct ProbeResult {
    bool stable = true;
    BlowUp detector = BlowUp::None; ///< the detector that fired first
    std::int64_t step = 0;          ///< step (since the probe began) at which it fired [-]
    std::string detail;             ///< what it saw, in words
    double energyScale = 0;         ///< E_ref at the end [J]
    double maxResidual = 0;         ///< largest |residual| / E_ref over the run [-]
    double finalResidual = 0;       ///< |residual| / E_ref at the end [-]
    double finalUnbalanced = 0;     ///< I_uf at the end [%]
    std::int64_t stepsRun = 0;      ///< steps actually taken [-]
    std::vector<ProbeCheck> trace;  ///< every check when ProbeSettings::trace is set
};

/// The time unit of the map: sqrt(m_min / k_n), m_min the smallest grain mass of the state [s].
double probeTimeUnit(const SimulationState& state);

/// Runs `base` for settings.steps steps at `timeStep` [s], unguarded, and classifies the run.
/// The energy bookkeeping is taken relative to the state as given. Throws std::invalid_argument
/// for a state the engine refuses for other reasons (no grains, a narrow cell).
ProbeResult runStabilityProbe(SimulationState base, double timeStep, const ProbeSettings& settings);

} // namespace grainlab
