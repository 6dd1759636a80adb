#include "stage_equilibrium.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

void EquilibriumStage::startWaiting(RunContext& ctx) {
    calm_ = 0;
    calmHistory_ = {};
    ctx.stageStartStep = ctx.sim->stepCount();
    const AxisControl servo{AxisMode::Stress, 0.0, pressure()};
    ctx.sim->setAxisControl(0, servo);
    ctx.sim->setAxisControl(1, servo);
    ctx.nextRecordStep = ctx.stageStartStep + criterion(ctx.config).checkInterval;
    ctx.nextSnapshotStep = ctx.sim->stepCount() + ctx.config.record.snapshotStepInterval;
}

std::int64_t EquilibriumStage::stepsToNextEvent(const RunContext& ctx) const {
    const std::int64_t now = ctx.sim->stepCount();
    const std::int64_t check = criterion(ctx.config).checkInterval;
    const std::int64_t nextCheck =
        ctx.stageStartStep + ((now - ctx.stageStartStep) / check + 1) * check;
    std::int64_t next = std::min(nextCheck, ctx.nextSnapshotStep);
    if (ctx.nextRecordStep > now) {
        next = std::min(next, ctx.nextRecordStep);
    }
    return std::max<std::int64_t>(1, next - now);
}

bool EquilibriumStage::handleEvents(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    if (now >= ctx.nextRecordStep) {
        ctx.recordNow();
        ctx.nextRecordStep = now + ctx.config.record.stepInterval;
    }
    if (now >= ctx.nextSnapshotStep) {
        ctx.checkpoint(ctx.checkpointLabel());
        ctx.nextSnapshotStep = now + ctx.config.record.snapshotStepInterval;
    }
    const EquilibriumCriterion& c = criterion(ctx.config);
    if ((now - ctx.stageStartStep) % c.checkInterval != 0) {
        return false;
    }
    const EquilibriumCheck check = checkEquilibrium(*ctx.sim, pressure(), c);
    const double error = check.stressError, unbalanced = check.unbalancedForce;
    calm_ = calmChecksAfter(calm_, check);
    if (calm_ >= c.calmChecks) {
        return true;
    }
    calmHistory_.note(now - ctx.stageStartStep, c.maxSteps, unbalanced);
    if (now - ctx.stageStartStep >= c.maxSteps) {
        throw std::runtime_error(fmt::format(
            "stage '{}' did not reach equilibrium within {} steps (stress error {:.3g} % "
            "against the tolerance {:.3g} %, unbalanced-force index {:.3g} % against "
            "{:.3g} %); {}",
            ctx.stageName(), c.maxSteps, 100 * error, 100 * c.stressTolerance, unbalanced,
            c.unbalancedForceMax, whyNotCalm(calmHistory_, error, c, ctx.sim->stateRef())));
    }
    return false;
}

void EquilibriumStage::save(RunnerState& state, const RunContext& ctx) const {
    (void)ctx;
    state.calm = calm_;
    state.unbalancedLow = calmHistory_.lowest;
}

void EquilibriumStage::restore(const RunnerState& state, const RunContext& ctx,
                               const SimulationState& resumed,
                               std::optional<SimulationState> runningPeak) {
    (void)ctx;
    (void)resumed;
    (void)runningPeak;
    calm_ = state.calm;
    calmHistory_.lowest = state.unbalancedLow;
}

StageShare EquilibriumStage::settlingShare(double expected,
                                           const EquilibriumCriterion& criterion) const {
    // Whole numbers of steps, so that sums of shares are exact.
    const double capped =
        std::round(std::clamp(expected, 1.0, std::max(1.0, double(criterion.maxSteps))));
    return {capped, true};
}

} // namespace grainlab
