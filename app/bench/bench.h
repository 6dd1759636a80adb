#pragma once
// `grainlab bench`: times the engine on a dense periodic assembly under biaxial compression
// (axis 1 strain-controlled at an engineering rate of 0.2 /s, axis 2 held at 100 kPa, mu = 0.5)
// and prints grain-steps per second; optionally runs stock LAMMPS on the same disk assembly in
// the same invocation (interleaved rounds), the minimal disk kernel of limit_kernel.h beside the
// engine (--limit), and the cost per grain-step from 1k to 128k grains.
// Progress goes to stderr, the tables to stdout. Runs on the main thread. With --gui (GUI builds):
// what the live window costs the engine and the scene's frame time instead (window_bench.h).

#include <cstdint>
#include <string>

#include "common/resources.h"
#include "grainlab/simulation_state.h"

namespace CLI {
class App;
}

namespace grainlab {

struct BenchOptions {
    std::string shape = "both";  ///< "oval", "disk" or "both"
    int grains = 8450;           ///< grains of a generated assembly
    std::int64_t steps = 20000;  ///< timed steps per run
    std::string threads = "1,2"; ///< thread counts to time, comma separated
    std::uint64_t seed = 42;
    int rounds = 3; ///< interleaved rounds; the table shows medians
    /// Disk assembly: "lammps" reads lammpsDirectory/dense.data (the assembly LAMMPS runs);
    /// "generated" compacts a grid assembly with the engine (as for ovals).
    std::string assembly = "lammps";
    bool versusLammps = false; ///< also run stock LAMMPS (in.bench) in every round
    /// Also run the minimal disk kernel (limit_kernel.h) beside the engine's disk rows, at each
    /// thread count, in every round.
    bool limit = false;
    std::string lammpsDirectory = resourcePath("bench/lammps");
    std::string lammpsExecutable = "lmp";
    bool scaling = false; ///< cost per grain-step at 1k to 512k grains instead
    /// The live window instead (window_bench.h): engine speed headless and in the window for
    /// `guiSteps` steps of `experiment`'s first shear (threads: the first count of `threads`),
    /// and the scene's frame time with `grains` ovals.
    bool gui = false;
    std::int64_t guiSteps = 100000;
    /// The window shows strong force chains and void cells by valence (not its default view)
    /// while the engine's slowdown is measured.
    bool guiOverlays = false;
    std::string experiment = resourcePath("experiments/quick.json");
};

/// Declares the bench options on the `bench` subcommand.
void addBenchOptions(CLI::App& command, BenchOptions& options);

/// The window bench (`--gui`), window_bench.h's runGuiBench in GUI builds; the engine bench
/// does not depend on the window, the command line hands it in (nullptr: built without it).
using WindowBench = int (*)(const BenchOptions& options);

int runBench(const BenchOptions& options, WindowBench windowBench);

} // namespace grainlab
