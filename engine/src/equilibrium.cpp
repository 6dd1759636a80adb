#include "grainlab/equilibrium.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grainlab/measures.h"
#include "grainlab/time_step.h"

namespace grainlab {

EquilibriumCheck checkEquilibrium(const Simulation& simulation, double targetPressure,
                                  const EquilibriumCriterion& criterion) {
    EquilibriumCheck out;
    const Stress s = simulation.stress();
    out.stressError =
        std::max(std::fabs(s.s11 - targetPressure), std::fabs(s.s22 - targetPressure)) /
        targetPressure;
    out.unbalancedForce = simulation.unbalancedForceIndex();
    out.pass = out.stressError <= criterion.stressTolerance &&
               out.unbalancedForce <= criterion.unbalancedForceMax && simulation.contactCount() > 0;
    return out;
}

namespace {

/// A stage whose lowest I_uf over the last quarter of its step cap is above this fraction of the
/// lowest over its second quarter has stopped calming (it has a floor) [-].
constexpr double kStillFalling = 0.9;
/// A stage whose stress error is above this many times its tolerance is still on its way to the
/// target (e.g. a compaction still gathering the loose grid) [-].
constexpr double kFarFromTarget = 10.0;

} // namespace

void CalmHistory::note(std::int64_t inStage, std::int64_t maxSteps, double unbalancedForce) {
    const auto quarter = static_cast<std::size_t>(
        std::clamp<std::int64_t>(4 * inStage / std::max<std::int64_t>(1, maxSteps), 0, 3));
    double& low = lowest[quarter];
    low = low < 0 ? unbalancedForce : std::min(low, unbalancedForce);
}

std::string whyNotCalm(const CalmHistory& history, double stressError,
                       const EquilibriumCriterion& c, const SimulationState& state) {
    const SimulationParameters& p = state.parameters;
    if (p.damping.kind == DampingKind::None && p.friction == 0.0) {
        return "nothing dissipates energy in this stage (no damping and friction 0), so "
               "the grains cannot come to rest: choose a damping (damping.kind)";
    }
    if (stressError > kFarFromTarget * c.stressTolerance) {
        return "the stress is still far from its target: raise the stage's "
               "criterion.max_steps (or the servo's rate cap, max_strain_rate)";
    }
    const double late = history.lowest[3], before = history.lowest[1];
    if (late > c.unbalancedForceMax && before > 0 && late > kStillFalling * before) {
        const TimeStepLimit limit = criticalTimeStep(state.shapes, p);
        std::string assumed;
        if (p.stability.designCoordination != StabilityParameters{}.designCoordination) {
            SimulationParameters usual = p;
            usual.stability.designCoordination = StabilityParameters{}.designCoordination;
            assumed = fmt::format(
                " (it assumes stability.design_coordination = {} contacts on the stiffest "
                "grain; the default {} gives {:.4g} s)",
                p.stability.designCoordination, usual.stability.designCoordination,
                criticalTimeStep(state.shapes, usual).limit);
        }
        return fmt::format(
            "the unbalanced-force index does not fall: its lowest value over the last quarter "
            "of the stage, {:.3g} %, is not below {:.0f} % of the lowest over its second "
            "quarter ({:.3g} %). A packing that keeps such a floor jitters: the mark of a time "
            "step above the stable limit of the packing (docs/stability.md), or of an "
            "unbalanced_force_max below what it reaches at rest. time_step = {:.4g} s is {:.2f} "
            "of the engine's stable limit {:.4g} s{}; lower time_step, or relax the criterion",
            late, 100 * kStillFalling, before, p.timeStep, p.timeStep / limit.limit, limit.limit,
            assumed);
    }
    return "the unbalanced-force index was still falling: raise the stage's "
           "criterion.max_steps or relax its criterion";
}

} // namespace grainlab
