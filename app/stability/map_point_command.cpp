#include "stability/map_point_command.h"

#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "grainlab/servo_cell.h"
#include "grainlab/stability_cell.h"

namespace grainlab {

namespace fs = std::filesystem;

int runStabilityCellCommand(const std::string& folder, const std::string& cellId, bool quiet) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const fs::path preset = dir / "stability.json";
    if (!fs::exists(preset)) {
        throw std::runtime_error(fmt::format(
            "stability cell {}: no stability.json: not a stability map folder", dir.string()));
    }
    const StabilityMapSpec spec = readStabilityPreset(preset.string());
    const fs::path result = dir / "cells" / (cellId + ".json");
    if (fs::exists(result)) {
        if (!quiet) {
            fmt::print("grainlab stability cell {}: done already ({})\n", cellId, result.string());
        }
        return 0;
    }
    for (const StabilityCell& cell : stabilityCells(spec)) {
        if (cell.id != cellId) {
            continue;
        }
        const StabilityCellResult r = measureStabilityCell(spec, cell);
        fs::create_directories(result.parent_path());
        writeFileAtomically(result.string(), cellResultJson(r));
        if (!quiet) {
            fmt::print("grainlab stability cell {}: limit {:.4g} sqrt(m_min/k_n) ({}), estimate "
                       "{:.4g}, {} probes, {:.1f} s\n",
                       cellId, r.limit.limit, blowUpName(r.limit.detector), r.estimate,
                       r.limit.probes, r.seconds);
        }
        return 0;
    }
    throw std::runtime_error(
        fmt::format("stability cell {}: no such cell in {}", cellId, preset.string()));
}

int runServoCellCommand(const std::string& folder, const ServoMapSpec& spec,
                        const std::string& cellId, bool quiet) {
    const fs::path result = fs::path(folder) / "cells" / (cellId + ".json");
    if (fs::exists(result)) {
        if (!quiet) {
            fmt::print("grainlab stability cell {}: done already ({})\n", cellId, result.string());
        }
        return 0;
    }
    for (const ServoCell& cell : servoCells(spec)) {
        if (cell.id != cellId) {
            continue;
        }
        const ServoCellResult r = measureServoCell(spec, cell);
        fs::create_directories(result.parent_path());
        writeFileAtomically(result.string(), servoCellResultJson(r));
        if (!quiet) {
            fmt::print("grainlab stability cell {}: largest stable gain {:.4g} ({} above it), "
                       "{} runs, {:.1f} s\n",
                       cellId, r.limit.limit, servoResponseName(r.aboveLimit), r.runs.size(),
                       r.seconds);
        }
        return 0;
    }
    throw std::runtime_error(fmt::format("stability cell {}: no such cell in {}", cellId,
                                         (fs::path(folder) / "stability.json").string()));
}

} // namespace grainlab
