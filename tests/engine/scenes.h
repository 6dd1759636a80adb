#pragma once
// Small scenes for the engine tests, each built in a few lines.

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "grainlab/assembly.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"

namespace grainlab::test {

/// Parameters for closed-form tests: no damping, no friction unless set.
inline SimulationParameters bareParameters() {
    SimulationParameters p;
    p.damping.kind = DampingKind::None;
    p.friction = 0.0;
    return p;
}

/// A state with the given grains (one shape per grain) in an L1 x L2 rectangular cell.
struct GrainSpec {
    double x1, x2, theta, v1, v2, omega;
    double width, aspect;
};
inline SimulationState makeScene(const std::vector<GrainSpec>& grains, double l1, double l2,
                                 const SimulationParameters& p) {
    SimulationState s;
    s.parameters = p;
    s.cell = {l1, 0.0, 0.0, l2};
    s.grains.resize(grains.size());
    for (std::size_t i = 0; i < grains.size(); ++i) {
        const GrainSpec& g = grains[i];
        s.shapes.push_back(makeOval(g.width, g.aspect));
        s.grains.x1[i] = g.x1;
        s.grains.x2[i] = g.x2;
        s.grains.theta[i] = g.theta;
        s.grains.v1[i] = g.v1;
        s.grains.v2[i] = g.v2;
        s.grains.omega[i] = g.omega;
        s.grains.shape[i] = static_cast<std::int32_t>(i);
    }
    return s;
}

/// A small random loose assembly (grid, 1-2 mm, given aspect ratio).
inline SimulationState smallAssembly(int count, double aspect, std::uint64_t seed,
                                     const SimulationParameters& p, double gap = 0.02) {
    AssemblySpec spec;
    spec.gap = gap;
    spec.grainCount = count;
    spec.widths = evenlySpacedWidths(1e-3, 2e-3, 11);
    spec.aspectRatio = aspect;
    spec.seed = seed;
    return generateGridAssembly(spec, p);
}

/// `count` grains of aspect ratio `aspect` (5 classes over 1-2 mm) compacted isotropically to
/// 100 kPa, frictionless, by the shared scene: until the runner's equilibrium rule holds, or
/// `steps` steps.
inline Simulation compactedPacking(int count, double aspect, std::uint64_t seed,
                                   std::int64_t steps) {
    scenes::CompactedSceneSpec spec;
    spec.grains = count;
    spec.aspectRatio = aspect;
    spec.widths = evenlySpacedWidths(1e-3, 2e-3, 5);
    spec.seed = seed;
    spec.criterion.maxSteps = steps;
    return std::move(scenes::compactScene(spec).simulation);
}

/// A small frictional assembly squeezed (axial strain rate, lateral servo) until its grains
/// touch, so that contacts carry tangential history, velocities and spins are non-zero, and a
/// servo integral is running: the checkpoint and restart tests' state.
inline Simulation squeezedAssembly(int grains, std::uint64_t seed, std::int64_t steps) {
    AssemblySpec spec;
    spec.grainCount = grains;
    spec.widths = evenlySpacedWidths(1.0e-3, 2.0e-3, 3);
    spec.aspectRatio = 0.6;
    spec.gap = 0.02;
    spec.seed = seed;
    SimulationParameters p;
    p.friction = 0.5;
    p.threads = 1;
    p.servo.maxStrainRate = 100.0;
    SimulationState s = generateGridAssembly(spec, p);
    s.axes[0] = {AxisMode::Strain, 300.0, 0.0, 0.0};
    s.axes[1] = {AxisMode::Stress, 0.0, 2.0e4, 0.0};
    Simulation sim(std::move(s));
    sim.advance(steps);
    return sim;
}

/// The whole content of a file (binary).
inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace grainlab::test
