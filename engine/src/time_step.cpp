#include "grainlab/time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

TimeStepLimit criticalTimeStep(const std::vector<OvalShape>& shapes,
                               const SimulationParameters& p) {
    // Central differences are stable for omega_max * dt < 2. The stiffest grain with z contacts
    // has a translational stiffness z * max(k_n, k_t) and a rotational stiffness of at most
    // z * max(k_n, k_t) * a^2 (every contact force has a lever arm of at most a).
    TimeStepLimit out;
    out.translational = out.rotational = std::numeric_limits<double>::infinity();
    const double k = std::max(p.normalStiffness, p.tangentialStiffness) *
                     std::max(1, p.stability.designCoordination);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const OvalShape& s = shapes[i];
        const double m = p.density * s.area, inertia = p.density * s.polarMoment;
        const double t = 2.0 * std::sqrt(m / k);
        const double r = 2.0 * std::sqrt(inertia / (k * s.halfWidth * s.halfWidth));
        out.translational = std::min(out.translational, t);
        if (r < out.rotational) {
            out.rotational = r;
        }
        if (std::min(t, r) < out.limit || i == 0) {
            out.limit = std::min(t, r);
            out.stiffestShape = static_cast<int>(i);
        }
    }
    out.limit = std::min(out.translational, out.rotational);
    return out;
}

std::string checkTimeStep(const std::vector<OvalShape>& shapes, const SimulationParameters& p) {
    const TimeStepLimit lim = criticalTimeStep(shapes, p);
    const double dt = p.timeStep;
    if (!(dt > 0.0) || !std::isfinite(dt)) {
        throw std::invalid_argument(fmt::format("time step {} s: must be > 0", dt));
    }
    const auto describe = [&] {
        return fmt::format("the stable limit is {:.4g} s (translational {:.4g} s, rotational "
                           "{:.4g} s, set by the grain of width {:.4g} m with {} contacts)",
                           lim.limit, lim.translational, lim.rotational,
                           shapes[lim.stiffestShape].width, p.stability.designCoordination);
    };
    if (!(lim.limit > 0.0) || !std::isfinite(lim.limit)) {
        throw std::invalid_argument(fmt::format(
            "the stable limit is not a finite positive number ({}: translational {}, rotational "
            "{}); the material's stiffness and density and the grains' shapes must give finite "
            "masses, moments of inertia and stiffnesses",
            lim.limit, lim.translational, lim.rotational));
    }
    if (dt > lim.limit) {
        throw std::invalid_argument(fmt::format(
            "time step {:.4g} s is above {}; use at most {:.4g} s", dt, describe(), lim.limit));
    }
    if (dt > 0.8 * lim.limit) {
        return fmt::format("time step {:.4g} s is within 20 % of {}", dt, describe());
    }
    return {};
}

} // namespace grainlab
