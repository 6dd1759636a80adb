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
    Compaction = 0,     ///< isotropic compaction to a confining pressure (saves a sample)
    Equilibration = 1,  ///< a sample at rest again under the test's friction, before its test
    Shear = 2,          ///< the drained biaxial shear test
    Done = 3,           ///< the run is finished
    ConstantVolume = 4, ///< axis 1 strained, the cell's area held (the undrained analogue)
    ConstantP = 5,      ///< axis 1 strained, sigma22 servoed to keep p
    StressPath = 6,     ///< axis 1 strained, sigma22 servoed along a linear path in sigma11
    Cyclic = 7,         ///< axis 1 strained back and forth, drained or at constant volume
    Probes = 8,         ///< small strain increments in evenly spread directions from one state
};

/// True for the kinds that are a test of a sample (its eps1 is the test's axial strain): the
/// drained shear test and the other loading paths.
bool isTestStage(StageKind kind);

/// "compaction", "equilibration", "shear", "done", "constant_volume", "constant_p",
/// "stress_path", "cyclic" or "probes" (the run file's checkpoint kind; a test's kind is the name
/// its experiment file gives it, "shear" for the drained test).
std::string stageKindName(StageKind kind);
/// The kind of a name stageKindName() gives; nullopt for any other text.
std::optional<StageKind> stageKindFromName(const std::string& name);
/// A stage as the window, the progress bar and the series' stage column name it: its kind's
/// name and its pressure, "shear 15 kPa".
std::string stageTitle(const std::string& kindName, double pressure);

} // namespace grainlab
