#include "stage.h"

#include <stdexcept>

#include <fmt/format.h>

#include "stage_compaction.h"
#include "stage_drained_shear.h"
#include "stage_equilibration.h"

namespace grainlab {

std::vector<PlannedStage> experimentPlan(const ExperimentConfig& config) {
    std::vector<PlannedStage> plan;
    const auto& compaction = config.compaction.pressures;
    for (std::size_t k = 0; k < compaction.size(); ++k) {
        plan.push_back({StageKind::Compaction, int(k), compaction[k]});
    }
    const auto& tests = config.shear.pressures;
    for (std::size_t k = 0; k < tests.size(); ++k) {
        plan.push_back({StageKind::Equilibration, int(k), tests[k]});
        plan.push_back({StageKind::Shear, int(k), tests[k]});
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

std::unique_ptr<Stage> makeStage(const PlannedStage& planned) {
    switch (planned.kind) {
    case StageKind::Compaction:
        return std::make_unique<CompactionStage>(planned);
    case StageKind::Equilibration:
        return std::make_unique<EquilibrationStage>(planned);
    case StageKind::Shear:
        return std::make_unique<DrainedShearStage>(planned);
    case StageKind::Done:
        break;
    }
    throw std::logic_error("makeStage: no stage object for a finished run");
}

} // namespace grainlab
