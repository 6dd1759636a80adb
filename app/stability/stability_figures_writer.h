#pragma once
// The stability maps' figures for the headless `grainlab stability` (GUI builds only): the
// time-step map's heat maps, the servo map's response maps and stable-gain lines, the geometry
// map's departure lines, painted with the widgets' figure code into the map folder's figures/,
// under Qt's offscreen platform when no Qt application runs yet. Main thread.

#include <string>
#include <vector>

#include "grainlab/geometry_map.h"
#include "grainlab/servo_map.h"
#include "grainlab/stability_map.h"

namespace grainlab {

/// Writes figures/ into `folder`; returns "" or what went wrong.
std::string writeStabilityFiguresHeadless(const std::string& folder, const StabilityMapSpec& spec,
                                          const std::vector<StabilityCellResult>& results);

/// The servo map's figures, with the experiment reader's gain bound drawn on them.
std::string writeServoFiguresHeadless(const std::string& folder, const ServoMapSpec& spec,
                                      const std::vector<ServoCellResult>& results);

/// The geometry map's figure, with the engine's default overlap guard drawn on it.
std::string writeGeometryFiguresHeadless(const std::string& folder, const GeometryMapSpec& spec,
                                         const std::vector<GeometryLevel>& levels);

} // namespace grainlab
