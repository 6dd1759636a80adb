#pragma once
// Sample generation (docs/experiment-file.md): grains placed on a grid in a rectangular periodic
// cell with random orientations and no contact (a very loose start). Called once before a run, on
// the caller's thread.

#include <cstdint>
#include <vector>

#include "grainlab/oval_shape.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

struct AssemblySpec {
    int grainCount = 8450;
    std::vector<double> widths; ///< the size classes, W [m]; counts as equal as possible
    double aspectRatio = 0.6;   ///< H/W in (0, 1]
    OvalClosure closure = OvalClosure::EqualArea;
    double endRadiusRatio = 0;  ///< r/W when closure is EndRadiusRatio
    double gap = 0.1;           ///< free space between grid neighbours, fraction of W_max
    double cellAspectRatio = 1; ///< L1 / L2 of the rectangular cell
    std::uint64_t seed = 1;
};

/// The shape table of an assembly: one oval per size class, in the order of `spec.widths` (grain
/// i has size class i mod the number of classes, before the grid is shuffled).
std::vector<OvalShape> assemblyShapes(const AssemblySpec& spec);

/// `count` widths evenly spaced from `smallest` to `largest` [m].
std::vector<double> evenlySpacedWidths(double smallest, double largest, int count);

/// A loose periodic assembly: the returned state has the given parameters, no velocities, no
/// contacts and both axes in strain mode at rate 0. Throws std::invalid_argument on bad input.
SimulationState generateGridAssembly(const AssemblySpec& spec,
                                     const SimulationParameters& parameters);

} // namespace grainlab
