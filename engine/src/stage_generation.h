#pragma once
// The generation of a run's assembly (the experiment's "assembly"): the grid of grains under
// the compaction's friction and servo rate, and the run's one check of its time step.

#include <memory>
#include <string>

#include "grainlab/experiment.h"
#include "grainlab/simulation.h"

namespace grainlab {

struct GeneratedSample {
    std::unique_ptr<Simulation> simulation;
    /// The time step's warning (checkTimeStep(): within 20 % of the stable limit), or "".
    std::string timeStepWarning;
};

/// Generates the assembly of `config`. Throws std::invalid_argument for a time step above the
/// engine's stable limit.
GeneratedSample generateSample(const ExperimentConfig& config);

} // namespace grainlab
