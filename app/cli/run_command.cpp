#include "cli/run_command.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>

#include <fmt/format.h>

#include "cli/progress_bar.h"
#include "cli/run_cost.h"
#include "cli/run_output.h"
#include "grainlab/experiment_file.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/run_file.h"

namespace grainlab {
namespace {

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int) { interrupted.store(true); }

} // namespace

int runExperimentCommand(const RunOptions& options) {
    const bool resume = !options.resume.empty();
    const std::string folder = resume ? options.resume : options.out;
    ExperimentConfig config;
    ResumePoint point;
    if (resume) {
        const std::string runFile = (std::filesystem::path(folder) / "run.h5").string();
        if (!std::filesystem::exists(runFile)) {
            fmt::print(stderr, "grainlab run: --resume {}: no run file {}\n", folder, runFile);
            return 2;
        }
        config = parseExperimentText(readExperimentText(runFile), runFile + ":/experiment");
        point = RunOutputFolder::readResumePoint(folder);
    } else {
        config = readExperimentFile(options.experiment);
    }
    if (options.threads > 0) {
        config.parameters.threads = options.threads;
    }
    RunOutputFolder output(folder, config.sourceText, resume);
    std::unique_ptr<ExperimentRunner> runner =
        resume ? std::make_unique<ExperimentRunner>(config, std::move(point), &output)
               : std::make_unique<ExperimentRunner>(config, &output);

    // What the run costs, beside its run file (cost.json), for the study commands.
    RunCostMeter cost(folder, resume);
    const auto saveCost = [&](bool finished) {
        cost.save(runner->stepsTaken(), config.assembly.grainCount,
                  runner->simulation().stateRef().parameters.threads, finished);
    };

    interrupted.store(false);
    auto previous = std::signal(SIGINT, onInterrupt);
    auto previousTerm = std::signal(SIGTERM, onInterrupt);
    ProgressBar bar(fmt::format("{} ({} grains)", config.name, config.assembly.grainCount));
    auto last = std::chrono::steady_clock::now();
    std::int64_t lastStep = runner->progress().step;
    double stepsPerSecond = 0;
    int status = 0;
    try {
        while (runner->advance(200)) {
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
            saveCost(true);
            bar.update(1.0, "done");
            bar.finish();
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
        fmt::print(stderr,
                   "grainlab run: error: {}\nThe run file {} keeps the last good checkpoint and "
                   "every series recorded so far.\n",
                   e.what(), output.runFilePath());
        return 1;
    }
    std::signal(SIGINT, previous);
    std::signal(SIGTERM, previousTerm);
    return status;
}

} // namespace grainlab
