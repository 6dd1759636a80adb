#include "grainlab/servo_cell.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/assembly.h"
#include "grainlab/equilibrium.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"
#include "map_preset.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// The equilibration at the shear friction: the experiment runner's rule, with a cap.
constexpr std::int64_t kMaxEquilibrationSteps = 400000;

} // namespace

ServoSample servoSample(const ServoMapSpec& spec, const ServoCell& cell) {
    scenes::CompactedSceneSpec c;
    c.grains = spec.grains;
    c.aspectRatio = cell.aspectRatio;
    c.widths = spec.sizeClasses == 1 || spec.largestWidth == spec.smallestWidth
                   ? std::vector<double>{spec.smallestWidth}
                   : evenlySpacedWidths(spec.smallestWidth, spec.largestWidth, spec.sizeClasses);
    c.seed = spec.seed;
    c.pressure = cell.pressure;
    c.friction = 0.0;
    c.maxStrainRate = spec.compactionRate;
    scenes::CompactedScene scene = scenes::compactScene(c);
    ServoSample out;
    out.calm = scene.equilibrium;
    scene.simulation.clearVelocities();
    SimulationState s = scene.simulation.state();
    // As the experiment runner's equilibration before shear: friction on, the shear's rate cap,
    // the default servo on both axes at the pressure, until the equilibrium rule holds.
    s.parameters.friction = spec.friction;
    s.parameters.timeStep = spec.timeStep;
    s.parameters.servo = ServoParameters{};
    s.parameters.servo.maxStrainRate = spec.maxStrainRate;
    s.parameters.threads = 1;
    s.servoIntegral = {0.0, 0.0};
    Simulation sim(std::move(s));
    const AxisControl servo{AxisMode::Stress, 0.0, cell.pressure, 0.0};
    sim.setAxisControl(0, servo);
    sim.setAxisControl(1, servo);
    const EquilibriumCriterion rule{0.01, 1.0, 100, 20, kMaxEquilibrationSteps};
    int calm = 0;
    for (std::int64_t steps = 0; steps < rule.maxSteps && calm < rule.calmChecks;
         steps += rule.checkInterval) {
        sim.advance(rule.checkInterval);
        calm = calmChecksAfter(calm, checkEquilibrium(sim, cell.pressure, rule));
    }
    out.calm = out.calm && calm >= rule.calmChecks;
    out.state = sim.state();
    return out;
}

double affineLateralStiffness(const SimulationState& state) {
    const Simulation sim(state);
    const ContactNetwork net = sim.contactNetwork();
    const double kn = state.parameters.normalStiffness;
    const double kt = state.parameters.friction > 0.0 ? state.parameters.tangentialStiffness : 0.0;
    double sum = 0;
    for (const ContactRecord& c : net.contacts) {
        const double n2 = c.normal2, t2 = c.normal1; // t = (-n2, n1)
        sum += c.branch2 * c.branch2 * (kn * n2 * n2 + kt * t2 * t2);
    }
    return sum / sim.cellArea();
}

ServoCellResult measureServoCell(const ServoMapSpec& spec, const ServoCell& cell) {
    return map_preset::timedCell<ServoCellResult>(cell, [&](ServoCellResult& out) {
        const ServoSample sample = servoSample(spec, cell);
        out.compactionCalm = sample.calm;
        out.stiffnessOverPressure = affineLateralStiffness(sample.state) / cell.pressure;
        const ServoShear shear{cell.pressure, spec.strainPerStep, spec.maxStrainRate,
                               servoRunSteps(spec, cell.interval)};
        std::map<double, ServoResponse> seen;
        const auto run = [&](double gain, bool grid) {
            const auto known = seen.find(gain);
            if (known != seen.end()) {
                return known->second;
            }
            const ServoProbeResult r = runServoProbe(
                sample.state, {gain, cell.interval, spec.integralGain}, shear, spec.thresholds);
            out.runs.push_back({gain, grid, r.response, r.stats});
            seen[gain] = r.response;
            return r.response;
        };
        std::size_t firstUnstable = spec.gains.size();
        for (std::size_t i = 0; i < spec.gains.size(); ++i) {
            if (servoUnstable(run(spec.gains[i], true)) && firstUnstable == spec.gains.size()) {
                firstUnstable = i;
            }
        }
        if (firstUnstable == spec.gains.size()) {
            // Stable over the whole grid: the limit lies above it.
            out.limit.low = out.limit.high = out.limit.limit = spec.gains.back();
            out.aboveLimit = seen[spec.gains.back()];
        } else if (firstUnstable == 0) {
            out.limit.low = out.limit.high = out.limit.limit = spec.gains.front();
            out.aboveLimit = seen[spec.gains.front()];
        } else {
            // The bisection of the time-step map, on the gain: its bounds are grid runs already
            // made, so only the gains between them are run.
            out.limit = bisectStableStep(
                [&](double gain) {
                    ProbeResult p;
                    p.stable = !servoUnstable(run(gain, false));
                    return p;
                },
                spec.gains[firstUnstable - 1], spec.gains[firstUnstable], spec.precision);
            out.aboveLimit = seen[out.limit.high];
        }
    });
}

} // namespace grainlab
