// See stability_probe.h.
#include "grainlab/stability_probe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/enum_names.h"
#include "grainlab/measures.h"
#include "grainlab/simulation.h"

namespace grainlab {

std::string blowUpName(BlowUp kind) {
    static constexpr EnumName<BlowUp> kNames[] = {
        {BlowUp::None, "none"},
        {BlowUp::NonFinite, "non_finite"},
        {BlowUp::Displacement, "displacement"},
        {BlowUp::Overlap, "overlap"},
        {BlowUp::KineticEnergy, "kinetic_energy"},
        {BlowUp::EnergyResidual, "energy_residual"},
        {BlowUp::UnbalancedFloor, "unbalanced_force_floor"},
        {BlowUp::EngineStop, "engine_stop"}};
    return enumName(kNames, kind, "none");
}

double probeTimeUnit(const SimulationState& state) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const std::int32_t s : state.grains.shape) {
        smallest = std::min(smallest, state.parameters.density * state.shapes[s].area);
    }
    return std::sqrt(smallest / state.parameters.normalStiffness);
}

namespace {

/// The per-step checks: a non-finite grain or one that travelled too far. Its own reading of
/// the state, independent of the engine's guards (which the probe switches off).
struct MotionCheck {
    BlowUp kind = BlowUp::None;
    std::string detail;
};

MotionCheck checkMotion(const SimulationState& s, double timeStep, double maxTravel) {
    const GrainArrays& g = s.grains;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double speed = std::hypot(g.v1[i], g.v2[i]);
        if (!std::isfinite(g.x1[i]) || !std::isfinite(g.x2[i]) || !std::isfinite(g.theta[i]) ||
            !std::isfinite(speed) || !std::isfinite(g.omega[i])) {
            return {BlowUp::NonFinite, fmt::format("grain {}: non-finite state", i)};
        }
        const OvalShape& shape = s.shapes[g.shape[i]];
        const double travel = timeStep * (speed + std::fabs(g.omega[i]) * shape.halfWidth);
        if (travel > maxTravel * shape.halfHeight) {
            return {BlowUp::Displacement,
                    fmt::format("grain {} moved {:.3g} of its half-height in one step", i,
                                travel / shape.halfHeight)};
        }
    }
    return {};
}

double largestOverlapFraction(const ContactNetwork& net, const SimulationState& s) {
    double worst = 0;
    for (const ContactRecord& c : net.contacts) {
        const double a = s.shapes[s.grains.shape[c.first]].width;
        const double b = s.shapes[s.grains.shape[c.second]].width;
        worst = std::max(worst, c.overlap / std::min(a, b));
    }
    return worst;
}

} // namespace

ProbeResult runStabilityProbe(SimulationState base, double timeStep,
                              const ProbeSettings& settings) {
    if (!(timeStep > 0.0) || !std::isfinite(timeStep)) {
        throw std::invalid_argument(
            fmt::format("stability probe: time step {} s: must be > 0", timeStep));
    }
    if (settings.steps < 4 || settings.checkInterval < 1) {
        throw std::invalid_argument("stability probe: needs at least 4 steps and a check "
                                    "interval of at least 1");
    }
    base.parameters.timeStep = timeStep;
    base.parameters.stability.unguarded = true;
    const BlowUpThresholds& t = settings.thresholds;
    ProbeResult out;
    Simulation sim(std::move(base));
    const Energies e0 = sim.energies();
    const double mechanical0 = e0.kinetic + e0.elastic;
    const double unbalanced0 = t.unbalancedFloor ? unbalancedForceIndex(sim.contactNetwork()) : 0;
    const std::int64_t lastQuarter = settings.steps - settings.steps / 4;
    // Running maxima of E_kin and |residual| over the checks so far: check j is compared with
    // the maximum over the first quarter of the checks up to it (exponential growth shows as a
    // large ratio, a bounded fluctuation does not once the window spans its period).
    std::vector<double> kineticMax, residualMax;
    double floorLate = std::numeric_limits<double>::infinity();

    const auto fire = [&](BlowUp kind, std::int64_t step, std::string detail) {
        out.stable = false;
        out.detector = kind;
        out.step = step;
        out.detail = std::move(detail);
    };
    for (std::int64_t k = 1; k <= settings.steps && out.stable; ++k) {
        try {
            sim.step();
        } catch (const SimulationError& e) {
            // Unguarded, the engine stops only for a non-finite state or a cell that became
            // narrower than two grains: either way the step failed.
            const bool nonFinite = e.cause.find("non-finite") != std::string::npos;
            fire(nonFinite ? BlowUp::NonFinite : BlowUp::EngineStop, k, e.what());
            break;
        }
        out.stepsRun = k;
        const MotionCheck motion = checkMotion(sim.stateRef(), timeStep, t.maxTravel);
        if (motion.kind != BlowUp::None) {
            fire(motion.kind, k, motion.detail);
            break;
        }
        if (k % settings.checkInterval != 0 && k != settings.steps) {
            continue;
        }
        const Energies e = sim.energies();
        const double inflow = e.boundaryWork - e0.boundaryWork;
        const double scale =
            std::max(mechanical0 + std::max(inflow, 0.0), std::numeric_limits<double>::min());
        const double residual = (e.kinetic + e.elastic - mechanical0) - inflow +
                                (e.frictionWork - e0.frictionWork) +
                                (e.dampingWork - e0.dampingWork);
        const ContactNetwork net = sim.contactNetwork();
        ProbeCheck check;
        check.step = k;
        check.kinetic = e.kinetic / scale;
        check.residual = residual / scale;
        check.maxOverlap = largestOverlapFraction(net, sim.stateRef());
        check.unbalanced = t.unbalancedFloor ? unbalancedForceIndex(net) : 0.0;
        out.energyScale = scale;
        out.finalResidual = std::fabs(check.residual);
        out.maxResidual = std::max(out.maxResidual, out.finalResidual);
        out.finalUnbalanced = check.unbalanced;
        if (settings.trace) {
            out.trace.push_back(check);
        }
        if (!std::isfinite(check.kinetic) || !std::isfinite(check.residual)) {
            fire(BlowUp::NonFinite, k, "non-finite energy");
        } else if (check.maxOverlap > t.maxOverlap) {
            fire(BlowUp::Overlap, k,
                 fmt::format("overlap {:.3g} of the smaller width", check.maxOverlap));
        } else if (check.kinetic > t.catastrophic) {
            fire(BlowUp::KineticEnergy, k,
                 fmt::format("kinetic energy {:.3g} times the energy the run began with",
                             check.kinetic));
        } else if (std::fabs(check.residual) > t.maxResidual) {
            fire(BlowUp::EnergyResidual, k,
                 fmt::format("energy-balance residual {:.3g} times the energy the run began with "
                             "(the scheme made or lost more energy than there was)",
                             check.residual));
        } else {
            const std::size_t j = kineticMax.size();
            kineticMax.push_back(std::max(j ? kineticMax.back() : 0.0, check.kinetic));
            residualMax.push_back(
                std::max(j ? residualMax.back() : 0.0, std::fabs(check.residual)));
            const double kineticEarly = kineticMax[j / 4], residualEarly = residualMax[j / 4];
            if (j < 4) {
                // too few checks for a window
            } else if (check.kinetic > t.growth * std::max(kineticEarly, t.kineticFloor)) {
                fire(BlowUp::KineticEnergy, k,
                     fmt::format("kinetic energy grew to {:.3g} E_ref from at most {:.3g} over "
                                 "the first quarter of the run so far",
                                 check.kinetic, kineticEarly));
            } else if (std::fabs(check.residual) >
                       t.growth * std::max(residualEarly, t.residualFloor)) {
                fire(BlowUp::EnergyResidual, k,
                     fmt::format("energy-balance residual grew to {:.3g} E_ref from at most "
                                 "{:.3g} over the first quarter of the run so far",
                                 check.residual, residualEarly));
            }
        }
        if (k > lastQuarter) {
            floorLate = std::min(floorLate, check.unbalanced);
        }
    }
    if (out.stable && t.unbalancedFloor && floorLate > t.floorIndex &&
        floorLate > t.floorRise * unbalanced0) {
        fire(BlowUp::UnbalancedFloor, out.stepsRun,
             fmt::format("the unbalanced-force index stayed above {:.3g} % over the last quarter "
                         "of the run (it began at {:.3g} %): the packing jitters",
                         floorLate, unbalanced0));
    }
    return out;
}

} // namespace grainlab
