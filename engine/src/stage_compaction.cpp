#include "stage_compaction.h"

namespace grainlab {

void CompactionStage::start(RunContext& ctx) {
    startWaiting(ctx);
    ctx.currentSeries = ctx.seriesIndex(kCompactionSeries);
    if (index() == 0) {
        ctx.setStrainReference();
    }
    // The first record at the first equilibrium check: events fall on whole steps counted
    // from the stage's start, never where a caller's advance() happens to end.
    ctx.nextRecordStep = ctx.stageStartStep + criterion(ctx.config).checkInterval;
    ctx.nextSnapshotStep = ctx.sim->stepCount() + ctx.config.record.snapshotStepInterval;
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
