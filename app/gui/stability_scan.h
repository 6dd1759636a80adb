#pragma once
// What a stability map folder (`grainlab stability --out DIR`, docs/stability.md) holds so far,
// for the Stability view: whether it is a map at all (and if not, why), its preset
// (stability.json, read with the strict reader), which cells have finished and their results
// (cells/<id>.json, each read once with the engine's reader, parseCellResult()).
// scanStabilityFolder() is a plain function over the folder's files (no Qt); the view calls it on
// its worker thread and hands the immutable result to the GUI thread, so reading the folder
// never blocks the window.

#include <memory>
#include <string>
#include <vector>

#include "grainlab/stability_map.h"

namespace grainlab::ui {

/// A map folder as last read. Immutable once made; shared between the worker and GUI threads.
struct StabilityFolder {
    enum class Kind {
        New,     ///< missing or empty: `grainlab stability --out` may start a map there
        Map,     ///< holds a stability map (stability.json)
        Refused, ///< holds something else; `reason` says what
    };
    Kind kind = Kind::New;
    std::string reason;                       ///< Refused: why it is not a map folder
    std::string presetText;                   ///< Map: stability.json as read
    StabilityMapSpec spec;                    ///< Map: the map's preset
    std::vector<StabilityCell> cells;         ///< Map: every cell, in the map's order
    std::vector<int> resultOf;                ///< per cell: its index in `results`, or -1
    std::vector<StabilityCellResult> results; ///< the finished cells' results, in cell order
    std::vector<std::string> errors;          ///< cell files that exist but could not be read
    int finishedCount() const { return int(results.size()); }
};

/// Reads `folder`: whether it is a map, and the cells finished since `previous` (all of them
/// when it is null or held another preset); keeps the results `previous` already holds. Returns
/// `previous` itself when nothing changed.
std::shared_ptr<const StabilityFolder>
scanStabilityFolder(const std::string& folder,
                    const std::shared_ptr<const StabilityFolder>& previous);

} // namespace grainlab::ui
