#include "bench/bench.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench/lammps_peer.h"
#include "bench/limit_kernel.h"
#include "common/progress_bar.h"
#include "grainlab/assembly.h"
#include "grainlab/measures.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/random.h"
#include "grainlab/scenes/compacted_scene.h"
#include "grainlab/simulation.h"

namespace grainlab {
namespace {

constexpr double kConfiningStress = 1e5; // [Pa]
constexpr double kAxialStrainRate = 0.2; // engineering, as LAMMPS's fix deform erate [1/s]

// ---------------------------------------------------------------------------------------------
// Assemblies

/// Loose grid -> frictionless isotropic compaction to 100 kPa by the runner's equilibrium rule
/// (the shared scene), then velocities cleared.
SimulationState compactedAssembly(int grains, double aspectRatio, std::uint64_t seed) {
    scenes::CompactedSceneSpec spec;
    spec.grains = grains;
    spec.aspectRatio = aspectRatio;
    spec.seed = seed;
    spec.pressure = kConfiningStress;
    spec.threads = 2;
    ProgressBar bar(
        fmt::format("preparing {} {}s at 100 kPa", grains, aspectRatio < 1 ? "oval" : "disk"));
    SimulationState out = scenes::compactedState(spec, [&](const scenes::CompactionProgress& p) {
        bar.update(double(p.step) / p.maxSteps,
                   fmt::format("p error {:.1f} % I_uf {:.2f} %", 100 * p.check.stressError,
                               p.check.unbalancedForce));
    });
    bar.finish();
    out.parameters = SimulationParameters{}; // the reference parameters for the timed runs
    return out;
}

/// `tiles1` x `tiles2` copies of a periodic state side by side: again a periodic state, with
/// the same contacts per grain (for the scaling table). The neighbour list is rebuilt.
SimulationState tiled(const SimulationState& base, int tiles1, int tiles2) {
    SimulationState s;
    s.shapes = base.shapes;
    s.parameters = base.parameters;
    s.axes = base.axes;
    const auto& h = base.cell;
    const std::size_t n = base.grains.size();
    s.grains.resize(n * tiles1 * tiles2);
    std::size_t k = 0;
    for (int a = 0; a < tiles1; ++a) {
        for (int b = 0; b < tiles2; ++b) {
            for (std::size_t i = 0; i < n; ++i, ++k) {
                s.grains.x1[k] = base.grains.x1[i] + h[0] * a + h[2] * b;
                s.grains.x2[k] = base.grains.x2[i] + h[1] * a + h[3] * b;
                s.grains.theta[k] = base.grains.theta[i];
                s.grains.shape[k] = base.grains.shape[i];
            }
        }
    }
    s.cell = {h[0] * tiles1, h[1] * tiles1, h[2] * tiles2, h[3] * tiles2};
    return s;
}

// ---------------------------------------------------------------------------------------------
// Timed runs

/// Heap bytes in use (glibc: arena plus mmapped blocks).
std::size_t heapInUse() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

struct RunResult {
    double grainStepsPerSecond = 0;
    double contactsPerGrain = 0; ///< 2 * contacts / grains (LAMMPS's Z)
    double pairsPerGrain = 0;    ///< neighbour-list pairs / grains (each pair counted once)
    std::int64_t rebuilds = 0;
    double bytesPerGrain = 0; ///< engine state, heap bytes per grain
    SimulationState final;    ///< for the 1-thread vs 2-thread comparison
};

/// Times `steps` steps of `kernel` (the engine's Simulation or the LimitKernel): grain-steps per
/// second, and per grain the contacts and the pairs `pairCount(kernel)` counts after them.
template <class Kernel, class PairCount>
RunResult timeSteps(Kernel& kernel, std::int64_t steps, PairCount pairCount) {
    const auto start = std::chrono::steady_clock::now();
    kernel.advance(steps);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RunResult r;
    const double n = double(kernel.grainCount());
    r.grainStepsPerSecond = n * double(steps) / seconds;
    r.contactsPerGrain = 2.0 * double(kernel.contactCount()) / n;
    r.pairsPerGrain = double(pairCount(kernel)) / n;
    return r;
}

/// Biaxial compression from `dense`: axis 1 shortened at the engineering rate 0.2 /s, axis 2
/// held at 100 kPa, mu = 0.5. Times `steps` steps (the neighbour list is built before).
RunResult timeEngine(const SimulationState& dense, int threads, std::int64_t steps,
                     bool keepState) {
    const std::size_t heapBefore = heapInUse();
    SimulationState state = dense;
    state.parameters.friction = 0.5;
    state.parameters.threads = threads;
    Simulation sim(std::move(state));
    sim.setAxisControl(0, AxisControl{AxisMode::Strain, kAxialStrainRate, dense.cell[0]});
    sim.setAxisControl(1, AxisControl{AxisMode::Stress, 0.0, kConfiningStress});
    RunResult r =
        timeSteps(sim, steps, [](const Simulation& s) { return s.stateRef().pairs.size(); });
    r.bytesPerGrain = double(heapInUse() - heapBefore) / double(sim.grainCount());
    r.rebuilds = sim.neighbourRebuilds();
    if (keepState) {
        r.final = sim.state();
    }
    return r;
}

/// The minimal disk kernel on the same work as timeEngine, but with axis 2 held (no servo).
RunResult timeLimit(const SimulationState& dense, int threads, std::int64_t steps) {
    SimulationState state = dense;
    state.parameters.friction = 0.5;
    LimitKernel kernel(state, kAxialStrainRate, threads);
    const std::int64_t rebuildsBefore = kernel.rebuilds();
    RunResult r = timeSteps(kernel, steps, [](const LimitKernel& k) { return k.pairCount(); });
    r.rebuilds = kernel.rebuilds() - rebuildsBefore + 1; // as the engine counts: the first build
    return r;
}

double median(std::vector<double> values) {
    if (values.empty()) {
        return std::nan("");
    }
    std::sort(values.begin(), values.end());
    const std::size_t m = values.size() / 2;
    return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

std::vector<int> parseThreads(const std::string& text) {
    std::vector<int> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        out.push_back(std::stoi(item));
    }
    return out;
}

/// One row of the table: an engine configuration or LAMMPS, with its result in every round.
struct Series {
    std::string name, shape;
    int threads = 1;
    std::size_t grains = 0;
    std::vector<double> rate, contacts;
    double pairsPerGrain = 0;
    std::int64_t rebuilds = 0;
    double bytesPerGrain = 0;
};

double medianRatio(const Series& a, const Series& b) {
    std::vector<double> r;
    for (std::size_t k = 0; k < std::min(a.rate.size(), b.rate.size()); ++k) {
        r.push_back(a.rate[k] / b.rate[k]);
    }
    return median(r);
}

// ---------------------------------------------------------------------------------------------

/// The same state with its grains renumbered in the order `order` (grain k of the result is
/// grain order[k]), without a neighbour list.
SimulationState renumbered(const SimulationState& s, const std::vector<std::size_t>& order) {
    SimulationState out;
    out.shapes = s.shapes;
    out.parameters = s.parameters;
    out.axes = s.axes;
    out.cell = s.cell;
    out.grains.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::size_t i = order[k];
        out.grains.x1[k] = s.grains.x1[i];
        out.grains.x2[k] = s.grains.x2[i];
        out.grains.theta[k] = s.grains.theta[i];
        out.grains.v1[k] = s.grains.v1[i];
        out.grains.v2[k] = s.grains.v2[i];
        out.grains.omega[k] = s.grains.omega[i];
        out.grains.shape[k] = s.grains.shape[i];
    }
    return out;
}

/// A random order of `n` grains (Fisher-Yates).
std::vector<std::size_t> randomOrder(std::size_t n, std::uint64_t seed) {
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) {
        order[k] = k;
    }
    Random random(seed);
    for (std::size_t k = n - 1; k > 0; --k) {
        std::swap(order[k], order[random.below(k + 1)]);
    }
    return order;
}

/// The grains in Morton (Z) order of their positions in the cell: the order a spatial sort at
/// neighbour rebuilds would keep (LAMMPS's atom_modify sort bins by space likewise).
std::vector<std::size_t> mortonOrder(const SimulationState& s) {
    const auto spread = [](std::uint32_t v) { // 16 bits to the even bits of 32
        std::uint64_t x = v & 0xffffu;
        x = (x | (x << 8)) & 0x00ff00ffu;
        x = (x | (x << 4)) & 0x0f0f0f0fu;
        x = (x | (x << 2)) & 0x33333333u;
        x = (x | (x << 1)) & 0x55555555u;
        return x;
    };
    const std::size_t n = s.grains.size();
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto f = toFractional(s.cell, s.grains.x1[i], s.grains.x2[i]);
        const auto bin = [](double v) {
            return static_cast<std::uint32_t>(std::clamp(v - std::floor(v), 0.0, 1.0) * 65535.0);
        };
        key[i] = spread(bin(f[0])) | (spread(bin(f[1])) << 1);
    }
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) {
        order[k] = k;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
    return order;
}

/// How far apart in memory a neighbour pair's grains are: the median of |i - j| over the
/// neighbour list a simulation of `s` builds.
double medianIndexGap(const SimulationState& s) {
    const Simulation sim(s);
    const PairArrays& pairs = sim.stateRef().pairs;
    std::vector<double> gaps(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        gaps[p] = std::abs(double(pairs.second[p]) - double(pairs.first[p]));
    }
    return median(gaps);
}

int runScaling(const BenchOptions& o, const std::vector<std::pair<std::string, double>>& shapes,
               const std::vector<int>& threadCounts) {
    // One compacted base of 1000 grains per shape, tiled 1x1 to 32x16: the same dense structure
    // and contacts per grain at every size, without compacting 512k grains. Every size runs the
    // same steps from its start (the same strain path, so the same contacts per grain), repeated
    // until it has done the same grain-steps as the others. Three orders of the grains: as tiled
    // (tile by tile, each tile in its generated grid's order), sorted along a Morton curve (what
    // a spatial sort gives), and shuffled (what losing the order costs).
    const std::vector<std::pair<int, int>> tilings = {{1, 1}, {4, 2}, {8, 4}, {16, 8}, {32, 16}};
    const std::size_t largest = 1000 * 32 * 16;
    const std::int64_t steps =
        std::max<std::int64_t>(200, std::int64_t(double(o.steps) * 8450.0 / double(largest)));
    fmt::print("{:<6} {:<8} {:>7} {:>8} {:>12} {:>16} {:>9} {:>14} {:>14} {:>12}\n", "shape",
               "order", "grains", "threads", "steps x runs", "ns/grain-step", "vs 8000",
               "contacts/grain", "bytes/grain", "median|i-j|");
    for (const auto& [name, aspect] : shapes) {
        const SimulationState base = compactedAssembly(1000, aspect, o.seed);
        for (const std::string order : {"tiled", "morton", "shuffled"}) {
            std::map<int, double> at8000; // ns per grain-step at 8000 grains, by threads
            for (const auto& [t1, t2] : tilings) {
                SimulationState dense = tiled(base, t1, t2);
                const std::size_t n = dense.grains.size();
                if (order == "morton") {
                    dense = renumbered(dense, mortonOrder(dense));
                } else if (order == "shuffled") {
                    dense = renumbered(dense, randomOrder(n, o.seed));
                }
                const double gap = medianIndexGap(dense);
                const std::int64_t runs =
                    std::max<std::int64_t>(1, std::llround(double(largest) / double(n)));
                for (int threads : threadCounts) {
                    std::vector<double> rates;
                    RunResult last;
                    for (int round = 0; round < o.rounds; ++round) {
                        fmt::print(stderr, "scaling: {} {} {} grains, {} thread(s), round {}/{}\n",
                                   name, order, n, threads, round + 1, o.rounds);
                        double seconds = 0;
                        for (std::int64_t r = 0; r < runs; ++r) {
                            last = timeEngine(dense, threads, steps, false);
                            seconds += double(n) * double(steps) / last.grainStepsPerSecond;
                        }
                        rates.push_back(double(n) * double(steps * runs) / seconds);
                    }
                    const double ns = 1e9 / median(rates);
                    if (n == 8000) {
                        at8000[threads] = ns;
                    }
                    const std::string ratio =
                        at8000.count(threads) ? fmt::format("{:.2f}", ns / at8000[threads]) : "";
                    fmt::print("{:<6} {:<8} {:>7} {:>8} {:>12} {:>16.2f} {:>9} {:>14.3f} {:>14.0f} "
                               "{:>12.0f}\n",
                               name, order, n, threads, fmt::format("{} x {}", steps, runs), ns,
                               ratio, last.contactsPerGrain, last.bytesPerGrain, gap);
                    std::fflush(stdout);
                }
            }
        }
    }
    return 0;
}

} // namespace

void addBenchOptions(CLI::App& command, BenchOptions& o) {
    command.add_option("--shape", o.shape, "oval, disk or both")->capture_default_str();
    command.add_option("--grains", o.grains, "grains of a generated assembly")
        ->capture_default_str();
    command.add_option("--steps", o.steps, "timed steps per run")->capture_default_str();
    command.add_option("--threads", o.threads, "thread counts, comma separated")
        ->capture_default_str();
    command.add_option("--seed", o.seed, "random seed of generated assemblies")
        ->capture_default_str();
    command.add_option("--rounds", o.rounds, "interleaved rounds (the table shows medians)")
        ->capture_default_str();
    command
        .add_option("--assembly", o.assembly,
                    "disks: lammps (dense.data, as LAMMPS runs it) or generated (compacted here)")
        ->capture_default_str();
    command.add_flag("--vs-lammps", o.versusLammps,
                     "run stock LAMMPS (lmp, in.bench) in every round and print the ratios");
    command.add_flag(
        "--limit", o.limit,
        "run the minimal disk kernel (the engine's disk physics without servo, "
        "recording or checks) beside the engine's disk rows and print engine / kernel");
    command.add_option("--lammps-dir", o.lammpsDirectory, "folder with in.bench and dense.data")
        ->capture_default_str();
    command.add_option("--lammps", o.lammpsExecutable, "LAMMPS executable")->capture_default_str();
    command.add_flag("--scaling", o.scaling,
                     "cost per grain-step at 1k to 512k grains (tiled assemblies, as tiled and "
                     "Morton-sorted and shuffled)");
    command.add_flag("--gui", o.gui,
                     "the live window instead: engine steps/s headless and in the window "
                     "(--gui-steps of --experiment's first shear, --rounds), and the scene's "
                     "frame time with --grains ovals (QPainter, and OpenGL where available)");
    command.add_option("--gui-steps", o.guiSteps, "--gui: timed steps per run")
        ->capture_default_str();
    command.add_flag("--gui-overlays", o.guiOverlays,
                     "--gui: the window shows strong force chains and void cells by valence "
                     "(the whole cell in view) while the engine's slowdown is measured, "
                     "instead "
                     "of its default view");
    command.add_option("--experiment", o.experiment, "--gui: experiment whose first test is run")
        ->capture_default_str();
}

namespace {

/// The dense assemblies of the bench, prepared once: (shape name, state).
std::vector<std::pair<std::string, SimulationState>>
denseAssemblies(const BenchOptions& o, const std::vector<std::pair<std::string, double>>& shapes) {
    std::vector<std::pair<std::string, SimulationState>> assemblies;
    for (const auto& [name, aspect] : shapes) {
        if (name == "disk" && o.assembly == "lammps") {
            const std::string path = o.lammpsDirectory + "/dense.data";
            fmt::print(stderr, "reading {}\n", path);
            assemblies.emplace_back(name, readLammpsDisks(path, SimulationParameters{}));
        } else {
            // Ovals: the LAMMPS assembly's grain count and size classes (widths 1-2 mm in 11
            // classes), compacted by the engine (frictionless, 100 kPa).
            const int grains = o.assembly == "lammps" ? 8450 : o.grains;
            assemblies.emplace_back(name, compactedAssembly(grains, aspect, o.seed));
        }
    }

    return assemblies;
}

/// The table of rates and the ratios between its rows.
void printBenchResults(const BenchOptions& o, const std::vector<Series>& series,
                       const std::vector<int>& threadCounts,
                       const std::vector<std::pair<std::string, SimulationState>>& assemblies,
                       const std::vector<int>& identical) {
    fmt::print("{:<9} {:<5} {:>6} {:>7} {:>7} {:>14} {:>11} {:>11} {:>9} {:>8} {:>8} {:>8}\n",
               "engine", "shape", "grains", "threads", "steps", "grain-steps/s", "min", "max",
               "contacts/g", "pairs/g", "rebuilds", "B/grain");
    for (const Series& s : series) {
        const auto [lo, hi] = std::minmax_element(s.rate.begin(), s.rate.end());
        const bool lammps = s.name == "LAMMPS";
        fmt::print("{:<9} {:<5} {:>6} {:>7} {:>7} {:>14.4g} {:>11.4g} {:>11.4g} {:>9.3f} {:>8} "
                   "{:>8} {:>8.0f}\n",
                   s.name, s.shape, s.grains, s.threads, o.steps, median(s.rate), *lo, *hi,
                   median(s.contacts),
                   lammps ? std::string("-") : fmt::format("{:.3f}", s.pairsPerGrain),
                   lammps ? std::string("-") : std::to_string(s.rebuilds), s.bytesPerGrain);
    }
    fmt::print("\nratios (median over rounds of the per-round ratio; {} round(s), {} steps):\n",
               o.rounds, o.steps);
    const auto find = [&](const std::string& name, const std::string& shape,
                          int threads) -> const Series* {
        for (const Series& s : series) {
            if (s.name == name && s.shape == shape && s.threads == threads) {
                return &s;
            }
        }
        return nullptr;
    };
    const Series* lammps = find("LAMMPS", "disk", 1);
    for (const Series& s : series) {
        if (s.name != "GrainLab") {
            continue;
        }
        if (lammps != nullptr) {
            fmt::print("  {} {} thread(s) / LAMMPS 1 core: {:.2f}x\n", s.shape, s.threads,
                       medianRatio(s, *lammps));
        }
        if (s.threads != threadCounts.front()) {
            if (const Series* one = find("GrainLab", s.shape, threadCounts.front())) {
                fmt::print("  {} {} threads / {} thread(s): {:.2f}x\n", s.shape, s.threads,
                           threadCounts.front(), medianRatio(s, *one));
            }
        }
        if (const Series* limit = find("limit", s.shape, s.threads)) {
            fmt::print("  {} {} thread(s) / limit kernel {} thread(s): {:.2f} (the engine at "
                       "{:.0f} % of the minimal kernel's speed)\n",
                       s.shape, s.threads, s.threads, medianRatio(s, *limit),
                       100.0 * medianRatio(s, *limit));
        }
    }
    for (const Series& s : series) {
        if (s.name == "limit" && s.threads != threadCounts.front()) {
            if (const Series* one = find("limit", s.shape, threadCounts.front())) {
                fmt::print("  limit kernel {} threads / {} thread(s): {:.2f}x\n", s.threads,
                           threadCounts.front(), medianRatio(s, *one));
            }
        }
    }
    for (int threads : threadCounts) {
        const Series* disk = find("GrainLab", "disk", threads);
        const Series* oval = find("GrainLab", "oval", threads);
        if (disk != nullptr && oval != nullptr) {
            const double perGrainStep = medianRatio(*disk, *oval);
            fmt::print("  oval cost / disk cost per grain-step, {} thread(s): {:.2f} (per "
                       "neighbour pair: {:.2f})\n",
                       threads, perGrainStep,
                       perGrainStep * disk->pairsPerGrain / oval->pairsPerGrain);
        }
    }
    if (threadCounts.size() > 1) {
        for (std::size_t a = 0; a < assemblies.size(); ++a) {
            fmt::print("  {}: final states for threads {} bit-identical: {}\n", assemblies[a].first,
                       o.threads, identical[a] ? "yes" : "NO");
        }
    }
}

} // namespace

int runBench(const BenchOptions& o, WindowBench windowBench) {
    std::vector<std::pair<std::string, double>> shapes;
    if (o.shape == "disk" || o.shape == "both") {
        shapes.emplace_back("disk", 1.0);
    }
    if (o.shape == "oval" || o.shape == "both") {
        shapes.emplace_back("oval", 0.6);
    }
    if (shapes.empty()) {
        fmt::print(stderr, "bench: --shape {}: allowed values are oval, disk, both\n", o.shape);
        return 2;
    }
    if (o.assembly != "lammps" && o.assembly != "generated") {
        fmt::print(stderr, "bench: --assembly {}: allowed values are lammps, generated\n",
                   o.assembly);
        return 2;
    }
    if (o.rounds < 1 || o.steps < 1 || o.guiSteps < 1) {
        fmt::print(stderr, "bench: --rounds, --steps and --gui-steps must be >= 1\n");
        return 2;
    }
    if (o.guiOverlays && !o.gui) {
        fmt::print(stderr, "bench: --gui-overlays belongs to the window bench: add --gui\n");
        return 2;
    }
    const std::vector<int> threadCounts = parseThreads(o.threads);
    if (o.gui) {
        if (windowBench == nullptr) {
            fmt::print(stderr, "bench: --gui: this grainlab was built without the window "
                               "(GRAINLAB_BUILD_GUI=OFF)\n");
            return 2;
        }
        return windowBench(o);
    }
    if (o.scaling) {
        return runScaling(o, shapes, threadCounts);
    }
    if (o.versusLammps && !haveExecutable(o.lammpsExecutable)) {
        fmt::print(stderr,
                   "bench: --vs-lammps: the LAMMPS executable `{}` was not found. On Debian 12: "
                   "apt-get update && apt-get install -y lammps   (provides `lmp`)\n",
                   o.lammpsExecutable);
        return 2;
    }

    if (o.limit && o.shape == "oval") {
        fmt::print(stderr,
                   "bench: --limit: the minimal kernel runs disks: use --shape disk or both\n");
        return 2;
    }

    const auto assemblies = denseAssemblies(o, shapes);

    // Rows in the order they run within a round: ours 1 thread, the limit kernel 1 thread,
    // LAMMPS, ours 2 threads, the limit kernel 2 threads, ...
    enum class Runner { Engine, Lammps, Limit };
    struct Planned {
        std::size_t assembly;
        int threads;
        Runner runner;
    };
    std::vector<Series> series;
    std::vector<Planned> plan;
    for (std::size_t a = 0; a < assemblies.size(); ++a) {
        for (std::size_t t = 0; t < threadCounts.size(); ++t) {
            plan.push_back({a, threadCounts[t], Runner::Engine});
            if (o.limit && assemblies[a].first == "disk") {
                plan.push_back({a, threadCounts[t], Runner::Limit});
            }
            if (a == 0 && t == 0 && o.versusLammps) {
                plan.push_back({a, 1, Runner::Lammps});
            }
        }
    }
    for (const Planned& k : plan) {
        Series s;
        s.shape = k.runner == Runner::Lammps ? "disk" : assemblies[k.assembly].first;
        s.threads = k.threads;
        s.grains = assemblies[k.assembly].second.grains.size();
        s.name = k.runner == Runner::Lammps  ? "LAMMPS"
                 : k.runner == Runner::Limit ? "limit"
                                             : "GrainLab";
        series.push_back(s);
    }
    std::vector<int> identical(assemblies.size(), 1);
    for (int round = 0; round < o.rounds; ++round) {
        std::vector<SimulationState> firstFinal(assemblies.size());
        for (std::size_t k = 0; k < plan.size(); ++k) {
            const std::size_t a = plan[k].assembly;
            const int threads = plan[k].threads;
            Series& s = series[k];
            fmt::print(stderr, "round {}/{}: {} {} {} thread(s), {} steps\n", round + 1, o.rounds,
                       s.name, s.shape, s.threads, o.steps);
            if (plan[k].runner == Runner::Limit) {
                const RunResult r = timeLimit(assemblies[a].second, threads, o.steps);
                s.rate.push_back(r.grainStepsPerSecond);
                s.contacts.push_back(r.contactsPerGrain);
                s.rebuilds = r.rebuilds;
                s.pairsPerGrain = r.pairsPerGrain;
                continue;
            }
            if (plan[k].runner == Runner::Lammps) {
                const LammpsResult r = runLammps(o.lammpsDirectory, o.lammpsExecutable, o.steps);
                s.rate.push_back(r.grainStepsPerSecond);
                s.contacts.push_back(r.contactsPerGrain);
                continue;
            }
            RunResult r = timeEngine(assemblies[a].second, threads, o.steps, true);
            s.rate.push_back(r.grainStepsPerSecond);
            s.contacts.push_back(r.contactsPerGrain);
            s.rebuilds = r.rebuilds;
            s.pairsPerGrain = r.pairsPerGrain;
            s.bytesPerGrain = r.bytesPerGrain;
            if (firstFinal[a].grains.size() == 0) {
                firstFinal[a] = std::move(r.final);
            } else if (!identicalDynamics(firstFinal[a], r.final)) {
                identical[a] = 0;
            }
        }
    }

    printBenchResults(o, series, threadCounts, assemblies, identical);
    std::fflush(stdout);
    return 0;
}

} // namespace grainlab
