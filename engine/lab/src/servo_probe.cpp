// See servo_probe.h.
#include "grainlab/servo_probe.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/enum_names.h"
#include "grainlab/simulation.h"

namespace grainlab {

namespace {

constexpr EnumName<ServoResponse> kResponseNames[] = {{ServoResponse::Steady, "steady"},
                                                      {ServoResponse::Lagging, "lagging"},
                                                      {ServoResponse::Oscillating, "oscillating"},
                                                      {ServoResponse::Diverging, "diverging"}};

} // namespace

std::string servoResponseName(ServoResponse response) {
    return enumName(kResponseNames, response, "steady");
}

ServoResponse servoResponseFromName(const std::string& name) {
    if (const auto response = enumFromName(kResponseNames, name)) {
        return *response;
    }
    throw std::invalid_argument(fmt::format("servo response {}: not a response", name));
}

ServoErrorStats servoErrorStats(const ServoErrorSeries& series, const ServoThresholds& thresholds,
                                bool stopped, const std::string& stopCause) {
    ServoErrorStats s;
    s.stopped = stopped;
    s.stopCause = stopCause;
    const auto n = std::int64_t(series.perStep.size());
    s.steps = n;
    const auto judged = std::int64_t(std::ceil(thresholds.transient * double(n)));
    std::int64_t count = 0;
    double sum = 0, squares = 0;
    for (std::int64_t k = 0; k < n; ++k) {
        const double e = series.perStep[std::size_t(k)];
        if (!std::isfinite(e)) {
            s.stopped = true;
            if (s.stopCause.empty()) {
                s.stopCause = fmt::format("non-finite lateral stress at step {}", k + 1);
            }
            break;
        }
        if (k < judged) {
            s.transientMax = std::max(s.transientMax, std::fabs(e));
            continue;
        }
        s.maxError = std::max(s.maxError, std::fabs(e));
        sum += e;
        squares += e * e;
        ++count;
    }
    if (count > 0) {
        s.meanError = sum / double(count);
        s.rmsError = std::sqrt(squares / double(count));
    }
    // Consecutive updates after the transient: the alternating part from the second
    // difference (a linear drift or lag has none), sign changes from the errors themselves.
    double alternating = 0;
    std::int64_t triples = 0, pairs = 0, reversals = 0;
    const std::vector<double>& u = series.perUpdate;
    for (std::size_t k = 1; k < u.size(); ++k) {
        if (series.updateStep[k - 1] < judged) {
            continue;
        }
        if (!std::isfinite(u[k - 1]) || !std::isfinite(u[k])) {
            break;
        }
        reversals += (u[k - 1] > 0.0 && u[k] < 0.0) || (u[k - 1] < 0.0 && u[k] > 0.0) ? 1 : 0;
        ++pairs;
        if (k + 1 < u.size() && std::isfinite(u[k + 1])) {
            const double second = 0.25 * (u[k + 1] - 2.0 * u[k] + u[k - 1]);
            alternating += second * second;
            ++triples;
        }
    }
    s.updates = pairs;
    if (triples > 0) {
        s.alternating = std::sqrt(alternating / double(triples));
    }
    if (pairs > 0) {
        s.reversals = double(reversals) / double(pairs);
    }
    return s;
}

ServoResponse classifyServo(const ServoErrorStats& s, const ServoThresholds& t) {
    if (s.stopped || !(s.alternating <= t.divergence)) {
        return ServoResponse::Diverging;
    }
    if (s.maxError <= t.band) {
        return ServoResponse::Steady;
    }
    return s.alternating > t.oscillation ? ServoResponse::Oscillating : ServoResponse::Lagging;
}

ServoProbeResult runServoProbe(SimulationState base, const ServoSetting& setting,
                               const ServoShear& shear, const ServoThresholds& thresholds) {
    if (!(setting.gain > 0.0) || setting.interval < 1 || !(setting.integralGain >= 0.0)) {
        throw std::invalid_argument(
            fmt::format("servo probe: gain {} and interval {} must be > 0, integral gain {} >= 0",
                        setting.gain, setting.interval, setting.integralGain));
    }
    if (!(shear.pressure > 0.0) || shear.steps < 1) {
        throw std::invalid_argument("servo probe: needs a pressure > 0 and at least one step");
    }
    ServoParameters& servo = base.parameters.servo;
    servo.gain = setting.gain;
    servo.interval = setting.interval;
    servo.integralGain = setting.integralGain;
    servo.maxStrainRate = shear.maxStrainRate;
    base.servoIntegral = {0.0, 0.0};
    const double length = base.cell[0];
    const double dt = base.parameters.timeStep;
    // As the experiment runner's shear: x1 at a constant engineering increment per step, x2 at
    // the confining pressure.
    base.axes[0] = AxisControl{AxisMode::Strain, shear.strainPerStep / dt, 0.0, length};
    base.axes[1] = AxisControl{AxisMode::Stress, 0.0, shear.pressure, 0.0};
    Simulation sim(std::move(base));
    ServoProbeResult out;
    ServoErrorSeries& e = out.error;
    e.perStep.reserve(std::size_t(shear.steps));
    const auto errorNow = [&] { return (sim.stress().s22 - shear.pressure) / shear.pressure; };
    bool stopped = false;
    std::string cause;
    for (std::int64_t k = 0; k < shear.steps; ++k) {
        if (sim.stepCount() % setting.interval == 0) {
            // The servo updates at this step from the stress of the current configuration.
            e.perUpdate.push_back(errorNow());
            e.updateStep.push_back(k);
        }
        try {
            sim.step();
        } catch (const SimulationError& error) {
            stopped = true;
            cause = error.what();
            break;
        }
        e.perStep.push_back(errorNow());
        if (!std::isfinite(e.perStep.back())) {
            break;
        }
    }
    out.stats = servoErrorStats(e, thresholds, stopped, cause);
    out.response = classifyServo(out.stats, thresholds);
    return out;
}

} // namespace grainlab
