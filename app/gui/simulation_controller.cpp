// See simulation_controller.h.
#include "gui/simulation_controller.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include <fmt/format.h>

#include "gui/worker_thread.h"

namespace grainlab::ui {
namespace {

double wallSeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

/// Steps per advance() call are tuned so that one call takes about this long: short enough for
/// commands to feel immediate, long enough that the loop costs nothing.
constexpr double kChunkSeconds = 0.005;
constexpr std::int64_t kMaxChunk = 1 << 20;

} // namespace

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<grainlab::ui::RunState>();
    history_.setFinisher(&finisher_);
    worker_ = startWorkerThread(QStringLiteral("grainlab engine"), [this] { workerLoop(); });
}

SimulationController::~SimulationController() {
    quitWorkerThread(*worker_, mutex_, wake_, quit_);
}

void SimulationController::setRunFactory(RunFactory factory) {
    std::lock_guard lock(mutex_);
    factory_ = std::move(factory);
}

void SimulationController::post(Command command) {
    {
        std::lock_guard lock(mutex_);
        commands_.push_back(command);
    }
    wake_.notify_all();
}

void SimulationController::start() {
    post({CommandKind::Start});
}
void SimulationController::pause() {
    post({CommandKind::Pause});
}
void SimulationController::step(std::int64_t steps) {
    post({CommandKind::Step, std::max<std::int64_t>(1, steps)});
}
void SimulationController::stop() {
    post({CommandKind::Stop});
}

SnapshotPtr SimulationController::latestSnapshot() const {
    std::lock_guard lock(mutex_);
    return latest_;
}

RunStatus SimulationController::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

void SimulationController::setPublishInterval(double seconds) {
    std::lock_guard lock(mutex_);
    publishInterval_ = std::max(0.0, seconds);
}

void SimulationController::setState(RunState state, const std::string& error) {
    bool changed = false;
    {
        std::lock_guard lock(mutex_);
        changed = status_.state != state || !error.empty();
        status_.state = state;
        if (state != RunState::Failed) {
            status_.error.clear();
        } else {
            status_.error = error;
        }
    }
    if (changed) {
        emit stateChanged(state);
    }
}

bool SimulationController::ensureRun() {
    if (run_) {
        return true;
    }
    RunFactory factory;
    {
        std::lock_guard lock(mutex_);
        factory = factory_;
        status_.stepsDone = 0;
        status_.publishingSeconds = 0.0;
        status_.runningPublications = 0;
        status_.stepsPerSecond = status_.strainPerSecond = 0.0;
        status_.etaSeconds = -1.0;
    }
    if (!factory) {
        setState(RunState::Failed, "no experiment loaded");
        return false;
    }
    history_.clear();
    run_ = factory();
    run_->keepRecordSnapshots(&history_);
    {
        std::lock_guard lock(mutex_);
        status_.runFolder = run_->runFolder();
        status_.progress = run_->progress(); // not the previous run's
    }
    lastRateTime_ = wallSeconds();
    lastRateSteps_ = 0;
    lastRateStrain_ = run_->progress().axialStrain;
    lastRateFraction_ = run_->progress().fraction;
    return true;
}

void SimulationController::endRun() {
    running_ = false;
    if (!run_) {
        return;
    }
    std::unique_ptr<SteppedRun> run = std::move(run_);
    run->interrupt();
}

void SimulationController::publish(RunState state) {
    const double start = wallSeconds();
    std::shared_ptr<Snapshot> snapshot = run_->snapshot();
    const RunProgress progress = run_->progress();
    const bool later = state == RunState::Running && !snapshot->measured;
    if (!later) {
        addSnapshotMeasures(*snapshot);
    }
    const double now = wallSeconds();
    std::uint64_t sequence = 0;
    {
        std::lock_guard lock(mutex_);
        sequence = ++publishedSequence_;
        if (!later) {
            latest_ = snapshot;
            latestSequence_ = sequence;
        }
        status_.progress = progress;
        status_.snapshotSeconds = now - start;
        ++status_.publications;
        if (state == RunState::Running) {
            status_.publishingSeconds += now - start;
            ++status_.runningPublications;
        }
        // Rates over the interval since the previous publication, smoothed.
        const double dt = now - lastRateTime_;
        if (dt > 0.05 && state == RunState::Running) {
            const double blend = 0.4;
            const double steps = double(status_.stepsDone - lastRateSteps_) / dt;
            const double strain = (progress.axialStrain - lastRateStrain_) / dt;
            const double fraction = (progress.fraction - lastRateFraction_) / dt;
            status_.stepsPerSecond = status_.stepsPerSecond > 0
                                         ? (1 - blend) * status_.stepsPerSecond + blend * steps
                                         : steps;
            if (strain >= 0.0) {
                status_.strainPerSecond = (1 - blend) * status_.strainPerSecond + blend * strain;
            }
            status_.etaSeconds = fraction > 0 ? (1.0 - progress.fraction) / fraction : -1.0;
            lastRateTime_ = now;
            lastRateSteps_ = status_.stepsDone;
            lastRateStrain_ = progress.axialStrain;
            lastRateFraction_ = progress.fraction;
        }
    }
    if (later) {
        finisher_.submit(
            std::move(snapshot),
            [this, sequence](SnapshotPtr done) {
                std::lock_guard lock(mutex_);
                if (sequence > latestSequence_) { // not overtaken by a paused picture
                    latest_ = std::move(done);
                    latestSequence_ = sequence;
                }
                status_.measureSeconds = finisher_.lastSeconds();
            },
            true);
    }
    setState(state);
}

void SimulationController::workerLoop() {
    std::int64_t chunk = 10;
    double lastPublish = -1e300;
    for (;;) {
        std::deque<Command> commands;
        double interval = 0.0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || !commands_.empty() || running_; });
            if (quit_) {
                lock.unlock();
                try {
                    endRun();
                } catch (const std::exception&) {
                    // The window is closing: nobody is left to tell; the run file keeps its
                    // last complete checkpoint.
                }
                break;
            }
            commands.swap(commands_);
            // Copying a snapshot may take a while on a large assembly: publish at most so often
            // that it costs the engine about 2 % of its time.
            interval = std::max(publishInterval_, 49.0 * status_.snapshotSeconds);
        }
        try {
            for (const Command& c : commands) {
                switch (c.kind) {
                case CommandKind::Start:
                    if (ensureRun()) {
                        running_ = true;
                        publish(RunState::Running);
                        lastPublish = wallSeconds();
                    }
                    break;
                case CommandKind::Pause:
                    if (run_ && running_) {
                        running_ = false;
                        publish(RunState::Paused);
                    }
                    break;
                case CommandKind::Step:
                    if (ensureRun()) {
                        running_ = false;
                        const bool more = run_->advance(c.steps);
                        {
                            std::lock_guard lock(mutex_);
                            status_.stepsDone += c.steps;
                        }
                        publish(more ? RunState::Paused : RunState::Finished);
                    }
                    break;
                case CommandKind::Stop:
                    endRun();
                    setState(RunState::Idle);
                    break;
                }
            }
            if (running_ && run_) {
                const double t0 = wallSeconds();
                const bool more = run_->advance(chunk);
                const double dt = wallSeconds() - t0;
                {
                    std::lock_guard lock(mutex_);
                    status_.stepsDone += chunk;
                }
                if (dt < 0.5 * kChunkSeconds) {
                    chunk = std::min(kMaxChunk, 2 * chunk);
                } else if (dt > 2.0 * kChunkSeconds) {
                    chunk = std::max<std::int64_t>(1, chunk / 2);
                }
                if (!more) {
                    running_ = false;
                    publish(RunState::Finished);
                } else if (wallSeconds() - lastPublish >= interval) {
                    publish(RunState::Running);
                    lastPublish = wallSeconds();
                }
            }
        } catch (const std::exception& e) {
            running_ = false;
            std::string message = e.what();
            if (run_ && !run_->runFolder().empty()) {
                // As `grainlab run` says it: what the folder keeps, and how to continue.
                const std::string good = run_->lastGoodCheckpoint();
                message += fmt::format(
                    ". The run folder {} keeps {} and every series recorded up to it; once the "
                    "cause is removed, continue with: grainlab run --resume {}",
                    run_->runFolder(),
                    good.empty() ? std::string("no checkpoint yet")
                                 : "its last good checkpoint " + good,
                    run_->runFolder());
            }
            run_.reset();
            setState(RunState::Failed, message);
        }
    }
}

} // namespace grainlab::ui
