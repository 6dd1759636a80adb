#pragma once
// `grainlab stability [--preset NAME | FILE] --out DIR`: the stability map of the explicit
// integration (docs/stability.md). Every cell of the preset is one `grainlab stability cell`
// process run through the study's local pool (study/process_pool.h), with one progress bar for
// the map; each writes DIR/cells/<id>.json atomically, so a killed map resumes with the same
// command and redoes no finished cell. `--emit slurm|parallel` writes the cells as a Slurm job
// array or a GNU parallel job list instead (study/job_list.h); `grainlab stability collect DIR`
// writes limits.csv, accuracy.csv and, in GUI builds, the heat maps. Main thread.

#include <functional>
#include <string>
#include <vector>

#include "grainlab/stability_map.h"

namespace grainlab {

/// Writes a map's figures into its folder; returns "" or what went wrong (GUI builds).
using StabilityFigureWriter = std::function<std::string(
    const std::string& folder, const StabilityMapSpec&, const std::vector<StabilityCellResult>&)>;

struct StabilityOptions {
    std::string presetFile; ///< a preset file, or
    std::string preset;     ///< a preset name under resources/stability/
    std::string out;        ///< the map folder
    int jobs = 0;           ///< cells at once; 0: as many as the processors
    std::string emit;       ///< "", "slurm" or "parallel"
    bool quiet = false;
    std::string grainlab;          ///< this executable, for the cells' commands
    StabilityFigureWriter figures; ///< writes figures/ when set
};

/// The preset file of a preset name (resources/stability/NAME.json of the source tree).
std::string stabilityPresetPath(const std::string& name);

int runStabilityCommand(const StabilityOptions& options);

/// `grainlab stability collect DIR`: limits.csv and accuracy.csv of the cells done (exit
/// status 0 when all are, 3 when some are not yet).
int collectStabilityCommand(const std::string& folder, bool quiet,
                            const StabilityFigureWriter& figures = {});

} // namespace grainlab
