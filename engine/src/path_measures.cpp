// Cyclic and probe measures (path_measures.h).
#include "grainlab/path_measures.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace grainlab {

std::vector<std::size_t> reversalIndices(const std::vector<double>& series) {
    std::vector<std::size_t> out;
    int last = 0;         // sign of the last non-zero increment
    std::size_t turn = 0; // the record where that increment ended
    for (std::size_t i = 1; i < series.size(); ++i) {
        const double d = series[i] - series[i - 1];
        const int sign = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
        if (sign == 0) {
            continue;
        }
        if (last != 0 && sign != last) {
            out.push_back(turn);
        }
        last = sign;
        turn = i;
    }
    return out;
}

std::vector<CycleSpan> cycleSpans(const std::vector<std::size_t>& reversals) {
    std::vector<CycleSpan> spans;
    for (std::size_t k = 0; k + 2 < reversals.size(); k += 2) {
        spans.push_back({reversals[k], reversals[k + 2]});
    }
    return spans;
}

std::optional<PressureCriterionResult>
cyclesToPressureFraction(const std::vector<double>& p, const std::vector<std::size_t>& reversals,
                         double p0, double fraction) {
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p[i] < fraction * p0) {
            std::size_t before = 0;
            while (before < reversals.size() && reversals[before] < i) {
                ++before;
            }
            return PressureCriterionResult{i, 0.5 * double(before)};
        }
    }
    return std::nullopt;
}

std::vector<std::array<double, 2>> probeDirections(std::size_t count) {
    std::vector<std::array<double, 2>> u(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double angle = 2.0 * std::numbers::pi * double(k) / double(count);
        u[k] = {std::cos(angle), std::sin(angle)};
    }
    return u;
}

ResponseEnvelope responseEnvelope(const std::vector<std::array<double, 2>>& responses) {
    const std::size_t K = responses.size();
    if (K < 4 || K % 2 != 0) {
        throw std::invalid_argument(
            fmt::format("response envelope: {} probes; needs an even count >= 4", K));
    }
    ResponseEnvelope env;
    env.points = responses;
    const auto norm = [](const std::array<double, 2>& a) { return std::hypot(a[0], a[1]); };
    for (std::size_t k = 0; k < K / 2; ++k) {
        const auto& a = responses[k];
        const auto& b = responses[k + K / 2];
        const double scale = 0.5 * (norm(a) + norm(b));
        if (scale > 0.0) {
            env.asymmetry = std::max(env.asymmetry, std::hypot(a[0] + b[0], a[1] + b[1]) / scale);
        }
    }
    // Least squares M = (sum r u^T)(sum u u^T)^-1; the 2 x 2 Gram matrix is inverted in closed
    // form (for evenly spread directions it is K/2 I).
    const auto u = probeDirections(K);
    double g11 = 0, g12 = 0, g22 = 0;
    double c11 = 0, c12 = 0, c21 = 0, c22 = 0; // sum r u^T
    for (std::size_t k = 0; k < K; ++k) {
        g11 += u[k][0] * u[k][0];
        g12 += u[k][0] * u[k][1];
        g22 += u[k][1] * u[k][1];
        c11 += responses[k][0] * u[k][0];
        c12 += responses[k][0] * u[k][1];
        c21 += responses[k][1] * u[k][0];
        c22 += responses[k][1] * u[k][1];
    }
    const double det = g11 * g22 - g12 * g12;
    const double i11 = g22 / det, i12 = -g12 / det, i22 = g11 / det;
    const double m11 = c11 * i11 + c12 * i12, m12 = c11 * i12 + c12 * i22;
    const double m21 = c21 * i11 + c22 * i12, m22 = c21 * i12 + c22 * i22;
    env.linearMap = {m11, m21, m12, m22};
    double res = 0, total = 0;
    for (std::size_t k = 0; k < K; ++k) {
        const double f1 = m11 * u[k][0] + m12 * u[k][1];
        const double f2 = m21 * u[k][0] + m22 * u[k][1];
        res += (responses[k][0] - f1) * (responses[k][0] - f1) +
               (responses[k][1] - f2) * (responses[k][1] - f2);
        total += responses[k][0] * responses[k][0] + responses[k][1] * responses[k][1];
    }
    env.ellipseResidual = total > 0.0 ? std::sqrt(res / total) : 0.0;
    // Singular values of M from M M^T = [[a, b], [b, c]]: its eigenvalues are the squared
    // semi-axes, its leading eigenvector the major axis of the ellipse M (unit circle).
    const double a = m11 * m11 + m12 * m12;
    const double b = m11 * m21 + m12 * m22;
    const double c = m21 * m21 + m22 * m22;
    const double mid = 0.5 * (a + c);
    const double rad = std::hypot(0.5 * (a - c), b);
    env.majorSemiAxis = std::sqrt(mid + rad);
    env.minorSemiAxis = std::sqrt(std::max(0.0, mid - rad));
    env.majorAngle = 0.5 * std::atan2(2.0 * b, a - c);
    return env;
}

} // namespace grainlab
