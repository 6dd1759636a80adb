#include "stage_generation.h"

#include "grainlab/assembly.h"
#include "grainlab/time_step.h"
#include "run_context.h"

namespace grainlab {

GeneratedSample generateSample(const ExperimentConfig& config) {
    SimulationParameters p = config.parameters;
    p.friction = config.compaction.friction;
    p.servo.maxStrainRate = config.compaction.maxStrainRate;
    p.threads = threadsFor(config);
    SimulationState state = generateGridAssembly(config.assembly, p);
    GeneratedSample out;
    // The run's time-step check: every later stage has the same shapes, density, stiffness
    // and damping, so its answer holds for the whole run.
    out.timeStepWarning = checkTimeStep(state.shapes, p);
    out.simulation = std::make_unique<Simulation>(std::move(state));
    return out;
}

} // namespace grainlab
