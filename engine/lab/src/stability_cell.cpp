#include "grainlab/stability_cell.h"

#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/stability_bisection.h"
#include "grainlab/stability_probe.h"
#include "grainlab/stability_scene.h"
#include "grainlab/time_step.h"
#include "map_preset.h"

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
    return map_preset::timedCell<StabilityCellResult>(cell, [&](StabilityCellResult& out) {
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
            [&](double step) { return runStabilityProbe(base, step * unit, settings); },
            spec.lowBound, spec.highBound, spec.precision);

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
    });
}

} // namespace grainlab
