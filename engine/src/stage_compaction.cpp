#include "stage_compaction.h"

namespace grainlab {

void CompactionStage::start(RunContext& ctx) {
    startWaiting(ctx);
    ctx.currentSeries = ctx.seriesIndex(kCompactionSeries);
    if (index() == 0) {
        ctx.setStrainReference();
    }
}

void CompactionStage::finish(RunContext& ctx) {
    ctx.recordNow();
    ctx.sim->clearVelocities();
    SimulationState sample = ctx.sim->state();
    ctx.samples[pressure()] = sample;
    if (ctx.output) {
        ctx.output->sample(pressure(), sample);
    }
}

StageShare CompactionStage::share(const ExperimentConfig& config) const {
    return settlingShare((index() == 0 ? 0.1 : 0.01) / config.parameters.timeStep,
                         config.compaction.criterion);
}

} // namespace grainlab
