#include "grainlab/stability_scene.h"

#include <cmath>
#include <numbers>

#include "grainlab/assembly.h"
#include "grainlab/random.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"
#include "grainlab/time_step.h"

namespace grainlab {

namespace {

std::vector<double> widthsOf(const StabilityMapSpec& spec) {
    if (spec.sizeClasses == 1 || spec.largestWidth == spec.smallestWidth) {
        return {spec.smallestWidth};
    }
    return evenlySpacedWidths(spec.smallestWidth, spec.largestWidth, spec.sizeClasses);
}

/// Random directions at speed `speed`, then the mean momentum removed (the cell does not drift).
void gasVelocities(SimulationState& s, double speed, std::uint64_t seed) {
    Random random(seed ^ 0x5eedULL);
    auto& g = s.grains;
    double p1 = 0, p2 = 0, mass = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
        g.v1[i] = speed * std::cos(angle);
        g.v2[i] = speed * std::sin(angle);
        const double m = s.shapes[g.shape[i]].area;
        p1 += m * g.v1[i];
        p2 += m * g.v2[i];
        mass += m;
    }
    for (std::size_t i = 0; i < g.size(); ++i) {
        g.v1[i] -= p1 / mass;
        g.v2[i] -= p2 / mass;
    }
}

} // namespace

StabilityPacking stabilityPacking(const StabilityMapSpec& spec, const StabilityCell& cell) {
    StabilityPacking out;
    if (cell.packing.kind == PackingKind::Gas) {
        AssemblySpec a;
        a.grainCount = spec.grains;
        a.widths = widthsOf(spec);
        a.aspectRatio = cell.aspectRatio;
        a.gap = spec.gasGap;
        a.seed = spec.seed;
        out.state = generateGridAssembly(a, SimulationParameters{});
        gasVelocities(out.state, spec.gasSpeed, spec.seed);
        return out;
    }
    scenes::CompactedSceneSpec c;
    c.grains = spec.grains;
    c.aspectRatio = cell.aspectRatio;
    c.widths = widthsOf(spec);
    c.seed = spec.seed;
    c.pressure = cell.packing.pressure;
    c.friction = 0.0;
    c.maxStrainRate = spec.compactionRate;
    scenes::CompactedScene scene = scenes::compactScene(c);
    scene.simulation.clearVelocities();
    out.state = scene.simulation.state();
    out.calm = scene.equilibrium;
    out.steps = scene.steps;
    return out;
}

SimulationState stabilityProbeState(const StabilityMapSpec& spec, const StabilityCell& cell,
                                    const StabilityPacking& packing,
                                    const DampingParameters& damping) {
    SimulationState s = packing.state;
    SimulationParameters& p = s.parameters;
    p.tangentialStiffness = cell.stiffnessRatio * p.normalStiffness;
    p.friction = spec.friction;
    p.damping = damping;
    p.threads = 1;
    p.timeStep = 0.5 * criticalTimeStep(s.shapes, p).estimate;
    s.axes = {AxisControl{}, AxisControl{}}; // a fixed cell
    s.servoIntegral = {0.0, 0.0};
    s.velocityGradient = {};
    if (cell.packing.kind != PackingKind::Shear) {
        return s;
    }
    const double length = s.cell[0], step = p.timeStep;
    s.axes[0] = AxisControl{AxisMode::Strain, spec.shearStrainRate, 0.0, length};
    s.axes[1] = AxisControl{AxisMode::Stress, 0.0, cell.packing.pressure, 0.0};
    Simulation sim(std::move(s));
    const auto steps = std::int64_t(std::ceil(spec.shearPreStrain / (spec.shearStrainRate * step)));
    sim.advance(steps);
    return sim.state();
}

} // namespace grainlab
