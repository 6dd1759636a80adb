#include "cli/run_command.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "cli/run_session.h"
#include "common/progress_bar.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) {
    interrupted.store(true);
}

/// SIGINT and SIGTERM noted, not fatal, while the command runs; the previous handlers back when
/// it returns. Installed before the run folder is touched: a stop that comes while a new run
/// makes its files (a study stopped just as its pool starts a run) ends the run at its first
/// checkpoint, instead of killing it between its run file and that checkpoint, where a resume
/// would find nothing to continue from.
class InterruptHandlers {
public:
    InterruptHandlers() {
        interrupted.store(false);
        previousInt_ = std::signal(SIGINT, onInterrupt);
        previousTerm_ = std::signal(SIGTERM, onInterrupt);
    }
    ~InterruptHandlers() {
        std::signal(SIGINT, previousInt_);
        std::signal(SIGTERM, previousTerm_);
    }
    InterruptHandlers(const InterruptHandlers&) = delete;
    InterruptHandlers& operator=(const InterruptHandlers&) = delete;

private:
    void (*previousInt_)(int) = nullptr;
    void (*previousTerm_)(int) = nullptr;
};

/// The test hook (see run_command.h): after this many steps of this process, raise the signal.
struct TestStop {
    std::int64_t afterSteps = -1; ///< -1: no test stop
    int signal = SIGKILL;
};

TestStop testStopFromEnvironment() {
    TestStop stop;
    const char* steps = std::getenv("GRAINLAB_TEST_STOP_AFTER_STEPS");
    if (!steps || !*steps) {
        return stop;
    }
    char* end = nullptr;
    const long long n = std::strtoll(steps, &end, 10);
    if (*end != '\0' || n < 1) {
        throw std::runtime_error(fmt::format(
            "GRAINLAB_TEST_STOP_AFTER_STEPS={}: must be a whole number of steps >= 1", steps));
    }
    stop.afterSteps = n;
    const char* name = std::getenv("GRAINLAB_TEST_STOP_SIGNAL");
    const std::string signalName = name ? name : "KILL";
    if (signalName == "KILL") {
        stop.signal = SIGKILL;
    } else if (signalName == "INT") {
        stop.signal = SIGINT;
    } else if (signalName == "TERM") {
        stop.signal = SIGTERM;
    } else {
        throw std::runtime_error(
            fmt::format("GRAINLAB_TEST_STOP_SIGNAL={}: must be KILL, INT or TERM", signalName));
    }
    return stop;
}

/// What to change in the experiment file when the run stopped for a cause of the experiment
/// itself (the physics, or a stage's step limit): a resume restarts from a checkpoint with the
/// same keys and meets the same stop. Empty for a cause outside the experiment (a full disk, a
/// file that cannot be written), which a resume survives once the cause is removed.
std::string experimentRemedy(const std::exception& e) {
    if (const auto* stop = dynamic_cast<const SimulationError*>(&e)) {
        if (stop->cause.find("overlap") != std::string::npos) {
            return "lower time_step, or raise stability.max_overlap_fraction (at most 1)";
        }
        if (stop->cause.find("runaway") != std::string::npos) {
            return "lower time_step, or raise stability.max_step_fraction (at most 1)";
        }
        return "lower time_step, or raise damping.coefficient";
    }
    // The runner's stop at a stage's step limit (a plain runtime_error of ExperimentRunner).
    const std::string text = e.what();
    if (text.find("did not reach equilibrium") != std::string::npos) {
        return text.find("stage 'compaction") != std::string::npos
                   ? "raise compaction.criterion.max_steps, or relax that criterion"
                   : "raise shear.equilibration.max_steps, or relax that criterion";
    }
    return {};
}

/// Where this process's time went (the run's sums over its processes are in cost.json).
void printTimes(const RunnerTimes& t) {
    const double total = t.total();
    if (!(total > 0.0)) {
        return;
    }
    const auto part = [&](double seconds) {
        return fmt::format("{:.1f} s ({:.1f} %)", seconds, 100.0 * seconds / total);
    };
    fmt::print("grainlab run: time in this process: stepping {}, records {}, checkpoints {}, "
               "other stage events {}\n",
               part(t.stepping), part(t.records), part(t.checkpoints), part(t.events));
}

} // namespace

int runExperimentCommand(const RunOptions& options) {
    const bool resume = !options.resume.empty();
    const std::string folder = resume ? options.resume : options.out;
    const InterruptHandlers handlers;
    std::unique_ptr<RunSession> session;
    try {
        // A new run's experiment is read and checked before its folder is created or locked: a
        // refused experiment leaves nothing behind (reading writes nothing).
        session = resume ? RunSession::resume(folder, options.threads)
                         : RunSession::create(readExperimentFile(options.experiment), folder,
                                              options.force, options.threads);
    } catch (const RunFolderRefused& e) {
        fmt::print(stderr, "grainlab run: {}\n", e.what());
        return 2;
    }
    if (session->finishedAlready()) {
        // Nothing to run: the files stay exactly as they are, but for a cost record that
        // missed the end.
        session->completeCostRecord();
        fmt::print("grainlab run: the run in {} is finished; nothing to resume (outputs in {})\n",
                   folder, folder);
        return 0;
    }
    const ExperimentConfig& config = session->config();
    // Past a file size limit (ulimit -f) a write then fails with EFBIG, which the run file
    // reports and survives like a full disk, instead of SIGXFSZ killing the process.
    std::signal(SIGXFSZ, SIG_IGN);

    ProgressBar bar(fmt::format("{} ({} grains)", config.name, config.assembly.grainCount));
    auto last = std::chrono::steady_clock::now();
    std::int64_t lastStep = 0;
    double stepsPerSecond = 0;
    int status = 0;
    const TestStop stop = testStopFromEnvironment();
    std::int64_t advanced = 0; // steps of this process (the step count restarts per test)
    try {
        // A new run writes its first checkpoint here: inside the try, as every later write.
        session->start();
        const ExperimentRunner* runner = &session->runner();
        lastStep = runner->progress().step;
        // Each warning is printed once, when it is given (a resumed run's earlier ones again
        // at its start, so that the terminal shows them all).
        std::size_t warned = 0;
        const auto printWarnings = [&] {
            const std::vector<RunWarning>& all = runner->warnings();
            for (; warned < all.size(); ++warned) {
                // A test ended by its stop criterion is news, not a warning.
                const bool ended = all[warned].kind == "test_end";
                bar.note(fmt::format("grainlab run: {} ({}, step {}): {}",
                                     ended ? "test ended early" : "warning", all[warned].test,
                                     all[warned].step, all[warned].text));
            }
        };
        printWarnings();
        while (true) {
            std::int64_t chunk = 200;
            if (stop.afterSteps > advanced) {
                chunk = std::min(chunk, stop.afterSteps - advanced);
            }
            const bool more = session->advance(chunk);
            advanced += chunk;
            if (advanced == stop.afterSteps) {
                std::raise(stop.signal);
            }
            printWarnings();
            if (!more) {
                break;
            }
            if (interrupted.load()) {
                session->interrupt();
                bar.finish();
                fmt::print(stderr,
                           "grainlab run: interrupted; the run file and series are valid and a "
                           "checkpoint was written.\nContinue with: grainlab run --resume {}\n",
                           folder);
                status = 130;
                break;
            }
            const auto now = std::chrono::steady_clock::now();
            const double seconds = std::chrono::duration<double>(now - last).count();
            const RunProgress p = runner->progress();
            if (seconds > 0.5) {
                const std::int64_t steps = p.step - lastStep;
                stepsPerSecond = steps > 0 ? steps / seconds : stepsPerSecond;
                last = now;
                lastStep = p.step;
            }
            if (!options.quiet) {
                bar.update(p.fraction, fmt::format("{} eps1 {:.4f} {:.0f} steps/s", p.stage,
                                                   p.axialStrain, stepsPerSecond));
            }
        }
        if (status == 0) {
            // The run file is complete on disk before the cost record says the run is finished
            // (a study takes a finished record as a finished, readable run).
            session->finish();
            if (!options.quiet) {
                bar.update(1.0, "done");
                bar.finish();
            }
            fmt::print("grainlab run: finished; outputs in {}\n", folder);
            if (!options.quiet) {
                printTimes(runner->times());
            }
        }
    } catch (const std::exception& e) {
        bar.finish();
        session->saveCostAfterFailure();
        const std::string kept = session->lastCheckpoint();
        const std::string remedy = experimentRemedy(e);
        if (!remedy.empty()) {
            const std::string experiment = resume || options.experiment.empty()
                                               ? std::string("EXPERIMENT.json")
                                               : options.experiment;
            fmt::print(stderr,
                       "grainlab run: error: {}\nThis stop comes from the experiment itself: a "
                       "resume would meet it again. In the experiment file (its text is also "
                       "kept in {} as /experiment): {}; then start a new run: grainlab run {} "
                       "--out NEW_FOLDER\n",
                       e.what(), session->runFilePath(), remedy, experiment);
            if (!kept.empty()) {
                fmt::print(stderr,
                           "The run file {} keeps its last good checkpoint {} and every series "
                           "recorded up to it.\n",
                           session->runFilePath(), kept);
            }
        } else if (kept.empty()) {
            fmt::print(stderr,
                       "grainlab run: error: {}\nThe run file {} holds no checkpoint to continue "
                       "from. Once the cause is removed (e.g. space freed), run the experiment "
                       "again with --force\n",
                       e.what(), session->runFilePath());
        } else {
            fmt::print(stderr,
                       "grainlab run: error: {}\nThe run file {} keeps its last good checkpoint "
                       "{} and every series recorded up to it. Once the cause is removed (e.g. "
                       "space freed), continue with: grainlab run --resume {}\n",
                       e.what(), session->runFilePath(), kept, folder);
        }
        return 1;
    }
    return status;
}

} // namespace grainlab
