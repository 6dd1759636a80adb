#include "stage.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "stage_compaction.h"
#include "stage_cyclic.h"
#include "stage_equilibration.h"
#include "stage_monotonic_test.h"
#include "stage_probes.h"

namespace grainlab {

StageKind stageKindOf(const LoadingPath& path) {
    // A switch, so that the compiler names a test kind left out.
    switch (path.kind) {
    case LoadingPath::Kind::Drained:
        return StageKind::Shear;
    case LoadingPath::Kind::ConstantVolume:
        return StageKind::ConstantVolume;
    case LoadingPath::Kind::ConstantP:
        return StageKind::ConstantP;
    case LoadingPath::Kind::StressPath:
        return StageKind::StressPath;
    case LoadingPath::Kind::Cyclic:
        return StageKind::Cyclic;
    case LoadingPath::Kind::Probes:
        return StageKind::Probes;
    }
    throw std::invalid_argument(
        fmt::format("experiment: tests of kind {} are not available", loadingKindName(path.kind)));
}

std::vector<PlannedStage> experimentPlan(const ExperimentConfig& config) {
    std::vector<PlannedStage> plan;
    const auto& compaction = config.compaction.pressures;
    for (std::size_t k = 0; k < compaction.size(); ++k) {
        plan.push_back({StageKind::Compaction, int(k), compaction[k], 0, ""});
    }
    const auto& pressures = config.shear.pressures;
    const std::size_t n = config.tests.size();
    for (std::size_t k = 0; k < pressures.size(); ++k) {
        for (std::size_t j = 0; j < n; ++j) {
            const int index = int(k * n + j);
            const std::string series = testName(pressures[k]) + testSuffix(config.tests[j]);
            // Probes after another test start where it ended: no re-equilibration between.
            if (j == 0 || config.tests[j].kind != LoadingPath::Kind::Probes) {
                plan.push_back({StageKind::Equilibration, index, pressures[k], int(j), series});
            }
            plan.push_back({stageKindOf(config.tests[j]), index, pressures[k], int(j), series});
        }
    }
    return plan;
}

std::size_t planPosition(const std::vector<PlannedStage>& plan, StageKind kind, int index) {
    if (kind == StageKind::Done) {
        return plan.size();
    }
    for (std::size_t k = 0; k < plan.size(); ++k) {
        if (plan[k].kind == kind && plan[k].index == index) {
            return k;
        }
    }
    throw std::runtime_error(fmt::format("resume: the runner state's stage ({} {}) is not a stage "
                                         "of this experiment",
                                         stageKindName(kind), index));
}

void TestStage::save(RunnerState& state, const RunContext& ctx) const {
    state.voidsAtStart = voidsAtStart_;
    state.peak.reset();
    saveTest(state, ctx);
}

void TestStage::restore(const RunnerState& state, const RunContext& ctx,
                        const SimulationState& resumed,
                        std::optional<SimulationState> runningPeak) {
    voidsAtStart_ = state.voidsAtStart;
    restoreTest(state, ctx, resumed, std::move(runningPeak));
}

void LoadingTestStage::start(RunContext& ctx) {
    ctx.stageStartStep = ctx.sim->stepCount();
    ctx.setStrainReference();
    forgetInitialVoids();
    startTest(ctx);
    ctx.checkpoint(ctx.checkpointLabel());
}

void LoadingTestStage::recordFirst(RunContext& ctx) {
    const RecordSpec& every = ctx.config.record;
    ctx.nextRecordStep = ctx.stageStartStep;
    ctx.nextSnapshotStep = ctx.stageStartStep + ctx.strideOf(every.snapshotStrainInterval);
    ctx.recordNow(); // eps1 = 0: N_vi
    ctx.nextRecordStep = ctx.stageStartStep + ctx.strideOf(every.strainInterval);
}

std::int64_t LoadingTestStage::stepsToNextEvent(const RunContext& ctx) const {
    return std::max<std::int64_t>(
        1, std::min({ctx.nextRecordStep, ctx.nextSnapshotStep, nextTestEvent(ctx)}) -
               ctx.sim->stepCount());
}

void LoadingTestStage::record(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    ctx.recordNow();
    ctx.nextRecordStep = now + ctx.strideOf(ctx.config.record.strainInterval);
}

void LoadingTestStage::checkpointWhenDue(RunContext& ctx) {
    const std::int64_t now = ctx.sim->stepCount();
    if (now >= ctx.nextSnapshotStep) {
        ctx.checkpoint(ctx.checkpointLabel());
        ctx.nextSnapshotStep = now + ctx.strideOf(ctx.config.record.snapshotStrainInterval);
    }
}

std::unique_ptr<Stage> makeStage(const PlannedStage& planned) {
    switch (planned.kind) {
    case StageKind::Compaction:
        return std::make_unique<CompactionStage>(planned);
    case StageKind::Equilibration:
        return std::make_unique<EquilibrationStage>(planned);
    case StageKind::Shear:
    case StageKind::ConstantVolume:
    case StageKind::ConstantP:
    case StageKind::StressPath:
        return std::make_unique<MonotonicTestStage>(planned);
    case StageKind::Cyclic:
        return std::make_unique<CyclicStage>(planned);
    case StageKind::Probes:
        return std::make_unique<ProbesStage>(planned);
    case StageKind::Done:
        break;
    }
    throw std::logic_error("makeStage: no stage object for a finished run");
}

} // namespace grainlab
