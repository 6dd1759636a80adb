#include "stage_cyclic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

CyclicStrainSchedule CyclicStage::schedule(const RunContext& ctx) const {
    return CyclicStrainSchedule(0.0, path(ctx).mean, path(ctx).amplitude,
                                ctx.config.shear.axialStrainPerStep);
}

bool CyclicStage::stressControl(const RunContext& ctx) const {
    return path(ctx).control == LoadingPath::Control::Stress;
}

void CyclicStage::driveAxis(RunContext& ctx, std::int64_t n) const {
    const int direction = stressControl(ctx) ? direction_ : schedule(ctx).direction(n);
    const double rate =
        direction * ctx.config.shear.axialStrainPerStep / ctx.config.parameters.timeStep;
    ctx.sim->setAxisControl(0, {AxisMode::Strain, rate, 0.0, ctx.length1At0});
}

void CyclicStage::startTest(RunContext& ctx) {
    direction_ = stressControl(ctx) ? 1 : 0; // q rises first
    reversals_ = 0;
    driveAxis(ctx, 0);
    if (path(ctx).drainage == LoadingPath::Drainage::ConstantVolume) {
        AxisControl area{AxisMode::ConstantArea};
        area.referenceArea = ctx.sim->cellArea();
        ctx.sim->setAxisControl(1, area);
    } else {
        ctx.sim->setAxisControl(1, {AxisMode::Stress, 0.0, pressure()});
    }
    recordFirst(ctx);
    const SeriesTable& t = ctx.series[std::size_t(ctx.currentSeries)];
    p0_ = t.rows.back()[std::size_t(t.column("p"))];
}

std::int64_t CyclicStage::nextTestEvent(const RunContext& ctx) const {
    if (stressControl(ctx)) { // reversals are decided at records
        return std::numeric_limits<std::int64_t>::max();
    }
    const std::int64_t n = ctx.sim->stepCount() - ctx.stageStartStep;
    const CyclicStrainSchedule s = schedule(ctx);
    const std::int64_t reversal = ctx.stageStartStep + s.reversalStep(s.reversalsBy(n));
    const std::int64_t end = ctx.stageStartStep + s.reversalStep(2 * path(ctx).cycles);
    return std::min(reversal, end);
}

std::string CyclicStage::stopReason(const RunContext& ctx) const {
    const LoadingPath& p = path(ctx);
    const SeriesTable& t = ctx.series[std::size_t(ctx.currentSeries)];
    if (p.stopStrainAmplitude && std::fabs(ctx.eps1()) > *p.stopStrainAmplitude) {
        return fmt::format("{} stopped after {} reversals ({:g} cycles): |eps1| = {:.4g} exceeded "
                           "{:g} (test.stop_strain_amplitude): the sample no longer holds the "
                           "cycle of q",
                           test(), reversals_, 0.5 * double(reversals_), std::fabs(ctx.eps1()),
                           *p.stopStrainAmplitude);
    }
    if (!p.stopPressureFraction) {
        return "";
    }
    const double pNow = t.rows.back()[std::size_t(t.column("p"))];
    if (!(pNow < *p.stopPressureFraction * p0_)) {
        return "";
    }
    const std::int64_t n = ctx.sim->stepCount() - ctx.stageStartStep;
    std::int64_t reversals = reversals_;
    if (!stressControl(ctx)) {
        reversals = schedule(ctx).reversalsBy(n);
    }
    return fmt::format("{} stopped at step {} of the test ({} reversals, {:g} cycles): p' = {:.4g} "
                       "Pa fell below {:g} p0 = {:.4g} Pa (test.stop_pressure_fraction)",
                       test(), n, reversals, 0.5 * double(reversals), pNow, *p.stopPressureFraction,
                       *p.stopPressureFraction * p0_);
}

bool CyclicStage::handleStressControlled(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    if (now >= ctx.nextRecordStep) {
        record(ctx);
        if (const std::string reason = stopReason(ctx); !reason.empty()) {
            ctx.warn("test_end", reason);
            return true;
        }
        // q past its bound: the strain turns back. Reversal 2N, at the upper bound, ends the
        // N-th cycle (a cycle: from one upper reversal to the next).
        const LoadingPath& p = path(ctx);
        const SeriesTable& t = ctx.series[std::size_t(ctx.currentSeries)];
        const double q = t.rows.back()[std::size_t(t.column("q"))];
        const int next =
            cyclicStressDirection(q, direction_, p.mean - p.amplitude, p.mean + p.amplitude);
        if (next != direction_) {
            if (reversals_ == 2 * p.cycles) {
                return true;
            }
            direction_ = next;
            ++reversals_;
            driveAxis(ctx, 0);
        }
    }
    checkpointWhenDue(ctx);
    return false;
}

bool CyclicStage::handleEvents(RunContext& ctx) {
    if (stressControl(ctx)) {
        return handleStressControlled(ctx);
    }
    const std::int64_t now = ctx.sim->stepCount();
    const std::int64_t n = now - ctx.stageStartStep;
    const CyclicStrainSchedule s = schedule(ctx);
    const bool end = n >= s.reversalStep(2 * path(ctx).cycles);
    // Every peak of the waveform is a record too, however the record interval falls: the loops'
    // turning points are what a cyclic test is read by.
    const bool peak = s.isReversal(n);
    bool stopped = false;
    if (now >= ctx.nextRecordStep || end || peak) {
        record(ctx);
        if (const std::string reason = stopReason(ctx); !reason.empty()) {
            ctx.warn("test_end", reason);
            stopped = true;
        }
    }
    if (end || stopped) {
        return true;
    }
    if (peak) {
        driveAxis(ctx, n); // the strain turns back
    }
    checkpointWhenDue(ctx);
    return false;
}

void CyclicStage::saveTest(RunnerState& state, const RunContext& ctx) const {
    (void)ctx;
    state.cyclicDirection = direction_;
    state.cyclicReversals = reversals_;
}

void CyclicStage::restoreTest(const RunnerState& state, const RunContext& ctx,
                              const SimulationState& resumed, std::optional<SimulationState> kept) {
    (void)resumed;
    (void)kept;
    direction_ = state.cyclicDirection;
    reversals_ = state.cyclicReversals;
    // p0: the test's first record, the first row of this stage's kind in its series.
    const SeriesTable& t = ctx.series.at(std::size_t(ctx.currentSeries));
    const std::string kind = stageKindName(StageKind::Cyclic);
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        if (k < t.stageKinds.size() && t.stageKinds[k] == kind) {
            p0_ = t.rows[k][std::size_t(t.column("p"))];
            return;
        }
    }
    throw std::runtime_error(fmt::format(
        "resume: the series {} holds no record of its cyclic test, whose first gives p0", test()));
}

StageShare CyclicStage::share(const ExperimentConfig& config) const {
    const LoadingPath& p = config.tests[std::size_t(testIndex())];
    if (p.control == LoadingPath::Control::Stress) {
        // Its length is the sample's to decide: a guess of 0.2 % of strain per half cycle, and
        // the estimate creeps on beyond it.
        return {double(2 * p.cycles * strideOf(config, 0.002)), true};
    }
    const CyclicStrainSchedule s(0.0, p.mean, p.amplitude, config.shear.axialStrainPerStep);
    return {double(s.reversalStep(2 * p.cycles)), false};
}

} // namespace grainlab
