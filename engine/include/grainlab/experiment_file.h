#pragma once
// The experiment file (JSON, SI units): reads and validates it, through the strict reader of
// strict_json.h, into an ExperimentConfig. Every
// key is documented in docs/experiment-file.md. Nothing is guessed or clamped: an unknown key, a
// missing required key, a wrong type or a value out of range is an ExperimentFileError that
// names the file, the key path, the value and what is allowed. Called once before a run, on the
// caller's thread (the CLI's main thread or the GUI's thread when a file is opened); pure
// functions, safe on any thread.

#include <string>
#include <vector>

#include "grainlab/experiment.h"
#include "grainlab/strict_json.h"

namespace grainlab {

/// A bad experiment file (names the file and the key path; see strict_json.h).
using ExperimentFileError = JsonFileError;

/// Reads and validates an experiment file. sourcePath is `path`, sourceText the file's text.
ExperimentConfig readExperimentFile(const std::string& path);

/// Validates experiment text; `sourceName` names it in error messages and becomes sourcePath.
ExperimentConfig parseExperimentText(const std::string& text, const std::string& sourceName);

/// The file's rule for shear.pressures, for whoever edits the list (the window): each one of the
/// compaction pressures [Pa], listed once. Returns "" when `shear` keeps it; else what
/// shear[index] must be, as the file's errors say it ("one of the compaction pressures (...)").
std::string shearPressureRule(const std::vector<double>& compaction,
                              const std::vector<double>& shear, std::size_t& index);

} // namespace grainlab
