#pragma once
// The re-equilibration before a test: the sample of the test's pressure, as compacted, with the
// test's friction and servo rate, servoed at that pressure until at rest again (each test of a
// sample starts from it afresh). Starts the test's series (its sample's testName() and the
// test's testSuffix()) and its strain reference
// and orientation reference (thetaAtTestStart), and writes a checkpoint at its start. The test
// follows at once when it ends, with no checkpoint of its own.

#include "stage_equilibrium.h"

namespace grainlab {

/// A test's name, which sorts by pressure: p015kPa, p100kPa (p12.5kPa for non-integer kPa).
std::string testName(double pressure);

class EquilibrationStage final : public EquilibriumStage {
public:
    using EquilibriumStage::EquilibriumStage;
    void start(RunContext& ctx) override;
    void finish(RunContext& ctx) override { ctx.recordNow(); }
    /// The test follows at once, with no checkpoint between.
    bool checkpointAtEnd() const override { return false; }
    /// Two calm windows (calm_checks * check_interval steps each).
    StageShare share(const ExperimentConfig& config) const override;

protected:
    const EquilibriumCriterion& criterion(const ExperimentConfig& config) const override {
        return config.shear.equilibration;
    }
};

} // namespace grainlab
