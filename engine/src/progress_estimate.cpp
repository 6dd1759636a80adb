#include "progress_estimate.h"

#include <algorithm>
#include <cmath>

namespace grainlab {

double progressFraction(const std::vector<StageShare>& plan, std::size_t stage,
                        std::int64_t stepsInStage) {
    double total = 0;
    double done = 0;
    for (std::size_t k = 0; k < plan.size(); ++k) {
        if (k < stage) {
            done += plan[k].weight;
        }
        total += plan[k].weight;
    }
    if (stage < plan.size()) {
        const StageShare& s = plan[stage];
        const double inStage = std::max(0.0, double(stepsInStage));
        // settling: below the weight for every finite step count.
        done +=
            s.settles ? s.weight * -std::expm1(-inStage / s.weight) : std::min(inStage, s.weight);
    }
    return total > 0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
}

} // namespace grainlab
