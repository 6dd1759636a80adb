#pragma once
// What the GUI's simulation controller drives: something that advances in chunks of steps and
// builds immutable snapshots. In the app it is the ExperimentRunner (makeExperimentRun); tests
// may substitute a scripted run. Called only on the controller's worker thread.

#include <cstdint>
#include <memory>

#include "grainlab/experiment.h"
#include "grainlab/experiment_runner.h"
#include "grainlab/snapshot.h"

namespace grainlab::ui {

class SteppedRun {
public:
    virtual ~SteppedRun() = default;
    /// Advances by at most `maxSteps` steps; false once the run is finished. May throw.
    virtual bool advance(std::int64_t maxSteps) = 0;
    virtual SnapshotPtr snapshot() const = 0;
    virtual RunProgress progress() const = 0;
};

/// The experiment runner behind the SteppedRun interface (no output files: the GUI exports on
/// demand).
std::unique_ptr<SteppedRun> makeExperimentRun(const ExperimentConfig& config);

} // namespace grainlab::ui
