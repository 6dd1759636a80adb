#include "command_line.h"

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench.h"

namespace grainlab {

int runCommandLine(int argc, char** argv) {
    CLI::App app{"GrainLab: 2D discrete element simulations of oval grains"};
    app.set_version_flag("--version", std::string(GRAINLAB_VERSION));

    BenchOptions bench;
    auto* benchCommand =
        app.add_subcommand("bench", "time the engine on a dense assembly under biaxial compression");
    benchCommand->add_option("--shape", bench.shape, "oval, disk or both")->capture_default_str();
    benchCommand->add_option("--grains", bench.grains, "number of grains")->capture_default_str();
    benchCommand->add_option("--steps", bench.steps, "timed steps")->capture_default_str();
    benchCommand->add_option("--threads", bench.threads, "thread counts, comma separated")
        ->capture_default_str();
    benchCommand->add_option("--seed", bench.seed, "random seed")->capture_default_str();

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (*benchCommand) {
            return runBench(bench);
        }
        fmt::print("{}", app.help());
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "grainlab: error: {}\n", e.what());
        return 1;
    }
}

} // namespace grainlab
