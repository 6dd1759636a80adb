#pragma once
// Isotropic compaction to one confining pressure (compaction.pressures[index]) under the
// compaction friction, recording to the series "compaction". The first compaction stage takes
// the generated assembly and sets the strain reference; each further one continues from the
// previous. At equilibrium its state, at rest, is saved as the sample of its pressure
// (RunOutput::sample), and a checkpoint marks its end.

#include "stage_equilibrium.h"

namespace grainlab {

class CompactionStage final : public EquilibriumStage {
public:
    using EquilibriumStage::EquilibriumStage;
    std::string test() const override { return kCompactionSeries; }
    void start(RunContext& ctx) override;
    void finish(RunContext& ctx) override;
    /// A compaction ends with its sample's checkpoint.
    bool checkpointAtEnd() const override { return true; }
    /// A settling time: 0.1 s of simulated time from the loose grid, 0.01 s for each further
    /// pressure (the quick run's stages take 0.12 s, then 0.018, 0.006, 0.007 s).
    StageShare share(const ExperimentConfig& config) const override;

protected:
    const EquilibriumCriterion& criterion(const ExperimentConfig& config) const override {
        return config.compaction.criterion;
    }
};

} // namespace grainlab
