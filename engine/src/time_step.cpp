#include "grainlab/time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

TimeStepLimit criticalTimeStep(const std::vector<OvalShape>& shapes,
                               const SimulationParameters& p) {
    TimeStepLimit out;
    out.dampingFactor = p.damping.kind == DampingKind::CundallLocal
                            ? 1.0 / std::sqrt(1.0 + p.damping.coefficient)
                            : 1.0;
    out.translational = out.rotational = std::numeric_limits<double>::infinity();
    const double k = std::max(p.normalStiffness, p.tangentialStiffness) *
                     std::max(1, p.stability.designCoordination);
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const OvalShape& s = shapes[i];
        const double m = p.density * s.area, inertia = p.density * s.polarMoment;
        const double t = 2.0 * std::sqrt(m / k) * out.dampingFactor;
        const double r =
            2.0 * std::sqrt(inertia / (k * s.halfWidth * s.halfWidth)) * out.dampingFactor;
        out.translational = std::min(out.translational, t);
        out.rotational = std::min(out.rotational, r);
        if (std::min(t, r) < smallest || i == 0) {
            smallest = std::min(t, r);
            out.stiffestShape = static_cast<int>(i);
        }
    }
    out.estimate = std::min(out.translational, out.rotational);
    out.limit = kTimeStepMargin * out.estimate;
    return out;
}

std::string checkTimeStep(const std::vector<OvalShape>& shapes, const SimulationParameters& p) {
    const TimeStepLimit lim = criticalTimeStep(shapes, p);
    const double dt = p.timeStep;
    if (!(dt > 0.0) || !std::isfinite(dt)) {
        throw std::invalid_argument(fmt::format("time step {} s: must be > 0", dt));
    }
    if (!(lim.estimate > 0.0) || !std::isfinite(lim.estimate)) {
        throw std::invalid_argument(fmt::format(
            "the stable limit is not a finite positive number ({}: translational {}, rotational "
            "{}); the material's stiffness and density and the grains' shapes must give finite "
            "masses, moments of inertia and stiffnesses",
            lim.estimate, lim.translational, lim.rotational));
    }
    const auto describe = [&] {
        const std::string local =
            lim.dampingFactor < 1.0
                ? fmt::format(", times {:.3g} = 1/sqrt(1 + {:g}) for Cundall local damping",
                              lim.dampingFactor, p.damping.coefficient)
                : std::string();
        return fmt::format(
            "the stable limit {:.4g} s: the engine's estimate {:.4g} s (translational {:.4g} s, "
            "rotational {:.4g} s{}, set by the grain of width {:.4g} m with {} contacts) times "
            "the safety margin {:g}; the stability maps measured the true limit of dense and "
            "sheared packings at {:g} to {:g} times the estimate (docs/stability.md)",
            lim.limit, lim.estimate, lim.translational, lim.rotational, local,
            shapes[lim.stiffestShape].width, p.stability.designCoordination, kTimeStepMargin,
            kSmallestMeasuredLimit, kLargestMeasuredLimit);
    };
    if (dt > lim.limit) {
        throw std::invalid_argument(fmt::format("time step {:.4g} s is above {}; use at most "
                                                "{:.4g} s",
                                                dt, describe(), lim.limit));
    }
    if (dt > 0.8 * lim.limit) {
        return fmt::format("time step {:.4g} s is within 20 % of {}", dt, describe());
    }
    return {};
}

} // namespace grainlab
