#include "stage_equilibration.h"

#include <cmath>

#include <fmt/format.h>

namespace grainlab {

std::string testName(double pressure) {
    const double kpa = pressure / 1000.0;
    if (kpa == std::round(kpa)) {
        return fmt::format("p{:03d}kPa", static_cast<int>(kpa));
    }
    return fmt::format("p{:g}kPa", kpa);
}

void EquilibrationStage::start(RunContext& ctx) {
    SimulationState state = ctx.samples.at(pressure());
    state.parameters.friction = ctx.config.shear.friction;
    state.parameters.servo.maxStrainRate = ctx.config.shear.maxStrainRate;
    state.parameters.threads = threadsFor(ctx.config);
    ctx.sim = std::make_unique<Simulation>(std::move(state));
    startWaiting(ctx);
    ctx.currentSeries = ctx.seriesIndex(test());
    ctx.setStrainReference();
    ctx.thetaAtTestStart =
        std::make_shared<const std::vector<double>>(ctx.sim->stateRef().grains.theta);
    ctx.checkpoint(ctx.checkpointLabel());
}

StageShare EquilibrationStage::share(const ExperimentConfig& config) const {
    const EquilibriumCriterion& eq = config.shear.equilibration;
    return settlingShare(2.0 * double(eq.calmChecks) * double(eq.checkInterval), eq);
}

} // namespace grainlab
