#include "stability/map_point_command.h"

#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "grainlab/servo_cell.h"
#include "grainlab/stability_cell.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// Measures the map point `cellId` of `cells` and writes its result (`toJson`) to `result`,
/// unless it is there already; `summary` is what the line printed after says of it. `preset`
/// is named when no cell has that id.
template <class Cell, class Measure, class ToJson, class Summary>
int measureCellOnce(const fs::path& result, const std::vector<Cell>& cells,
                    const std::string& cellId, bool quiet, const std::string& preset,
                    Measure measure, ToJson toJson, Summary summary) {
    if (fs::exists(result)) {
        if (!quiet) {
            fmt::print("grainlab stability cell {}: done already ({})\n", cellId, result.string());
        }
        return 0;
    }
    for (const Cell& cell : cells) {
        if (cell.id != cellId) {
            continue;
        }
        const auto r = measure(cell);
        fs::create_directories(result.parent_path());
        writeFileAtomically(result.string(), toJson(r));
        if (!quiet) {
            fmt::print("grainlab stability cell {}: {}\n", cellId, summary(r));
        }
        return 0;
    }
    throw std::runtime_error(fmt::format("stability cell {}: no such cell in {}", cellId, preset));
}

} // namespace

int runStabilityCellCommand(const std::string& folder, const std::string& cellId, bool quiet) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const fs::path preset = dir / "stability.json";
    if (!fs::exists(preset)) {
        throw std::runtime_error(fmt::format(
            "stability cell {}: no stability.json: not a stability map folder", dir.string()));
    }
    const StabilityMapSpec spec = readStabilityPreset(preset.string());
    return measureCellOnce(
        dir / "cells" / (cellId + ".json"), stabilityCells(spec), cellId, quiet, preset.string(),
        [&](const StabilityCell& cell) { return measureStabilityCell(spec, cell); }, cellResultJson,
        [](const StabilityCellResult& r) {
            return fmt::format("limit {:.4g} sqrt(m_min/k_n) ({}), estimate {:.4g}, {} probes, "
                               "{:.1f} s",
                               r.limit.limit, blowUpName(r.limit.detector), r.estimate,
                               r.limit.probes, r.seconds);
        });
}

int runServoCellCommand(const std::string& folder, const ServoMapSpec& spec,
                        const std::string& cellId, bool quiet) {
    return measureCellOnce(
        fs::path(folder) / "cells" / (cellId + ".json"), servoCells(spec), cellId, quiet,
        (fs::path(folder) / "stability.json").string(),
        [&](const ServoCell& cell) { return measureServoCell(spec, cell); }, servoCellResultJson,
        [](const ServoCellResult& r) {
            return fmt::format("largest stable gain {:.4g} ({} above it), {} runs, {:.1f} s",
                               r.limit.limit, servoResponseName(r.aboveLimit), r.runs.size(),
                               r.seconds);
        });
}

} // namespace grainlab
