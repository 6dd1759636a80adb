#pragma once
// The kinds of stage an experiment plays (docs/experiment-file.md), as data: the runner reports
// the current one in RunProgress and the Snapshot, and the run file stores its name as a
// checkpoint attribute. The names below are the only place the text and the enum meet.

#include <optional>
#include <string>

namespace grainlab {

/// The values are stored as integers in the runner state of run files ("phase"): never
/// renumber them; a new test kind takes the next free value (Done stays 3).
enum class StageKind {
    Compaction = 0,    ///< isotropic compaction to a confining pressure (saves a sample)
    Equilibration = 1, ///< a sample at rest again under the test's friction, before its test
    Shear = 2,         ///< the drained biaxial shear test
    Done = 3,          ///< the run is finished
};

/// "compaction", "equilibration", "shear" or "done" (the run file's checkpoint kind).
std::string stageKindName(StageKind kind);
/// The kind of a name stageKindName() gives; nullopt for any other text.
std::optional<StageKind> stageKindFromName(const std::string& name);
/// A stage as the window, the progress bar and the series' stage column name it: its kind's
/// name and its pressure, "shear 15 kPa".
std::string stageTitle(const std::string& kindName, double pressure);

} // namespace grainlab
