#include "grainlab/scenes/compacted_scene.h"

#include <algorithm>
#include <utility>

#include "grainlab/assembly.h"

namespace grainlab::scenes {

namespace {

Simulation generated(const CompactedSceneSpec& spec) {
    AssemblySpec assembly;
    assembly.grainCount = spec.grains;
    assembly.widths = spec.widths.empty() ? evenlySpacedWidths(1e-3, 2e-3, 11) : spec.widths;
    assembly.aspectRatio = spec.aspectRatio;
    assembly.seed = spec.seed;
    SimulationParameters p;
    p.friction = spec.friction;
    p.servo.maxStrainRate = spec.maxStrainRate;
    p.threads = spec.threads;
    return Simulation(generateGridAssembly(assembly, p));
}

} // namespace

CompactedScene compactScene(const CompactedSceneSpec& spec, const CompactionCallback& progress) {
    CompactedScene out{generated(spec), false, 0, {}};
    Simulation& sim = out.simulation;
    out.initialTheta = sim.stateRef().grains.theta;
    const AxisControl servo{AxisMode::Stress, 0.0, spec.pressure};
    sim.setAxisControl(0, servo);
    sim.setAxisControl(1, servo);
    const EquilibriumCriterion& c = spec.criterion;
    int calm = 0;
    while (out.steps < c.maxSteps && calm < c.calmChecks) {
        const std::int64_t chunk = std::min(c.checkInterval, c.maxSteps - out.steps);
        sim.advance(chunk);
        out.steps += chunk;
        const EquilibriumCheck check = checkEquilibrium(sim, spec.pressure, c);
        calm = calmChecksAfter(calm, check);
        if (progress) {
            progress({out.steps, c.maxSteps, check, calm});
        }
    }
    out.equilibrium = calm >= c.calmChecks;
    return out;
}

SimulationState compactedState(const CompactedSceneSpec& spec, const CompactionCallback& progress) {
    CompactedScene scene = compactScene(spec, progress);
    scene.simulation.clearVelocities();
    return scene.simulation.state();
}

} // namespace grainlab::scenes
