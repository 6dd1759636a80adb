#pragma once
// Where a run started in the window is written: a folder the user picked, or by default a new
// dated folder under the runs folder, e.g. "~/GrainLab runs/2026-12-01 20-31-05 quick/"
// (GRAINLAB_RUNS_DIR, when set, replaces "~/GrainLab runs"). A run never overwrites another:
// the folder is claimed by creating it, atomically; a picked folder that already holds files is
// refused, and a dated name already taken gets " (2)", " (3)", … appended.
// defaultRunsFolder() and datedRunFolder() only compute names (GUI thread); claimRunFolder()
// creates the folder and is called on the engine's worker thread, just before the run file.

#include <string>

#include <QDateTime>
#include <QString>

namespace grainlab::ui {

/// "$GRAINLAB_RUNS_DIR", or "<home>/GrainLab runs".
QString defaultRunsFolder();

/// "<runsFolder>/<yyyy-MM-dd HH-mm-ss> <experiment name>" (characters a folder name cannot
/// hold in the name replaced by '_').
QString datedRunFolder(const QString& runsFolder, const QString& experimentName,
                       const QDateTime& when);

/// Creates `folder` (and its parents) for a new run and returns the folder created. With
/// `pickFreeName`, a folder that exists already is left alone and the first free "<folder> (n)"
/// is taken instead; without, an existing folder is accepted only when it is empty. Throws
/// std::runtime_error naming the folder when it cannot be had.
std::string claimRunFolder(const std::string& folder, bool pickFreeName);

} // namespace grainlab::ui
