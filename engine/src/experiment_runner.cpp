#include "grainlab/experiment_runner.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "progress_estimate.h"
#include "run_context.h"
#include "runner_state.h"
#include "stage.h"
#include "stage_generation.h"

namespace grainlab {

/// Plays the plan's stages in order (stage.h): advances the simulation to the current stage's
/// next event, lets the stage handle it, and moves on when it has finished.
struct ExperimentRunner::Impl {
    RunContext ctx;
    std::vector<PlannedStage> plan;
    std::vector<StageShare> shares; ///< each planned stage's part of the progress estimate
    std::size_t position = 0;       ///< of the current stage in the plan

    void setPlan() {
        plan = experimentPlan(ctx.config);
        shares.clear();
        for (const PlannedStage& p : plan) {
            shares.push_back(makeStage(p)->share(ctx.config));
        }
    }

    /// The checkpoint at the end of a stage that ends with one. It says that its stage is done
    /// (stage_done), so that a run resumed from it goes on with the next stage
    /// (continueAfterStage) instead of running the finished one again; after the last stage it
    /// holds the finished run.
    void stageEndCheckpoint() {
        const std::string label = ctx.checkpointLabel();
        const StageIdentity id = ctx.identity();
        if (position + 1 == plan.size()) {
            ctx.done = true;
        }
        ctx.stageDone = true;
        ctx.checkpoint(label, id);
        continueAfterStage();
    }

    void continueAfterStage() {
        ctx.stageDone = false;
        if (!ctx.done) {
            startStage(position + 1);
        }
    }

    void startStage(std::size_t k) {
        position = k;
        ctx.stage = makeStage(plan[k]);
        ctx.stage->start(ctx);
    }

    void endStage() {
        ctx.stage->finish(ctx);
        ctx.stage->save(ctx.carried, ctx); // its fields keep their final values
        if (ctx.stage->checkpointAtEnd()) {
            stageEndCheckpoint();
        } else {
            startStage(position + 1);
        }
    }

    double fraction() const {
        return progressFraction(shares, ctx.done ? plan.size() : position,
                                ctx.sim->stepCount() - ctx.stageStartStep);
    }
};

ExperimentRunner::ExperimentRunner(ExperimentConfig config, RunOutput* output)
    : impl_(std::make_unique<Impl>()) {
    RunContext& ctx = impl_->ctx;
    ctx.config = std::move(config);
    ctx.output = output;
    if (ctx.config.compaction.pressures.empty()) {
        throw std::invalid_argument("experiment: compaction.pressures is empty");
    }
    impl_->setPlan();
    GeneratedSample generated = generateSample(ctx.config);
    ctx.sim = std::move(generated.simulation);
    ctx.thetaAtRunStart =
        std::make_shared<const std::vector<double>>(ctx.sim->stateRef().grains.theta);
    impl_->startStage(0);
    if (!generated.timeStepWarning.empty()) {
        ctx.warn("time_step", generated.timeStepWarning);
    }
    // A checkpoint of the generated assembly: a run killed before its first periodic
    // checkpoint can still be resumed.
    ctx.checkpoint(ctx.checkpointLabel());
}

ExperimentRunner::ExperimentRunner(ExperimentConfig config, ResumePoint resume, RunOutput* output)
    : impl_(std::make_unique<Impl>()) {
    RunContext& ctx = impl_->ctx;
    ctx.config = std::move(config);
    ctx.output = output;
    impl_->setPlan();
    ctx.samples = std::move(resume.samples);
    const RunnerState s = parseRunnerState(resume.runnerState);
    for (SeriesTable& t : resume.series) {
        const auto it = s.seriesRows.find(t.test);
        const std::size_t keep = it == s.seriesRows.end() ? 0 : it->second;
        t.rows.resize(std::min(keep, t.rows.size()));
        t.stages.resize(std::min(keep, t.stages.size()));
        t.stageKinds.resize(std::min(keep, t.stageKinds.size()));
        t.stagePressures.resize(std::min(keep, t.stagePressures.size()));
        ctx.series.push_back(std::move(t));
    }
    resume.state.parameters.threads = threadsFor(ctx.config);

    const auto kind = static_cast<StageKind>(s.phase);
    ctx.done = kind == StageKind::Done;
    // A finished run's stage is the plan's last, which its final checkpoint ended.
    impl_->position = ctx.done ? impl_->plan.size() - 1 : planPosition(impl_->plan, kind, s.index);
    ctx.stage = makeStage(impl_->plan[impl_->position]);
    ctx.restore(s);
    if (s.probeStartState) {
        if (!resume.probeStart || resume.probeStart->step != s.probeStartState->step) {
            throw std::runtime_error(fmt::format(
                "resume: the start state of the probes (step {}) is kept in checkpoint {}, which "
                "the resume point does not hold",
                s.probeStartState->step, s.probeStartState->keptIn));
        }
        ctx.probeStart = std::move(resume.probeStart);
        ctx.probeStart->parameters.threads = threadsFor(ctx.config);
    }
    ctx.stage->restore(s, ctx, resume.state, std::move(resume.runningPeak));
    ctx.sim = std::make_unique<Simulation>(std::move(resume.state));
    if (output) {
        output->warnings(ctx.warnings); // the file holds what its checkpoint held
    }
}

ExperimentRunner::~ExperimentRunner() = default;

bool ExperimentRunner::advance(std::int64_t maxSteps) {
    Impl& m = *impl_;
    RunContext& ctx = m.ctx;
    // The events' own time: their wall time less the records and checkpoints made in them.
    double eventsWall = 0;
    const double recordsBefore = ctx.times.records, checkpointsBefore = ctx.times.checkpoints;
    if (ctx.stageDone) {
        const AddWallTime timed(eventsWall);
        m.continueAfterStage(); // resumed from a stage-end checkpoint
    }
    std::int64_t done = 0;
    while (done < maxSteps && !ctx.done) {
        const std::int64_t chunk = std::min(ctx.stage->stepsToNextEvent(ctx), maxSteps - done);
        {
            const AddWallTime timed(ctx.times.stepping);
            ctx.sim->advance(chunk);
        }
        done += chunk;
        ctx.stepsTaken += chunk;
        const AddWallTime timed(eventsWall);
        if (ctx.stage->handleEvents(ctx)) {
            m.endStage();
        }
    }
    ctx.times.events += eventsWall - (ctx.times.records - recordsBefore) -
                        (ctx.times.checkpoints - checkpointsBefore);
    return !ctx.done;
}

std::int64_t ExperimentRunner::stepsTaken() const {
    return impl_->ctx.stepsTaken;
}

RunnerTimes ExperimentRunner::times() const {
    return impl_->ctx.times;
}

bool ExperimentRunner::finished() const {
    return impl_->ctx.done;
}

RunProgress ExperimentRunner::progress() const {
    const RunContext& ctx = impl_->ctx;
    RunProgress p;
    p.stage = ctx.stageName();
    p.kind = ctx.done ? StageKind::Done : ctx.stage->kind();
    p.pressure = ctx.stage->pressure();
    p.test = ctx.currentSeries >= 0 ? ctx.series[ctx.currentSeries].test : "";
    p.thetaAtTestStart = ctx.thetaAtTestStart;
    // eps1 of the current test: during the test, and its final value once the run is done.
    p.axialStrain = ctx.stage->isTest() ? ctx.eps1() : 0.0;
    p.fraction = impl_->fraction();
    p.step = ctx.sim->stepCount();
    p.finished = ctx.done;
    return p;
}

const ExperimentConfig& ExperimentRunner::config() const {
    return impl_->ctx.config;
}
const Simulation& ExperimentRunner::simulation() const {
    return *impl_->ctx.sim;
}
const std::vector<SeriesTable>& ExperimentRunner::series() const {
    return impl_->ctx.series;
}
std::vector<double> ExperimentRunner::measuresNow() const {
    const RunContext& ctx = impl_->ctx;
    const MeasureSet measures = computeMeasures(ctx.sim->contactNetwork());
    return seriesRow(measures, ctx.recordInputs(measures, true));
}
const std::vector<RunWarning>& ExperimentRunner::warnings() const {
    return impl_->ctx.warnings;
}

void ExperimentRunner::checkpointNow(const std::string& name) {
    impl_->ctx.checkpoint(name);
}

// The three readers below look at one key each, so they also read runner states that hold
// only that key.
bool ExperimentRunner::finishedAt(const std::string& runnerState) {
    return nlohmann::json::parse(runnerState).at("phase").get<int>() == int(StageKind::Done);
}

namespace {

/// The checkpoint that keeps the state named by the runner state's `key` ("" when none).
std::string keptIn(const std::string& runnerState, const char* key) {
    const nlohmann::json j = nlohmann::json::parse(runnerState);
    return j.contains(key) ? j.at(key).at("kept_in").get<std::string>() : std::string();
}

} // namespace

std::string ExperimentRunner::runningPeakCheckpoint(const std::string& runnerState) {
    return keptIn(runnerState, "peak");
}

std::string ExperimentRunner::probeStartCheckpoint(const std::string& runnerState) {
    return keptIn(runnerState, "probe_start");
}

std::map<std::string, std::size_t>
ExperimentRunner::seriesRowsAtCheckpoint(const std::string& runnerState) {
    std::map<std::string, std::size_t> out;
    const nlohmann::json j = nlohmann::json::parse(runnerState);
    for (const auto& [name, count] : j.at("series_rows").items()) {
        out[name] = count.get<std::size_t>();
    }
    return out;
}

std::shared_ptr<Snapshot> ExperimentRunner::snapshot(SnapshotMeasures measures) const {
    const RunContext& ctx = impl_->ctx;
    auto snap = std::make_shared<Snapshot>();
    const RunProgress p = progress();
    snap->stage = p.stage;
    snap->stageKind = p.kind;
    snap->stagePressure = p.pressure;
    snap->test = p.test;
    snap->axialStrain = p.axialStrain;
    snap->progress = p.fraction;
    snap->thetaAtTestStart = p.thetaAtTestStart;
    fillSnapshotScene(*snap, *ctx.sim, *ctx.thetaAtTestStart, measures);
    snap->series = ctx.series;
    snap->warnings = ctx.warnings;
    return snap;
}

int engineThreads(const ExperimentConfig& config) {
    return threadsFor(config);
}

} // namespace grainlab
