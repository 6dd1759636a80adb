#pragma once
// Where GrainLab's resources are (the preset experiments, studies and stability maps, the bench's
// LAMMPS inputs, the scripts): found at run time from the executable's own location, so that
// the same binary runs from its build folder and installed under any prefix, with no path of the
// source tree compiled in. Any thread.

#include <string>

namespace grainlab {

/// The resource folder: $GRAINLAB_RESOURCES when set; else <folder of the running executable>/
/// ../share/grainlab, which is the installed layout (PREFIX/bin/grainlab, PREFIX/share/grainlab)
/// and also exists in the build folder (BUILD/share/grainlab links to the source's resources/;
/// the executables are one folder down, BUILD/app/grainlab, BUILD/tests/...).
std::string resourceDirectory();

/// A path inside it: resourcePath("experiments/quick.json").
std::string resourcePath(const std::string& relative);

} // namespace grainlab
