// See stability_bisection.h.
#include "grainlab/stability_bisection.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

StepLimit bisectStableStep(const StepProbe& probe, double low, double high, double precision) {
    if (!(low > 0.0) || !(high > low) || !std::isfinite(high)) {
        throw std::invalid_argument(
            fmt::format("stability bisection: bounds {} and {}: need 0 < low < high", low, high));
    }
    if (!(precision > 0.0) || !(precision < 1.0)) {
        throw std::invalid_argument(
            fmt::format("stability bisection: precision {}: must be in (0, 1)", precision));
    }
    StepLimit out;
    const auto unstableAt = [&](double step, const ProbeResult& r) {
        out.high = step;
        out.detector = r.detector;
        out.detectorStep = r.step;
        out.detail = r.detail;
    };
    ProbeResult top = probe(high);
    ++out.probes;
    if (top.stable) {
        out.low = out.high = out.limit = high; // stable at the upper bound: limit is above it
        return out;
    }
    unstableAt(high, top);
    ProbeResult bottom = probe(low);
    ++out.probes;
    if (!bottom.stable) {
        out.low = out.limit = low; // unstable at the lower bound: limit is below it
        unstableAt(low, bottom);
        return out;
    }
    out.bracketed = true;
    out.low = low;
    while (out.high / out.low - 1.0 > precision) {
        const double mid = std::sqrt(out.low * out.high);
        const ProbeResult r = probe(mid);
        ++out.probes;
        if (r.stable) {
            out.low = mid;
        } else {
            unstableAt(mid, r);
        }
    }
    out.limit = out.low;
    return out;
}

} // namespace grainlab
