#pragma once
// One cell of the stability map: builds its scene (stability_scene.h), bisects the largest
// stable time step with the probe (stability_probe.h, stability_bisection.h), measures the
// energy-balance residual with damping off at fractions of that limit, and records the engine's
// own estimate (time_step.h) beside it. No files: `grainlab stability cell` writes the result
// (app/stability/map_point_command.h). Main thread.

#include "grainlab/stability_map.h"

namespace grainlab {

/// The probe settings a map uses for `cell` (the unbalanced-force floor only for damped dense
/// packings: a gas has no floor, an undamped packing none to fall to).
ProbeSettings stabilityProbeSettings(const StabilityMapSpec& spec, const StabilityCell& cell);

/// Measures one cell (seconds of work; no files).
StabilityCellResult measureStabilityCell(const StabilityMapSpec& spec, const StabilityCell& cell);

} // namespace grainlab
