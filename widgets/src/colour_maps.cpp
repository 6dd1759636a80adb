// See colour_maps.h. The control points are chosen by hand for monotone lightness.
#include "grainlab/ui/colour_maps.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainlab::ui {
namespace {

struct Stop {
    double t;
    int r, g, b;
};

template <std::size_t N>
QColor interpolate(const std::array<Stop, N>& stops, double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, stops.front().t, stops.back().t);
    for (std::size_t k = 1; k < N; ++k) {
        if (t <= stops[k].t) {
            const Stop& a = stops[k - 1];
            const Stop& b = stops[k];
            const double u = (t - a.t) / (b.t - a.t);
            return QColor::fromRgbF(float((a.r + u * (b.r - a.r)) / 255.0),
                                    float((a.g + u * (b.g - a.g)) / 255.0),
                                    float((a.b + u * (b.b - a.b)) / 255.0));
        }
    }
    return QColor(stops.back().r, stops.back().g, stops.back().b);
}

constexpr std::array<Stop, 5> kSequential{{{0.0, 68, 1, 84},
                                           {0.25, 59, 82, 139},
                                           {0.5, 33, 145, 140},
                                           {0.75, 94, 201, 98},
                                           {1.0, 253, 231, 37}}};
constexpr std::array<Stop, 5> kDiverging{{{-1.0, 33, 102, 172},
                                          {-0.5, 103, 169, 207},
                                          {0.0, 236, 236, 236},
                                          {0.5, 239, 138, 98},
                                          {1.0, 178, 24, 43}}};
constexpr std::array<QRgb, 8> kCategories{0xff1f77b4, 0xffd62728, 0xff2ca02c, 0xffff7f0e,
                                          0xff9467bd, 0xff8c564b, 0xffe377c2, 0xff17becf};

} // namespace

QColor sequentialColour(double t) {
    return interpolate(kSequential, t);
}

QColor divergingColour(double t) {
    return interpolate(kDiverging, t);
}

QColor categoryColour(int index) {
    const int n = static_cast<int>(kCategories.size());
    return QColor::fromRgb(kCategories[((index % n) + n) % n]);
}

QColor lighter(const QColor& c, double amount) {
    const double a = std::clamp(amount, 0.0, 1.0);
    return QColor::fromRgbF(float(c.redF() + a * (1.0 - c.redF())),
                            float(c.greenF() + a * (1.0 - c.greenF())),
                            float(c.blueF() + a * (1.0 - c.blueF())), c.alphaF());
}

} // namespace grainlab::ui
