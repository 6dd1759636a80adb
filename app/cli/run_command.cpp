#include "cli/run_command.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "common/progress_bar.h"
#include "common/run_cost.h"
#include "cli/run_output.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) {
    interrupted.store(true);
}

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

} // namespace

int runExperimentCommand(const RunOptions& options) {
    const bool resume = !options.resume.empty();
    const std::string folder = resume ? options.resume : options.out;
    // A new run's experiment is read and checked before its folder is created or locked: a
    // refused experiment leaves nothing behind (reading writes nothing).
    ExperimentConfig config;
    if (!resume) {
        config = readExperimentFile(options.experiment);
    }
    // The folder is locked before anything in it is read or written; a refusal touches nothing.
    std::unique_ptr<RunFolderLock> lock;
    const fs::path runFilePath = fs::path(folder) / "run.h5";
    try {
        if (resume) {
            if (!fs::exists(runFilePath)) {
                fmt::print(stderr, "grainlab run: --resume {}: no run file {}\n", folder,
                           runFilePath.string());
                return 2;
            }
            lock = std::make_unique<RunFolderLock>(folder, true);
        } else {
            if (fs::exists(RunFolderLock::path(folder))) {
                lock = std::make_unique<RunFolderLock>(folder, false);
            }
            if (fs::exists(runFilePath) && !options.force) {
                fmt::print(stderr,
                           "grainlab run: --out {}: that folder already holds a run ({}); "
                           "continue it with `grainlab run --resume {}`, or give --force to "
                           "replace it\n",
                           folder, runFilePath.string(), folder);
                return 2;
            }
            if (!lock) {
                lock = std::make_unique<RunFolderLock>(folder, true);
            }
        }
    } catch (const std::runtime_error& e) {
        fmt::print(stderr, "grainlab run: {}\n", e.what());
        return 2;
    }
    ResumePoint point;
    if (resume) {
        const std::string runFile = runFilePath.string();
        config = parseExperimentText(readExperimentText(runFile), runFile + ":/experiment");
        point = RunOutputFolder::readResumePoint(folder);
        if (ExperimentRunner::finishedAt(point.runnerState)) {
            // Nothing to run: the files stay exactly as they are, but for a cost record that
            // missed the end (the process was killed between its last checkpoint and it).
            RunCostRecord cost = readRunCost(folder);
            if (!cost.finished) {
                cost.finished = true;
                writeRunCost(folder, cost);
            }
            fmt::print("grainlab run: the run in {} is finished; nothing to resume (outputs in "
                       "{})\n",
                       folder, folder);
            return 0;
        }
    } else {
        if (options.force) {
            removeRunFiles(folder); // the old run's files, CSVs too, do not linger
        }
    }
    if (options.threads > 0) {
        config.parameters.threads = options.threads;
    }
    // Past a file size limit (ulimit -f) a write then fails with EFBIG, which the run file
    // reports and survives like a full disk, instead of SIGXFSZ killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
    RunOutputFolder output(folder, config.sourceText, resume);
    std::unique_ptr<ExperimentRunner> runner;

    // What the run costs, beside its run file (cost.json), for the study commands.
    RunCostMeter cost(folder, resume);
    const auto saveCost = [&](bool finished) {
        if (runner) {
            cost.save(runner->stepsTaken(), config.assembly.grainCount,
                      runner->simulation().stateRef().parameters.threads, finished);
        }
    };

    interrupted.store(false);
    auto previous = std::signal(SIGINT, onInterrupt);
    auto previousTerm = std::signal(SIGTERM, onInterrupt);
    ProgressBar bar(fmt::format("{} ({} grains)", config.name, config.assembly.grainCount));
    auto last = std::chrono::steady_clock::now();
    std::int64_t lastStep = 0;
    double stepsPerSecond = 0;
    int status = 0;
    const TestStop stop = testStopFromEnvironment();
    std::int64_t advanced = 0; // steps of this process (the step count restarts per test)
    try {
        // A new run writes its first checkpoint here: inside the try, as every later write.
        runner = resume ? std::make_unique<ExperimentRunner>(config, std::move(point), &output)
                        : std::make_unique<ExperimentRunner>(config, &output);
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
            const bool more = runner->advance(chunk);
            advanced += chunk;
            if (advanced == stop.afterSteps) {
                std::raise(stop.signal);
            }
            printWarnings();
            if (!more) {
                break;
            }
            cost.saveEvery(5.0, runner->stepsTaken(), config.assembly.grainCount,
                           runner->simulation().stateRef().parameters.threads);
            if (interrupted.load()) {
                runner->checkpointNow("interrupted");
                saveCost(false);
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
            output.close();
            saveCost(true);
            if (!options.quiet) {
                bar.update(1.0, "done");
                bar.finish();
            }
            fmt::print("grainlab run: finished; outputs in {}\n", folder);
        }
    } catch (const std::exception& e) {
        bar.finish();
        try {
            saveCost(false);
        } catch (const std::exception&) {
            // The error below is what matters; a cost record that cannot be written is not.
        }
        std::signal(SIGINT, previous);
        std::signal(SIGTERM, previousTerm);
        const std::string kept = output.lastCheckpoint();
        const std::string remedy = experimentRemedy(e);
        if (!remedy.empty()) {
            const std::string experiment =
                resume || options.experiment.empty() ? std::string("EXPERIMENT.json")
                                                      : options.experiment;
            fmt::print(stderr,
                       "grainlab run: error: {}\nThis stop comes from the experiment itself: a "
                       "resume would meet it again. In the experiment file (its text is also "
                       "kept in {} as /experiment): {}; then start a new run: grainlab run {} "
                       "--out NEW_FOLDER\n",
                       e.what(), output.runFilePath(), remedy, experiment);
            if (!kept.empty()) {
                fmt::print(stderr,
                           "The run file {} keeps its last good checkpoint {} and every series "
                           "recorded up to it.\n",
                           output.runFilePath(), kept);
            }
        } else if (kept.empty()) {
            fmt::print(stderr,
                       "grainlab run: error: {}\nThe run file {} holds no checkpoint to continue "
                       "from. Once the cause is removed (e.g. space freed), run the experiment "
                       "again with --force\n",
                       e.what(), output.runFilePath());
        } else {
            fmt::print(stderr,
                       "grainlab run: error: {}\nThe run file {} keeps its last good checkpoint "
                       "{} and every series recorded up to it. Once the cause is removed (e.g. "
                       "space freed), continue with: grainlab run --resume {}\n",
                       e.what(), output.runFilePath(), kept, folder);
        }
        return 1;
    }
    std::signal(SIGINT, previous);
    std::signal(SIGTERM, previousTerm);
    return status;
}

} // namespace grainlab
