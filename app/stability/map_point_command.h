#pragma once
// `grainlab stability cell DIR --cell ID`: measures one point of a map folder (the measurement
// itself is grainlab/stability_cell.h, grainlab/servo_cell.h) and writes DIR/cells/ID.json
// atomically, so that a pool or a job list can run the points of one map side by side.

#include <string>

#include "grainlab/servo_map.h"

namespace grainlab {

/// Measures the point `cellId` of the stability map in `folder` (its stability.json) unless
/// folder/cells/ID.json exists already; 0 on success.
int runStabilityCellCommand(const std::string& folder, const std::string& cellId, bool quiet);

/// Measures the point `cellId` of the servo map in `folder` unless its result exists; 0 on
/// success.
int runServoCellCommand(const std::string& folder, const ServoMapSpec& spec,
                        const std::string& cellId, bool quiet);

} // namespace grainlab
