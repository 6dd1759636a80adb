#include "stability/stability_command.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "common/job_list.h"
#include "common/pool_command.h"
#include "common/resources.h"
#include "grainlab/strict_json.h"
#include "stability/map_point_command.h"

namespace grainlab {

namespace fs = std::filesystem;

namespace {

/// Creates the map folder, or checks that an existing one holds this very preset.
void prepareFolder(const fs::path& dir, const std::string& sourceText,
                   const std::string& sourcePath) {
    preparePoolFolder({dir, "stability.json", "stability map", "map", {"cells", "logs"}},
                      sourceText, sourcePath);
}

std::vector<std::string> cellArguments(const std::string& grainlab, const fs::path& dir,
                                       const std::string& id) {
    return {grainlab, "stability", "cell", dir.string(), "--cell", id, "--quiet"};
}

/// The results of the cells done in the map folder `dir` (each cells/<id>.json there), in the
/// order of `cells`, read with `parse`.
template <class Cell, class Result>
std::vector<Result> cellResultsDone(const fs::path& dir, const std::vector<Cell>& cells,
                                    Result (*parse)(const std::string&, const std::string&)) {
    std::vector<Result> results;
    for (const Cell& cell : cells) {
        const fs::path file = dir / "cells" / (cell.id + ".json");
        if (fs::exists(file)) {
            results.push_back(parse(readWholeFile(file.string()), file.string()));
        }
    }
    return results;
}

/// Draws the figures of the cells done with `figures` (when given and any cell is done); throws
/// naming the `map` when that fails.
template <class FigureWriter, class Spec, class Result>
void drawFigures(const FigureWriter& figures, const fs::path& dir, const Spec& spec,
                 const std::vector<Result>& results, const std::string& map) {
    if (figures && !results.empty()) {
        const std::string error = figures(dir.string(), spec, results);
        if (!error.empty()) {
            throw std::runtime_error("writing the " + map + " map's figures: " + error);
        }
    }
}

std::size_t collectTimeStep(const fs::path& dir, const StabilityMapSpec& spec, bool quiet,
                            const StabilityFigureWriter& figures) {
    const std::vector<StabilityCellResult> results =
        cellResultsDone(dir, stabilityCells(spec), parseCellResult);
    writeFileAtomically((dir / "limits.csv").string(), limitsCsv(results));
    writeFileAtomically((dir / "accuracy.csv").string(), accuracyCsv(results));
    drawFigures(figures, dir, spec, results, "stability");
    if (!quiet) {
        fmt::print("grainlab stability: {} of {} cells done; limits in {}\n", results.size(),
                   stabilityCells(spec).size(), (dir / "limits.csv").string());
    }
    return results.size();
}

std::size_t collectServo(const fs::path& dir, const ServoMapSpec& spec, bool quiet,
                         const ServoFigureWriter& figures) {
    const std::vector<ServoCellResult> results =
        cellResultsDone(dir, servoCells(spec), parseServoCellResult);
    writeFileAtomically((dir / "servo_limits.csv").string(), servoLimitsCsv(spec, results));
    writeFileAtomically((dir / "servo_runs.csv").string(), servoRunsCsv(results));
    drawFigures(figures, dir, spec, results, "servo");
    if (!quiet) {
        fmt::print("grainlab stability: {} of {} cells done; largest stable gains in {}\n",
                   results.size(), servoCells(spec).size(), (dir / "servo_limits.csv").string());
    }
    return results.size();
}

/// A map made of cells, whatever its kind: its name, its cells' ids and how its tables are
/// written from the cells done (returns how many are).
struct CellMap {
    std::string name;
    std::vector<std::string> ids;
    std::function<std::size_t(const fs::path& dir, bool quiet)> collect;
};

/// The ids of a map's cells, in the map's order.
template <class Cell>
std::vector<std::string> cellIds(const std::vector<Cell>& cells) {
    std::vector<std::string> ids;
    for (const Cell& c : cells) {
        ids.push_back(c.id);
    }
    return ids;
}

/// The CellMap of a map of `cells` read as `spec`, whose tables `collect` writes (with
/// `figures`).
template <class Spec, class Cell, class FigureWriter>
CellMap cellMap(const Spec& spec, const std::vector<Cell>& cells,
                std::size_t (*collect)(const fs::path&, const Spec&, bool, const FigureWriter&),
                const FigureWriter& figures) {
    return {spec.name, cellIds(cells), [spec, collect, figures](const fs::path& d, bool quiet) {
                return collect(d, spec, quiet, figures);
            }};
}

CellMap cellMapOf(const fs::path& dir, const std::string& kind, const std::string& path,
                  const StabilityFigureWriter& figures, const ServoFigureWriter& servoFigures) {
    if (kind == "servo") {
        const ServoMapSpec spec = readServoPreset(path);
        return cellMap(spec, servoCells(spec), collectServo, servoFigures);
    }
    if (kind != "time_step") {
        throw std::runtime_error(fmt::format(
            "stability {}: a {} map runs in one process and has no cells; run it again with "
            "grainlab stability",
            dir.string(), kind));
    }
    const StabilityMapSpec spec = readStabilityPreset(path);
    return cellMap(spec, stabilityCells(spec), collectTimeStep, figures);
}

/// The kind of the map in a folder (its stability.json).
std::string folderKind(const fs::path& dir, const std::string& what) {
    const fs::path preset = dir / "stability.json";
    if (!fs::exists(preset)) {
        throw std::runtime_error(fmt::format("stability {} {}: no stability.json: not a stability "
                                             "map folder",
                                             what, dir.string()));
    }
    return stabilityPresetKind(readWholeFile(preset.string()), preset.string());
}

/// The geometry map, in this process: geometry.csv, geometry_limits.csv and the figure.
int runGeometryMap(const StabilityOptions& options, const fs::path& dir, const std::string& path) {
    if (!options.emit.empty()) {
        throw std::runtime_error(fmt::format(
            "--emit {}: a geometry map runs in one process (seconds to minutes); run it without "
            "--emit",
            options.emit));
    }
    const GeometryMapSpec spec = readGeometryPreset(path);
    const auto start = std::chrono::steady_clock::now();
    if (!options.quiet) {
        fmt::print("grainlab stability {}: the contact-geometry map, {} aspect ratios x {} size "
                   "ratios x {} overlaps x {} pairs; folder {}\n",
                   spec.name, spec.aspectRatios.size(), spec.sizeRatios.size(),
                   spec.overlaps.size(), spec.pairs, dir.string());
    }
    const std::vector<GeometryLevel> levels = measureGeometryMap(spec);
    const double guard = StabilityParameters{}.maxOverlapFraction;
    writeFileAtomically((dir / "geometry.csv").string(), geometryCsv(levels));
    writeFileAtomically((dir / "geometry_limits.csv").string(),
                        geometryLimitsCsv(geometryLines(spec, levels), guard));
    if (options.geometryFigures) {
        const std::string error = options.geometryFigures(dir.string(), spec, levels);
        if (!error.empty()) {
            throw std::runtime_error("writing the geometry map's figures: " + error);
        }
    }
    if (!options.quiet) {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (const GeometryLine& l : geometryLines(spec, levels)) {
            const double engine = l.departureStart[int(GeometryKernel::Engine)];
            fmt::print("  eta {}: {} (the overlap guard is at {} of the smaller width)\n",
                       l.aspectRatio,
                       engine > 0 ? fmt::format("the engine departs from the exact overlap from "
                                                "{} of the smaller width",
                                                engine)
                                  : fmt::format("no departure up to {} of the smaller width",
                                                l.largestMeasured),
                       guard);
        }
        fmt::print("grainlab stability: done in {:.1f} s; tables in {}\n", seconds,
                   (dir / "geometry_limits.csv").string());
    }
    return 0;
}

} // namespace

std::string stabilityPresetPath(const std::string& name) {
    return resourcePath("stability/" + name + ".json");
}

int runStabilityCommand(const StabilityOptions& options) {
    if (options.preset.empty() == options.presetFile.empty()) {
        throw std::runtime_error("grainlab stability: give either --preset NAME or a preset file");
    }
    const std::string path =
        options.preset.empty() ? options.presetFile : stabilityPresetPath(options.preset);
    const std::string text = readInputFile(path, "stability preset");
    const std::string kind = stabilityPresetKind(text, path);
    const fs::path dir = fs::absolute(options.out).lexically_normal();
    if (kind == "geometry") {
        readGeometryPreset(path); // refuse a bad preset before making the folder
        prepareFolder(dir, text, path);
        return runGeometryMap(options, dir, path);
    }
    const CellMap map = cellMapOf(dir, kind, path, options.figures, options.servoFigures);
    prepareFolder(dir, text, path);
    const std::string grainlab = fs::absolute(options.grainlab).string();
    const std::vector<std::string>& cells = map.ids;

    if (options.emit == "slurm" || options.emit == "parallel") {
        std::vector<std::vector<std::string>> commands;
        for (const std::string& id : cells) {
            commands.push_back(cellArguments(grainlab, dir, id));
        }
        const bool slurm = options.emit == "slurm";
        const fs::path file = dir / (slurm ? "stability.slurm" : "jobs.txt");
        const std::string comment = fmt::format(
            "The cells of stability map {} as a Slurm job array: one task per cell.\n"
            "Submit with: sbatch stability.slurm    Collect when all are done with:\n"
            "  {} stability collect {}\n"
            "A finished cell is not redone: resubmitting runs only the cells still missing.",
            map.name, shellQuote(grainlab), shellQuote(dir.string()));
        writeFileAtomically(file.string(),
                            slurm ? slurmArrayScript("stability-" + map.name, comment,
                                                     (dir / "logs").string(), commands, 1)
                                  : commandJobList(commands));
        printEmittedJobs(
            "grainlab stability", cells.size(), "cells", file.string(), slurm,
            fmt::format("Then collect with: {} stability collect {}", grainlab, dir.string()));
        return 0;
    }
    if (!options.emit.empty()) {
        throw std::runtime_error(fmt::format("--emit {}: must be slurm or parallel", options.emit));
    }

    std::vector<PoolJob> jobs;
    std::vector<std::string> jobNames;
    std::size_t doneBefore = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (fs::exists(dir / "cells" / (cells[i] + ".json"))) {
            ++doneBefore;
            continue;
        }
        jobs.push_back({cellArguments(grainlab, dir, cells[i]),
                        (dir / "logs" / (cells[i] + ".log")).string(), 1});
        jobNames.push_back(cells[i]);
    }
    const int slots = poolSlots(options.jobs);
    if (!options.quiet) {
        fmt::print("grainlab stability {}: {} cells, {} done, at most {} at a time; folder {}\n",
                   map.name, cells.size(), doneBefore, slots, dir.string());
    }
    const PoolOutcome outcome =
        runPoolJobs(jobs, jobNames, options.jobs, doneBefore, cells.size(),
                    fmt::format("stability {} ({} cells)", map.name, cells.size()), options.quiet);
    map.collect(dir, options.quiet);
    return poolExitStatus(outcome, "grainlab stability",
                          "grainlab stability: interrupted; the cells done are kept. Continue "
                          "with the same command.",
                          "cell(s)");
}

int collectStabilityCommand(const std::string& folder, bool quiet,
                            const StabilityFigureWriter& figures,
                            const ServoFigureWriter& servoFigures) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const std::string kind = folderKind(dir, "collect");
    const CellMap map =
        cellMapOf(dir, kind, (dir / "stability.json").string(), figures, servoFigures);
    const std::size_t done = map.collect(dir, quiet);
    return done == map.ids.size() ? 0 : 3;
}

int runStabilityMapCell(const std::string& folder, const std::string& cellId, bool quiet) {
    const fs::path dir = fs::absolute(folder).lexically_normal();
    const std::string kind = folderKind(dir, "cell");
    if (kind == "servo") {
        return runServoCellCommand(dir.string(), readServoPreset((dir / "stability.json").string()),
                                   cellId, quiet);
    }
    if (kind == "time_step") {
        return runStabilityCellCommand(folder, cellId, quiet);
    }
    throw std::runtime_error(fmt::format(
        "stability cell {}: a {} map runs in one process and has no cells", dir.string(), kind));
}

} // namespace grainlab
