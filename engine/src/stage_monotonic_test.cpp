#include "stage_monotonic_test.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/contact_network.h"
#include "grainlab/loading_rate.h"
#include "grainlab/void_cells.h"
#include "stage_equilibration.h"

namespace grainlab {

AxisControl MonotonicTestStage::lateralControl(const RunContext& ctx) const {
    switch (kind()) {
    case StageKind::ConstantVolume: {
        AxisControl c{AxisMode::ConstantArea};
        c.referenceArea = ctx.sim->cellArea();
        return c;
    }
    case StageKind::ConstantP:
    case StageKind::StressPath: {
        AxisControl c{AxisMode::StressPath};
        c.targetStress = pressure();
        c.pathSlope = kind() == StageKind::ConstantP ? -1.0 : ctx.config.tests[testIndex()].slope;
        c.pathOrigin = ctx.sim->stress().s11;
        return c;
    }
    default:
        return {AxisMode::Stress, 0.0, pressure()};
    }
}

double MonotonicTestStage::direction(const RunContext& ctx) const {
    return ctx.config.tests[std::size_t(testIndex())].extension ? -1.0 : 1.0;
}

const LoadingPath* MonotonicTestStage::probesAfter(const RunContext& ctx) const {
    const std::size_t next = std::size_t(testIndex()) + 1;
    if (next >= ctx.config.tests.size()) {
        return nullptr;
    }
    const LoadingPath& path = ctx.config.tests[next];
    return path.kind == LoadingPath::Kind::Probes && path.start != LoadingPath::Start::End
               ? &path
               : nullptr;
}

std::int64_t MonotonicTestStage::handOverStep(const RunContext& ctx) const {
    const LoadingPath* probes = probesAfter(ctx);
    return probes && probes->start == LoadingPath::Start::Strain
               ? ctx.stageStartStep + ctx.strideOf(probes->startStrain)
               : -1;
}

void MonotonicTestStage::startTest(RunContext& ctx) {
    const ExperimentConfig& config = ctx.config;
    ctx.probeStart.reset();
    ctx.probeStartKeptIn.clear();
    peak_ = RunningPeak{};
    const double dt = config.parameters.timeStep;
    ctx.sim->setAxisControl(0, {AxisMode::Strain,
                                direction(ctx) * config.shear.axialStrainPerStep / dt, 0.0,
                                ctx.length1At0});
    ctx.sim->setAxisControl(1, lateralControl(ctx));
    if (const auto text = inertialNumberWarning(config, pressure())) {
        ctx.warn("inertial_number", *text);
    }
    recordFirst(ctx);
    trackPeak(ctx);
}

std::int64_t MonotonicTestStage::endStep(const RunContext& ctx) const {
    return ctx.stageStartStep + ctx.strideOf(ctx.config.shear.targetAxialStrain);
}

std::int64_t MonotonicTestStage::nextTestEvent(const RunContext& ctx) const {
    const std::int64_t end = endStep(ctx);
    const std::int64_t probes = handOverStep(ctx);
    return probes > ctx.sim->stepCount() ? std::min(end, probes) : end;
}

bool MonotonicTestStage::handleEvents(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    const bool end = now >= endStep(ctx);
    if (now == handOverStep(ctx)) {
        ctx.probeStart = ctx.sim->state(); // kept beside the next checkpoint
        ctx.probeStartKeptIn.clear();
    }
    if (now >= ctx.nextRecordStep || end) {
        record(ctx);
        trackPeak(ctx);
    }
    if (!end) {
        checkpointWhenDue(ctx);
    }
    return end;
}

void MonotonicTestStage::finish(RunContext& ctx) {
    if (const LoadingPath* probes = probesAfter(ctx);
        probes && probes->start == LoadingPath::Start::Peak && peak_.active) {
        ctx.probeStart = peak_.state; // kept beside the stage's end checkpoint
        ctx.probeStartKeptIn.clear();
    }
    peakCheckpoint(ctx);
    peak_ = RunningPeak{};
}

/// At a record, before a checkpoint of the same step: a new maximum of q/p keeps a copy of the
/// state. The first of equal maxima is the peak.
void MonotonicTestStage::trackPeak(RunContext& ctx) {
    const LoadingPath* probes = probesAfter(ctx);
    if (!ctx.output && !(probes && probes->start == LoadingPath::Start::Peak)) {
        return; // only the peak checkpoint and probes from the peak need it
    }
    const SeriesTable& t = ctx.series[ctx.currentSeries];
    const double ratio = t.rows.back()[t.column("q_over_p")];
    // In extension q < 0: the peak is the largest -q/p.
    const double sign = direction(ctx);
    if (peak_.active && !(sign * ratio > sign * peak_.at.stressRatio)) {
        return;
    }
    peak_.active = true;
    peak_.at.stressRatio = ratio;
    peak_.at.step = ctx.sim->stepCount();
    peak_.at.eps1 = ctx.eps1();
    peak_.state = ctx.sim->state();
    peak_.at.keptIn.clear();
}

/// The checkpoint at the peak of q/p of the test that is ending, marked as such. It is for
/// reading and viewing, not for continuing: it has no runner state (a resumed run starts from
/// the last checkpoint that is not a peak).
void MonotonicTestStage::peakCheckpoint(RunContext& ctx) {
    if (!ctx.output || !peak_.active) {
        return;
    }
    std::string stage = ctx.stageName();
    std::replace(stage.begin(), stage.end(), ' ', '-');
    const std::string name =
        ctx.nextCheckpointName(fmt::format("peak-{}-step{}", stage, peak_.at.step));
    // The contacts of the peak's state: a simulation made from it has the same forces, bit
    // for bit (as a resumed run has).
    const Simulation atPeak(peak_.state);
    const ContactNetwork network = atPeak.contactNetwork();
    const VoidCellSet cells = computeVoidCells(network);
    CheckpointData data;
    data.name = name;
    data.state = &peak_.state;
    data.identity = ctx.identity();
    data.identity.step = peak_.at.step;
    data.identity.axialStrain = peak_.at.eps1;
    data.identity.peak = true;
    data.identity.peakStressRatio = peak_.at.stressRatio;
    data.network = &network;
    data.voidCells = &cells;
    ctx.output->checkpoint(data);
}

void MonotonicTestStage::addToCheckpoint(CheckpointData& data) {
    if (peak_.active && peak_.at.step != data.state->step && peak_.at.keptIn.empty()) {
        // The first checkpoint since the peak's record keeps its state (named in the runner
        // state, so written before it is made).
        data.runningPeak = &peak_.state;
        peak_.at.keptIn = data.name;
    }
}

void MonotonicTestStage::saveTest(RunnerState& state, const RunContext& ctx) const {
    if (peak_.active) {
        RunningPeakRecord r = peak_.at;
        if (r.step == ctx.sim->stepCount()) {
            r.keptIn.clear(); // the checkpoint's own state is the peak's
        }
        state.peak = r;
    }
}

/// The running peak of a resumed run: from the runner state, with the state kept in the
/// checkpoint it names (`kept`), or the resumed state itself when the peak was at its step.
void MonotonicTestStage::restoreTest(const RunnerState& state, const RunContext& ctx,
                                     const SimulationState& resumed,
                                     std::optional<SimulationState> kept) {
    if (!state.peak) {
        return;
    }
    peak_.active = true;
    peak_.at = *state.peak;
    if (!peak_.at.keptIn.empty()) {
        if (!kept) {
            throw std::runtime_error(fmt::format(
                "resume: the checkpoint's running maximum of q/p is kept in checkpoint {}, "
                "which the resume point does not hold",
                peak_.at.keptIn));
        }
        peak_.state = std::move(*kept);
    } else if (peak_.at.step == resumed.step) {
        peak_.state = resumed;
    } else {
        throw std::runtime_error(
            fmt::format("resume: the running maximum of q/p (step {}) is kept in no checkpoint",
                        peak_.at.step));
    }
    if (peak_.state.step != peak_.at.step) {
        throw std::runtime_error(fmt::format("resume: the running maximum of q/p is at step "
                                             "{}, its kept state at step {}",
                                             peak_.at.step, peak_.state.step));
    }
    peak_.state.parameters.threads = threadsFor(ctx.config);
}

StageShare MonotonicTestStage::share(const ExperimentConfig& config) const {
    return {double(strideOf(config, config.shear.targetAxialStrain)), false};
}

} // namespace grainlab
