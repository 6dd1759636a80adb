#pragma once
// The experiment as edited in the window's Parameters tab, as experiment-file text: the text
// of the file it was opened from with the keys the tab edits set to the edited values
// (grains.count, shear.pressures, shear.friction, shear.target_axial_strain); every other key,
// its order and its value are the file's. This is the text **Save experiment as…** writes and
// the text a window run stores in its run file, so that the saved file, the run folder and
// `grainlab run` agree. Pure functions, any thread.

#include <string>

#include "grainlab/experiment.h"

namespace grainlab::ui {

/// The text of `base` (its sourceText) with the Parameters tab's keys taken from `edited`;
/// `base.sourceText` itself when none of them differs. Throws std::runtime_error when `base`
/// has no source text (an experiment built in code) or that text is not a JSON object.
std::string editedExperimentText(const ExperimentConfig& base, const ExperimentConfig& edited);

/// editedExperimentText() read back with the experiment-file reader (validated; its sourceText
/// is that text, its sourcePath `sourceName`). Throws ExperimentFileError or std::runtime_error.
ExperimentConfig editedExperiment(const ExperimentConfig& base, const ExperimentConfig& edited,
                                  const std::string& sourceName);

} // namespace grainlab::ui
