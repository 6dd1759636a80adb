#include "stability/stability_cell.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "cli/atomic_file.h"
#include "grainlab/stability_bisection.h"
#include "grainlab/stability_probe.h"
#include "grainlab/time_step.h"
#include "stability/stability_scene.h"

namespace grainlab {

namespace fs = std::filesystem;

ProbeSettings stabilityProbeSettings(const StabilityMapSpec& spec, const StabilityCell& cell) {
    ProbeSettings s;
    s.steps = spec.steps;
    s.thresholds.unbalancedFloor =
        cell.packing.kind != PackingKind::Gas && cell.damping.kind != DampingKind::None;
    return s;
}

StabilityCellResult measureStabilityCell(const StabilityMapSpec& spec, const StabilityCell& cell) {
    const auto start = std::chrono::steady_clock::now();
    StabilityCellResult out;
    out.cell = cell;
    const StabilityPacking packing = stabilityPacking(spec, cell);
    out.compactionCalm = packing.calm;
    const SimulationState base = stabilityProbeState(spec, cell, packing, cell.damping);
    const double unit = probeTimeUnit(base);
    out.timeUnit = unit;
    const TimeStepLimit estimate = criticalTimeStep(base.shapes, base.parameters);
    out.estimate = estimate.estimate / unit;
    out.estimateTranslational = estimate.translational / unit;
    out.estimateRotational = estimate.rotational / unit;
    const ProbeSettings settings = stabilityProbeSettings(spec, cell);
    out.limit = bisectStableStep(
        [&](double step) { return runStabilityProbe(base, step * unit, settings); }, spec.lowBound,
        spec.highBound, spec.precision);

    // Accuracy before stability: the energy balance with damping off, below the limit.
    StabilityCell undamped = cell;
    undamped.damping = {DampingKind::None, 0.0};
    const SimulationState free =
        cell.damping.kind == DampingKind::None
            ? base
            : stabilityProbeState(spec, undamped, packing, undamped.damping);
    const ProbeSettings freeSettings = stabilityProbeSettings(spec, undamped);
    for (double f : spec.accuracyFractions) {
        const double step = f * out.limit.limit;
        const ProbeResult r = runStabilityProbe(free, step * unit, freeSettings);
        out.accuracy.push_back({f, step, r.stable, r.maxResidual, r.finalResidual});
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

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

} // namespace grainlab
