#pragma once
// One cell of the servo map (servo_map.h): compacts a dense sample at the cell's pressure and
// shape with the shared compacted scene, equilibrates it at the shear friction, then shears it
// once per gain of the preset's grid with the lateral servo at the cell's interval, classifying
// each run (servo_probe.h), and bisects the largest stable gain between the grid's last stable
// and first unstable gains. No files: `grainlab stability cell` writes the result
// (app/stability/map_point_command.h). Main thread.

#include "grainlab/servo_map.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// The sample a cell's runs start from, and whether its preparation met the equilibrium rule.
struct ServoSample {
    SimulationState state;
    bool calm = true;
};
ServoSample servoSample(const ServoMapSpec& spec, const ServoCell& cell);

/// The servo's affine stiffness estimate E_22 = (1/A) sum l_2^2 (k_n n_2^2 + k_t t_2^2) of a
/// state (k_t only with friction), as the engine's servo computes it [Pa].
double affineLateralStiffness(const SimulationState& state);

/// Measures one cell (seconds to minutes of work; no files).
ServoCellResult measureServoCell(const ServoMapSpec& spec, const ServoCell& cell);

} // namespace grainlab
