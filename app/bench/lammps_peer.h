#pragma once
// The LAMMPS peer of `grainlab bench` (bench.h): the same disk assembly and the same biaxial test
// run by stock LAMMPS, so that the bench can quote both speeds from one invocation. Reads the
// LAMMPS data file of the dense state into an engine state, and drives the `lmp` process on
// resources/bench/lammps/in.bench. Runs on the caller's thread.

#include <cstdint>
#include <string>

#include "grainlab/simulation_state.h"

namespace grainlab {

/// Reads a LAMMPS data file of disks (atom_style sphere: id type diameter density x y z ix iy
/// iz; an orthogonal box) into a state of disks with `parameters`. LAMMPS's y axis becomes the
/// engine's x1 (the axial direction: in.bench compresses y) and x its x2; positions are taken
/// relative to (xlo, ylo); grains keep the file's order (LAMMPS writes them spatially sorted).
/// One shape per distinct diameter. The mass in the file must equal the engine's
/// density * pi r^2 (in.prep uses `set density/disc`); velocities (Velocities section) are read.
/// Throws std::runtime_error naming the file, the line and the problem.
SimulationState readLammpsDisks(const std::string& path, const SimulationParameters& parameters);

/// What one LAMMPS run measured.
struct LammpsResult {
    double grainStepsPerSecond = 0;
    double contactsPerGrain = 0; ///< Z at the end of the run (0 when LAMMPS did not print it)
};

/// True when `name` is found on the PATH (or is an executable path).
bool haveExecutable(const std::string& name);

/// Runs stock LAMMPS (`executable`) on in.bench in `directory` (biaxial mode, 1 process,
/// 1 thread) for `steps` steps and reads its loop time. Throws std::runtime_error with the end
/// of LAMMPS's output when it printed no loop time.
LammpsResult runLammps(const std::string& directory, const std::string& executable,
                       std::int64_t steps);

} // namespace grainlab
