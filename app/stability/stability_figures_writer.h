#pragma once
// The stability map's heat maps for the headless `grainlab stability` (GUI builds only): painted
// with the widgets' heat map into the map folder's figures/, under Qt's offscreen platform when
// no Qt application runs yet. Main thread.

#include <string>
#include <vector>

#include "grainlab/stability_map.h"

namespace grainlab {

/// Writes figures/ into `folder`; returns "" or what went wrong.
std::string writeStabilityFiguresHeadless(const std::string& folder, const StabilityMapSpec& spec,
                                          const std::vector<StabilityCellResult>& results);

} // namespace grainlab
