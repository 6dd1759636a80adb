#include "command_line.h"

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench.h"
#include "run_command.h"

#if defined(GRAINLAB_WITH_GUI) && __has_include("gui_app.h")
#define GRAINLAB_HAVE_WINDOW 1
#include "gui_app.h"
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
    // The experiment file's range for `threads` (docs/experiment-file.md).
    runCommand
        ->add_option("--threads", run.threads, "threads, 1 to 1024 (default: the experiment's)")
        ->check(CLI::Range(1, 1024).description("")) // out of range or not a whole number: refused
        ->type_name("N");
    runCommand->add_flag("--force", run.force,
                         "replace the run already in the --out folder (its files are removed)");
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
            return runBench(bench);
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
#ifdef GRAINLAB_HAVE_WINDOW
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
