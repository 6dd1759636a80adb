#include "grainlab/statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainlab {

Scatter scatterOf(const std::vector<double>& values) {
    Scatter s;
    s.count = static_cast<int>(values.size());
    if (values.empty()) {
        return s;
    }
    double sum = 0;
    for (double v : values) {
        sum += v;
    }
    s.mean = sum / double(values.size());
    if (values.size() >= 2) {
        double squares = 0;
        for (double v : values) {
            squares += (v - s.mean) * (v - s.mean);
        }
        s.sd = std::sqrt(squares / double(values.size() - 1));
    }
    return s;
}

Scatter scatterOf(const std::vector<std::optional<double>>& values) {
    std::vector<double> present;
    for (const auto& v : values) {
        if (v) {
            present.push_back(*v);
        }
    }
    return scatterOf(present);
}

bool withinNoise(double difference, const Scatter& reference, double factor) {
    return std::abs(difference) <= factor * reference.sd;
}

std::optional<double> valueAt(const Curve& curve, double x) {
    const std::size_t n = std::min(curve.x.size(), curve.y.size());
    if (n == 0 || !(x >= curve.x.front()) || !(x <= curve.x[n - 1])) {
        return std::nullopt;
    }
    // The first point with x_k >= x; with equal x values the last one of them counts.
    const auto begin = curve.x.begin();
    std::size_t k = std::size_t(std::lower_bound(begin, begin + long(n), x) - begin);
    while (k + 1 < n && curve.x[k + 1] == x) {
        ++k;
    }
    if (curve.x[k] == x || k == 0) {
        return curve.y[k];
    }
    const double x0 = curve.x[k - 1], x1 = curve.x[k];
    const double t = (x - x0) / (x1 - x0);
    return curve.y[k - 1] + t * (curve.y[k] - curve.y[k - 1]);
}

std::vector<double> evenlySpaced(double from, double to, int count) {
    if (count < 2) {
        throw std::invalid_argument("evenlySpaced needs at least 2 points");
    }
    std::vector<double> out(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        out[std::size_t(k)] = from + (to - from) * double(k) / double(count - 1);
    }
    out.back() = to;
    return out;
}

CurveBand meanCurve(const std::vector<Curve>& curves, const std::vector<double>& grid) {
    CurveBand band;
    for (double x : grid) {
        std::vector<double> here;
        for (const Curve& c : curves) {
            if (const auto y = valueAt(c, x)) {
                here.push_back(*y);
            }
        }
        if (here.empty()) {
            continue;
        }
        const Scatter s = scatterOf(here);
        band.x.push_back(x);
        band.mean.push_back(s.mean);
        band.sd.push_back(s.sd);
        band.count.push_back(s.count);
    }
    return band;
}

std::optional<double> rmsDifference(const Curve& curve, const Curve& reference,
                                    const std::vector<double>& grid) {
    double squares = 0;
    int n = 0;
    for (double x : grid) {
        const auto a = valueAt(curve, x);
        const auto b = valueAt(reference, x);
        if (a && b) {
            squares += (*a - *b) * (*a - *b);
            ++n;
        }
    }
    if (n == 0) {
        return std::nullopt;
    }
    return std::sqrt(squares / n);
}

} // namespace grainlab
