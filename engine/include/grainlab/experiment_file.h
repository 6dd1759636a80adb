#pragma once
// The experiment file (JSON, SI units): reads and validates it into an ExperimentConfig. Every
// key is documented in docs/experiment-file.md. Nothing is guessed or clamped: an unknown key, a
// missing required key, a wrong type or a value out of range is an ExperimentFileError that
// names the file, the key path, the value and what is allowed. Called once before a run, on the
// caller's thread (the CLI's main thread or the GUI's thread when a file is opened); pure
// functions, safe on any thread.

#include <stdexcept>
#include <string>
#include <vector>

#include "grainlab/experiment.h"

namespace grainlab {

/// A bad experiment file. what() reads like
/// `reference.json: grains.aspect_ratio = 1.5: must be a number in (0, 1]`.
class ExperimentFileError : public std::runtime_error {
public:
    ExperimentFileError(std::string file, std::string keyPath, const std::string& message);
    std::string file;    ///< the file (or source name) at fault
    std::string keyPath; ///< dotted key path, e.g. "grains.aspect_ratio" ("" for the whole file)
};

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
