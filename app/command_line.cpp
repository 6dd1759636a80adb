#include "command_line.h"

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench/bench.h"
#include "cli/run_command.h"

#ifdef GRAINLAB_WITH_GUI
#include "bench/window_bench.h"
#include "gui/app.h"
#endif

namespace grainlab {

int runCommandLine(int argc, char** argv) {
    CLI::App app{"GrainLab: 2D discrete element simulations of oval grains"};
    app.set_version_flag("--version", std::string(GRAINLAB_VERSION));

    BenchOptions bench;
    auto* benchCommand =
        app.add_subcommand("bench", "time the engine on a dense assembly under biaxial compression");
    addBenchOptions(*benchCommand, bench);

    RunOptions run;
    auto* runCommand = app.add_subcommand("run", "run an experiment headless (no display needed)");
    runCommand->add_option("experiment", run.experiment, "experiment file (.json)");
    runCommand->add_option("--out", run.out, "output folder (run.h5 and <test>/series.csv)");
    runCommand->add_option("--resume", run.resume,
                           "continue the run in this output folder from its last checkpoint");
    runCommand->add_option("--threads", run.threads, "threads (default: the experiment's)");
    runCommand->add_flag("--quiet", run.quiet, "no progress bar");

    std::string experiment = std::string(GRAINLAB_SOURCE_DIR) + "/resources/experiments/quick.json";
    app.add_option("--experiment", experiment, "experiment to open in the window");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (*benchCommand) {
#ifdef GRAINLAB_WITH_GUI
            return runBench(bench, runGuiBench);
#else
            return runBench(bench, nullptr);
#endif
        }
        if (*runCommand) {
            if (run.resume.empty() == run.experiment.empty()) {
                fmt::print(stderr, "grainlab run: give either an experiment file with --out DIR, "
                                   "or --resume DIR\n");
                return 2;
            }
            if (!run.experiment.empty() && run.out.empty()) {
                fmt::print(stderr, "grainlab run: --out DIR is required with an experiment file\n");
                return 2;
            }
            return runExperimentCommand(run);
        }
#ifdef GRAINLAB_WITH_GUI
        return runGui(argc, argv, experiment);
#else
        fmt::print("{}", app.help());
        return 0;
#endif
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab: error: {}\n", e.what());
        return 1;
    }
}

} // namespace grainlab
