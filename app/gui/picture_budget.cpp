// See picture_budget.h.
#include "gui/picture_budget.h"

#include <algorithm>
#include <cmath>

namespace grainlab::ui {

PictureBudget::PictureBudget(double share, double floorMs)
    : share_(std::isfinite(share) ? std::clamp(share, 1e-6, 1.0) : kFreeCoreShare),
      floorMs_(std::isfinite(floorMs) ? std::max(0.0, floorMs) : 0.0) {}

double PictureBudget::shareFor(int engineThreads, int processors) {
    processors = std::max(1, processors);
    if (std::max(1, engineThreads) < processors) {
        return kFreeCoreShare;
    }
    return kEngineLoss;
}

double PictureBudget::intervalMs(double pictureCostMs) const {
    const double cost = std::isfinite(pictureCostMs) ? std::max(0.0, pictureCostMs) : 0.0;
    return std::max(floorMs_, cost / share_);
}

} // namespace grainlab::ui
