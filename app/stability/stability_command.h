#pragma once
// `grainlab stability [--preset NAME | FILE] --out DIR`: the stability maps (docs/stability.md).
// The preset's "kind" names the map: the time step of the explicit integration (the default),
// the servo ("servo", servo_map.h) or the contact geometry ("geometry", geometry_map.h). Every
// map point of a time-step or servo map is one `grainlab stability cell` process
// (map_point_command.h) run through the common local pool (common/process_pool.h), with one
// progress bar for the map; each writes DIR/cells/<id>.json atomically, so a killed map resumes
// with the same command and redoes no finished map point. `--emit slurm|parallel` writes the map
// points as a Slurm job array or a GNU parallel job list instead (common/job_list.h); `grainlab
// stability collect DIR` writes the tables (limits.csv and accuracy.csv; servo_limits.csv and
// servo_runs.csv) and, in GUI builds, the figures. The geometry map is cheap and runs in this
// process. Main thread.

#include <functional>
#include <string>
#include <vector>

#include "grainlab/geometry_map.h"
#include "grainlab/servo_map.h"
#include "grainlab/stability_map.h"

namespace grainlab {

/// Writes a map's figures into its folder; returns "" or what went wrong (GUI builds).
using StabilityFigureWriter = std::function<std::string(
    const std::string& folder, const StabilityMapSpec&, const std::vector<StabilityCellResult>&)>;

/// Writes a servo map's figures into its folder; returns "" or what went wrong (GUI builds).
using ServoFigureWriter = std::function<std::string(const std::string& folder, const ServoMapSpec&,
                                                    const std::vector<ServoCellResult>&)>;
/// Writes a geometry map's figures into its folder; returns "" or what went wrong.
using GeometryFigureWriter = std::function<std::string(
    const std::string& folder, const GeometryMapSpec&, const std::vector<GeometryLevel>&)>;

struct StabilityOptions {
    std::string presetFile; ///< a preset file, or
    std::string preset;     ///< a preset name under resources/stability/
    std::string out;        ///< the map folder
    int jobs = 0;           ///< cells at once; 0: as many as the processors
    std::string emit;       ///< "", "slurm" or "parallel"
    bool quiet = false;
    std::string grainlab;          ///< this executable, for the cells' commands
    StabilityFigureWriter figures; ///< writes figures/ when set
    ServoFigureWriter servoFigures;
    GeometryFigureWriter geometryFigures;
};

/// The preset file of a preset name (resources/stability/NAME.json of the source tree).
std::string stabilityPresetPath(const std::string& name);

int runStabilityCommand(const StabilityOptions& options);

/// `grainlab stability collect DIR`: the tables of the cells done (exit status 0 when all are,
/// 3 when some are not yet). A geometry map has no cells to collect (refused).
int collectStabilityCommand(const std::string& folder, bool quiet,
                            const StabilityFigureWriter& figures = {},
                            const ServoFigureWriter& servoFigures = {});

/// `grainlab stability cell DIR --cell ID` for a map of any kind with cells.
int runStabilityMapCell(const std::string& folder, const std::string& cellId, bool quiet);

} // namespace grainlab
