#pragma once
// The study file (JSON): reads and validates it into a StudySpec (study_plan.h). Every key is
// documented in docs/study-file.md. Read with the same strict reader as experiment files: an
// unknown key, a wrong type or a value out of range is an error naming the file, the key path
// and what is allowed; nothing is guessed or clamped. Pure functions, any thread.

#include <string>

#include "grainlab/study_plan.h"

namespace grainlab {

/// Reads and validates a study file. A base experiment given as a path is read relative to the
/// study file's folder; StudySpec::sourceText holds the study with that base written inline.
/// Throws ExperimentFileError (experiment_file.h) naming the file and key.
StudySpec readStudyFile(const std::string& path);

/// Validates study text; `sourceName` names it in messages; `folder` resolves a base path.
StudySpec parseStudyText(const std::string& text, const std::string& sourceName,
                         const std::string& folder);

/// The metrics a study can decide on: every shear-test metric and the two curve errors.
std::vector<std::string> studyMetricNames();

} // namespace grainlab
