#include "stage_probes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/path_measures.h"

namespace grainlab {

std::int64_t ProbesStage::probeSteps(const ExperimentConfig& config, const LoadingPath& path) {
    return std::max<std::int64_t>(1,
                                  std::llround(path.increment / config.shear.axialStrainPerStep));
}

void ProbesStage::start(RunContext& ctx) {
    const LoadingPath& path = ctx.config.tests[std::size_t(testIndex())];
    if (path.start != LoadingPath::Start::End) {
        // At a strain or the peak of the test before: the state it handed over.
        if (!ctx.probeStart) {
            throw std::runtime_error(
                fmt::format("{}: the test before the probes handed over no start state", test()));
        }
        SimulationState state = std::move(*ctx.probeStart);
        ctx.probeStart.reset();
        ctx.probeStartKeptIn.clear();
        state.step = ctx.sim->stepCount(); // the step counter goes on
        state.parameters.threads = threadsFor(ctx.config);
        ctx.sim = std::make_unique<Simulation>(std::move(state));
    }
    // A series of its own, also when it follows another test with no re-equilibration between.
    ctx.currentSeries = ctx.seriesIndex(test());
    ctx.thetaAtTestStart =
        std::make_shared<const std::vector<double>>(ctx.sim->stateRef().grains.theta);
    ctx.stageStartStep = ctx.sim->stepCount();
    ctx.setStrainReference();
    forgetInitialVoids();
    base_ = ctx.sim->state();
    ctx.recordNow(); // the start
    probe_ = -1;     // first the zero probe: the drift of the start state over a probe's steps
    beginProbe(ctx);
}

void ProbesStage::beginProbe(RunContext& ctx) {
    const ExperimentConfig& config = ctx.config;
    const LoadingPath& path = config.tests[std::size_t(testIndex())];
    SimulationState state = base_;
    state.step = ctx.sim->stepCount();
    state.parameters.threads = threadsFor(config);
    ctx.sim = std::make_unique<Simulation>(std::move(state));
    ctx.setStrainReference();
    probeStart_ = ctx.sim->stepCount();
    const std::array<double, 2> u =
        probe_ < 0 ? std::array<double, 2>{0.0, 0.0}
                   : probeDirections(std::size_t(path.probeCount))[std::size_t(probe_)];
    const double perStep = path.increment / double(probeSteps(config, path));
    const double dt = config.parameters.timeStep;
    ctx.sim->setAxisControl(0, {AxisMode::Strain, u[0] * perStep / dt, 0.0, ctx.length1At0});
    ctx.sim->setAxisControl(1, {AxisMode::Strain, u[1] * perStep / dt, 0.0, ctx.length2At0});
    ctx.checkpoint(ctx.checkpointLabel());
}

std::int64_t ProbesStage::stepsToNextEvent(const RunContext& ctx) const {
    const LoadingPath& path = ctx.config.tests[std::size_t(testIndex())];
    return std::max<std::int64_t>(1, probeStart_ + probeSteps(ctx.config, path) -
                                         ctx.sim->stepCount());
}

bool ProbesStage::handleEvents(RunContext& ctx) {
    const LoadingPath& path = ctx.config.tests[std::size_t(testIndex())];
    if (ctx.sim->stepCount() < probeStart_ + probeSteps(ctx.config, path)) {
        return false;
    }
    ctx.recordNow(); // the response of this probe
    ++probe_;
    if (probe_ >= path.probeCount) {
        return true;
    }
    beginProbe(ctx);
    return false;
}

void ProbesStage::addToCheckpoint(CheckpointData& data) {
    if (keptIn_.empty()) {
        data.runningPeak = &base_; // the first checkpoint of the stage keeps the start state
        keptIn_ = data.name;
    }
}

void ProbesStage::saveTest(RunnerState& state, const RunContext& ctx) const {
    (void)ctx;
    state.probe = probe_;
    state.probeStartStep = probeStart_;
    if (!keptIn_.empty()) {
        state.peak = RunningPeakRecord{0.0, base_.step, 0.0, keptIn_};
    }
}

void ProbesStage::restoreTest(const RunnerState& state, const RunContext& ctx,
                              const SimulationState& resumed, std::optional<SimulationState> kept) {
    probe_ = state.probe;
    probeStart_ = state.probeStartStep;
    if (!state.peak || !kept) {
        throw std::runtime_error(fmt::format(
            "resume: the probes of {} need their start state, kept beside checkpoint {}; the "
            "resume point does not hold it",
            test(), state.peak ? state.peak->keptIn : std::string("(none named)")));
    }
    (void)resumed;
    keptIn_ = state.peak->keptIn;
    base_ = std::move(*kept);
    base_.parameters.threads = threadsFor(ctx.config);
}

StageShare ProbesStage::share(const ExperimentConfig& config) const {
    const LoadingPath& path = config.tests[std::size_t(testIndex())];
    return {double((path.probeCount + 1) * probeSteps(config, path)), false};
}

} // namespace grainlab
