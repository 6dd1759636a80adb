#include "stage_cyclic.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

CyclicStrainSchedule CyclicStage::schedule(const RunContext& ctx) const {
    return CyclicStrainSchedule(0.0, path(ctx).mean, path(ctx).amplitude,
                                ctx.config.shear.axialStrainPerStep);
}

void CyclicStage::driveAxis(RunContext& ctx, std::int64_t n) const {
    const double rate =
        schedule(ctx).direction(n) * ctx.config.shear.axialStrainPerStep /
        ctx.config.parameters.timeStep;
    ctx.sim->setAxisControl(0, {AxisMode::Strain, rate, 0.0, ctx.length1At0});
}

void CyclicStage::start(RunContext& ctx) {
    const ExperimentConfig& config = ctx.config;
    ctx.stageStartStep = ctx.sim->stepCount();
    ctx.setStrainReference();
    forgetInitialVoids();
    driveAxis(ctx, 0);
    if (path(ctx).drainage == LoadingPath::Drainage::ConstantVolume) {
        AxisControl area{AxisMode::ConstantArea};
        area.referenceArea = ctx.sim->cellArea();
        ctx.sim->setAxisControl(1, area);
    } else {
        ctx.sim->setAxisControl(1, {AxisMode::Stress, 0.0, pressure()});
    }
    ctx.nextRecordStep = ctx.stageStartStep;
    ctx.nextSnapshotStep = ctx.stageStartStep + ctx.strideOf(config.record.snapshotStrainInterval);
    ctx.recordNow(); // eps1 = 0: N_vi and p0
    const SeriesTable& t = ctx.series[std::size_t(ctx.currentSeries)];
    p0_ = t.rows.back()[std::size_t(t.column("p"))];
    ctx.nextRecordStep = ctx.stageStartStep + ctx.strideOf(config.record.strainInterval);
    ctx.checkpoint(ctx.checkpointLabel());
}

std::int64_t CyclicStage::stepsToNextEvent(const RunContext& ctx) const {
    const std::int64_t now = ctx.sim->stepCount();
    const std::int64_t n = now - ctx.stageStartStep;
    const CyclicStrainSchedule s = schedule(ctx);
    // The next reversal after step n (reversal k at first_ + k half_).
    std::int64_t k = n < s.firstLegSteps()
                         ? 0
                         : (n - s.firstLegSteps()) / s.halfCycleSteps() + 1;
    const std::int64_t reversal = ctx.stageStartStep + s.reversalStep(k);
    const std::int64_t end = ctx.stageStartStep + s.reversalStep(2 * path(ctx).cycles);
    return std::max<std::int64_t>(
        1, std::min({ctx.nextRecordStep, ctx.nextSnapshotStep, reversal, end}) - now);
}

std::string CyclicStage::stopReason(const RunContext& ctx) const {
    const LoadingPath& p = path(ctx);
    if (!p.stopPressureFraction) {
        return "";
    }
    const SeriesTable& t = ctx.series[std::size_t(ctx.currentSeries)];
    const double pNow = t.rows.back()[std::size_t(t.column("p"))];
    if (!(pNow < *p.stopPressureFraction * p0_)) {
        return "";
    }
    const std::int64_t n = ctx.sim->stepCount() - ctx.stageStartStep;
    const CyclicStrainSchedule s = schedule(ctx);
    const std::int64_t reversals = n < s.firstLegSteps()
                                       ? 0
                                       : (n - s.firstLegSteps()) / s.halfCycleSteps() + 1;
    return fmt::format("{} stopped at step {} of the test ({} reversals, {:g} cycles): p' = {:.4g} "
                       "Pa fell below {:g} p0 = {:.4g} Pa (test.stop_pressure_fraction)",
                       test(), n, reversals, 0.5 * double(reversals), pNow,
                       *p.stopPressureFraction, *p.stopPressureFraction * p0_);
}

bool CyclicStage::handleEvents(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    const std::int64_t n = now - ctx.stageStartStep;
    const CyclicStrainSchedule s = schedule(ctx);
    const bool end = n >= s.reversalStep(2 * path(ctx).cycles);
    // Every peak of the waveform is a record too, however the record interval falls: the loops'
    // turning points are what a cyclic test is read by.
    const bool peak = n >= s.firstLegSteps() && (n - s.firstLegSteps()) % s.halfCycleSteps() == 0;
    bool stopped = false;
    if (now >= ctx.nextRecordStep || end || peak) {
        ctx.recordNow();
        ctx.nextRecordStep = now + ctx.strideOf(ctx.config.record.strainInterval);
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
    if (now >= ctx.nextSnapshotStep) {
        ctx.checkpoint(ctx.checkpointLabel());
        ctx.nextSnapshotStep = now + ctx.strideOf(ctx.config.record.snapshotStrainInterval);
    }
    return false;
}

void CyclicStage::save(RunnerState& state, const RunContext& ctx) const {
    (void)ctx;
    saveInitialVoids(state);
    state.peak.reset();
}

void CyclicStage::restore(const RunnerState& state, const RunContext& ctx,
                          const SimulationState& resumed, std::optional<SimulationState> peak) {
    (void)resumed;
    (void)peak;
    restoreInitialVoids(state);
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
    const CyclicStrainSchedule s(0.0, p.mean, p.amplitude, config.shear.axialStrainPerStep);
    return {double(s.reversalStep(2 * p.cycles)), false};
}

} // namespace grainlab
