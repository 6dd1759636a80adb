#pragma once
// The scenes of the stability map (stability_map.h): for one cell, the packing state it is
// probed in, built by the engine's own rules: a loose gas on the generator's grid with random
// velocities; a dense sample compacted by the shared compacted scene (grainlab_scenes) at the
// cell's pressure, then held at a fixed cell with friction on; or that sample sheared (strain
// control on x1, x2 held at the pressure) for a short pre-strain at a safe step. Main thread.

#include "grainlab/simulation_state.h"
#include "grainlab/stability_map.h"

namespace grainlab {

/// The packing of a cell before its method parameters are set: the gas, or the compacted
/// sample (velocities cleared). Independent of stiffness ratio and damping.
struct StabilityPacking {
    SimulationState state;
    bool calm = true;       ///< a compacted sample met the equilibrium rule (gas: true)
    std::int64_t steps = 0; ///< compaction steps [-]
};
StabilityPacking stabilityPacking(const StabilityMapSpec& spec, const StabilityCell& cell);

/// The state a probe starts from: the packing with the cell's k_t / k_n, friction and `damping`,
/// and for a shear cell, sheared for the preset's pre-strain at half the engine's estimate.
SimulationState stabilityProbeState(const StabilityMapSpec& spec, const StabilityCell& cell,
                                    const StabilityPacking& packing,
                                    const DampingParameters& damping);

} // namespace grainlab
