#include "bench.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "grainlab/assembly.h"
#include "grainlab/simulation.h"
#include "progress_bar.h"

namespace grainlab {
namespace {

constexpr double kConfiningStress = 1e5; // [Pa]

/// Loose grid -> frictionless isotropic compaction to 100 kPa, then velocities cleared.
SimulationState prepareDenseAssembly(const BenchOptions& o, double aspectRatio) {
    AssemblySpec spec;
    spec.grainCount = o.grains;
    spec.widths = evenlySpacedWidths(1e-3, 2e-3, 11);
    spec.aspectRatio = aspectRatio;
    spec.seed = o.seed;
    SimulationParameters p;
    p.friction = 0.0;
    p.servo.maxStrainRate = 20.0;
    p.threads = 2;
    Simulation sim(generateGridAssembly(spec, p));
    const AxisControl servo{AxisMode::Stress, 0.0, kConfiningStress};
    sim.setAxisControl(0, servo);
    sim.setAxisControl(1, servo);
    ProgressBar bar(fmt::format("preparing {} {}s at 100 kPa", o.grains,
                                aspectRatio < 1 ? "oval" : "disk"));
    const std::int64_t maxSteps = 400000;
    int calm = 0;
    for (std::int64_t k = 0; k < maxSteps && calm < 20; k += 500) {
        sim.advance(500);
        const Stress s = sim.stress();
        const double error = std::max(std::fabs(s.s11 - kConfiningStress),
                                      std::fabs(s.s22 - kConfiningStress)) / kConfiningStress;
        const Energies e = sim.energies();
        calm = (error < 0.01 && e.kinetic < 1e-4 * e.elastic) ? calm + 1 : 0;
        bar.update(double(k) / maxSteps, fmt::format("p error {:.1f} %", 100 * error));
    }
    bar.finish();
    sim.clearVelocities();
    return sim.state();
}

std::vector<int> parseThreads(const std::string& text) {
    std::vector<int> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        out.push_back(std::stoi(item));
    }
    return out;
}

} // namespace

int runBench(const BenchOptions& o) {
    std::vector<std::pair<std::string, double>> shapes;
    if (o.shape == "disk" || o.shape == "both") {
        shapes.emplace_back("disk", 1.0);
    }
    if (o.shape == "oval" || o.shape == "both") {
        shapes.emplace_back("oval", 0.6);
    }
    if (shapes.empty()) {
        fmt::print(stderr, "bench: --shape {}: allowed values are oval, disk, both\n", o.shape);
        return 2;
    }
    fmt::print("{:<6} {:>7} {:>8} {:>8} {:>16} {:>14} {:>9}\n", "shape", "grains", "threads",
               "steps", "grain-steps/s", "contacts/grain", "rebuilds");
    for (const auto& [name, aspect] : shapes) {
        const SimulationState dense = prepareDenseAssembly(o, aspect);
        for (int threads : parseThreads(o.threads)) {
            SimulationState state = dense;
            state.parameters.friction = 0.5;
            state.parameters.threads = threads;
            Simulation sim(std::move(state));
            sim.setAxisControl(0, AxisControl{AxisMode::Strain, 0.2, 0.0});
            sim.setAxisControl(1, AxisControl{AxisMode::Stress, 0.0, kConfiningStress});
            const auto start = std::chrono::steady_clock::now();
            sim.advance(o.steps);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            fmt::print("{:<6} {:>7} {:>8} {:>8} {:>16.4g} {:>14.3f} {:>9}\n", name,
                       sim.grainCount(), threads, o.steps,
                       double(sim.grainCount()) * double(o.steps) / seconds,
                       2.0 * double(sim.contactCount()) / double(sim.grainCount()),
                       sim.neighbourRebuilds());
            std::fflush(stdout);
        }
    }
    return 0;
}

} // namespace grainlab
