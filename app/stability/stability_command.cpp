#include "stability/stability_command.h"

#include <atomic>
#include <csignal>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "cli/atomic_file.h"
#include "cli/progress_bar.h"
#include "study/job_list.h"
#include "study/process_pool.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> stopRequested{false};

extern "C" void onStabilityInterrupt(int) {
    stopRequested.store(true);
}

/// Creates the map folder, or checks that an existing one holds this very preset.
void prepareFolder(const fs::path& dir, const StabilityMapSpec& spec) {
    const fs::path preset = dir / "stability.json";
    if (fs::exists(dir)) {
        if (!fs::is_directory(dir)) {
            throw std::runtime_error(
                fmt::format("--out {}: exists and is not a folder", dir.string()));
        }
        if (!fs::exists(preset)) {
            if (!fs::is_empty(dir)) {
                throw std::runtime_error(
                    fmt::format("--out {}: the folder is not empty and holds no stability map (no "
                                "stability.json); give a new or empty folder",
                                dir.string()));
            }
        } else if (readWholeFile(preset.string()) != spec.sourceText) {
            throw std::runtime_error(fmt::format(
                "--out {}: the folder holds a different map (its stability.json differs from "
                "{}); give another folder, or continue that map with its own stability.json",
                dir.string(), spec.sourcePath));
        }
    }
    for (const char* sub : {"cells", "logs"}) {
        fs::create_directories(dir / sub);
    }
    if (!fs::exists(preset)) {
        writeFileAtomically(preset.string(), spec.sourceText);
    }
}

std::vector<std::string> cellArguments(const std::string& grainlab, const fs::path& dir,
                                       const std::string& id) {
    return {grainlab, "stability", "cell", dir.string(), "--cell", id, "--quiet"};
}

std::size_t collect(const fs::path& dir, const StabilityMapSpec& spec, bool quiet,
                    const StabilityFigureWriter& figures) {
    std::vector<StabilityCellResult> results;
    for (const StabilityCell& cell : stabilityCells(spec)) {
        const fs::path file = dir / "cells" / (cell.id + ".json");
        if (fs::exists(file)) {
            results.push_back(parseCellResult(readWholeFile(file.string()), file.string()));
        }
    }
    writeFileAtomically((dir / "limits.csv").string(), limitsCsv(results));
    writeFileAtomically((dir / "accuracy.csv").string(), accuracyCsv(results));
    if (figures && !results.empty()) {
        const std::string error = figures(dir.string(), spec, results);
        if (!error.empty()) {
            throw std::runtime_error("writing the stability map's figures: " + error);
        }
    }
    if (!quiet) {
        fmt::print("grainlab stability: {} of {} cells done; limits in {}\n", results.size(),
                   stabilityCells(spec).size(), (dir / "limits.csv").string());
    }
    return results.size();
}

} // namespace

std::string stabilityPresetPath(const std::string& name) {
    return (fs::path(GRAINLAB_SOURCE_DIR) / "resources" / "stability" / (name + ".json")).string();
}

int runStabilityCommand(const StabilityOptions& options) {
    if (options.preset.empty() == options.presetFile.empty()) {
        throw std::runtime_error("grainlab stability: give either --preset NAME or a preset file");
    }
    const std::string path =
        options.preset.empty() ? options.presetFile : stabilityPresetPath(options.preset);
    const StabilityMapSpec spec = readStabilityPreset(path);
    const fs::path dir = fs::absolute(options.out).lexically_normal();
    prepareFolder(dir, spec);
    const std::string grainlab = fs::absolute(options.grainlab).string();
    const std::vector<StabilityCell> cells = stabilityCells(spec);

    if (options.emit == "slurm" || options.emit == "parallel") {
        std::vector<std::vector<std::string>> commands;
        for (const StabilityCell& c : cells) {
            commands.push_back(cellArguments(grainlab, dir, c.id));
        }
        const bool slurm = options.emit == "slurm";
        const fs::path file = dir / (slurm ? "stability.slurm" : "jobs.txt");
        const std::string comment = fmt::format(
            "The cells of stability map {} as a Slurm job array: one task per cell.\n"
            "Submit with: sbatch stability.slurm    Collect when all are done with:\n"
            "  {} stability collect {}\n"
            "A finished cell is not redone: resubmitting runs only the cells still missing.",
            spec.name, shellQuote(grainlab), shellQuote(dir.string()));
        writeFileAtomically(file.string(),
                            slurm ? slurmArrayScript("stability-" + spec.name, comment,
                                                     (dir / "logs").string(), commands, 1)
                                  : commandJobList(commands));
        fmt::print("grainlab stability: {} cells written as {}\n", cells.size(), file.string());
        if (slurm) {
            fmt::print("Submit with: sbatch {}\n", file.string());
        } else {
            fmt::print("Run with: parallel --jobs N < {}\n", file.string());
        }
        fmt::print("Then collect with: {} stability collect {}\n", grainlab, dir.string());
        return 0;
    }
    if (!options.emit.empty()) {
        throw std::runtime_error(fmt::format("--emit {}: must be slurm or parallel", options.emit));
    }

    std::vector<PoolJob> jobs;
    std::vector<std::size_t> jobCell;
    std::size_t doneBefore = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (fs::exists(dir / "cells" / (cells[i].id + ".json"))) {
            ++doneBefore;
            continue;
        }
        jobs.push_back({cellArguments(grainlab, dir, cells[i].id),
                        (dir / "logs" / (cells[i].id + ".log")).string(), 1});
        jobCell.push_back(i);
    }
    const int slots = options.jobs > 0 ? options.jobs : processorCount();
    if (!options.quiet) {
        fmt::print("grainlab stability {}: {} cells, {} done, at most {} at a time; folder {}\n",
                   spec.name, cells.size(), doneBefore, slots, dir.string());
    }
    stopRequested.store(false);
    auto previous = std::signal(SIGINT, onStabilityInterrupt);
    auto previousTerm = std::signal(SIGTERM, onStabilityInterrupt);
    ProgressBar bar(fmt::format("stability {} ({} cells)", spec.name, cells.size()));
    std::vector<std::string> failed;
    const auto total = double(cells.size());
    ProcessPool pool(slots, options.jobs > 0 ? 1 << 20 : processorCount());
    pool.run(
        jobs,
        [&](std::size_t job, const PoolResult& r) {
            if (!r.succeeded() && !stopRequested.load()) {
                failed.push_back(fmt::format(
                    "{} (exit {}{}; log {})", cells[jobCell[job]].id, r.exitStatus,
                    r.signal ? fmt::format(", signal {}", r.signal) : "", jobs[job].logPath));
            }
        },
        [&](std::size_t ended, std::size_t running) {
            if (!options.quiet) {
                bar.update(double(doneBefore + ended) / total,
                           fmt::format("{} done, {} running", doneBefore + ended, running));
            }
        },
        &stopRequested);
    if (!options.quiet) {
        bar.finish();
    }
    std::signal(SIGINT, previous);
    std::signal(SIGTERM, previousTerm);
    collect(dir, spec, options.quiet, options.figures);
    if (stopRequested.load()) {
        fmt::print(stderr,
                   "grainlab stability: interrupted; the cells done are kept. Continue with the "
                   "same command.\n");
        return 130;
    }
    if (!failed.empty()) {
        fmt::print(stderr, "grainlab stability: {} cell(s) failed:\n", failed.size());
        for (const std::string& f : failed) {
            fmt::print(stderr, "  {}\n", f);
        }
        return 1;
    }
    return 0;
}

int collectStabilityCommand(const std::string& folder, bool quiet,
                            const StabilityFigureWriter& figures) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const fs::path preset = dir / "stability.json";
    if (!fs::exists(preset)) {
        throw std::runtime_error(fmt::format(
            "stability collect {}: no stability.json: not a stability map folder", dir.string()));
    }
    const StabilityMapSpec spec = readStabilityPreset(preset.string());
    const std::size_t done = collect(dir, spec, quiet, figures);
    return done == stabilityCells(spec).size() ? 0 : 3;
}

} // namespace grainlab
