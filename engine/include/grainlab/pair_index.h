#pragma once
// Which neighbour pairs act on each grain, for gathering the per-pair forces onto the grains in
// one fixed order: the order of the sums fixes the bits, the same on any thread count. The pairs
// are sorted by first grain: grain i is first in the pairs [firstStart[i], firstStart[i+1]); it
// is second in the pairs secondPairs[secondStart[i] .. secondStart[i+1]).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace grainlab {

struct PairIndex {
    std::vector<std::int32_t> firstStart, secondStart, secondPairs;

    /// The index of `n` grains and the pairs (first[p], second[p]), sorted by first.
    void build(std::size_t n, const std::vector<std::int32_t>& first,
               const std::vector<std::int32_t>& second);
};

/// What the pairs put on one grain.
struct GrainSum {
    double f1 = 0.0, f2 = 0.0, torque = 0.0;
};

/// The force and torque of the pairs on grain i in the fixed order: the pairs where it is first
/// (-F, torqueFirst), then those where it is second (+F, torqueSecond). Raw pointers, for the
/// integrator's hot loop.
inline GrainSum sumOnGrain(std::size_t i, const std::int32_t* firstStart,
                           const std::int32_t* secondStart, const std::int32_t* secondPairs,
                           const double* force1, const double* force2, const double* torqueFirst,
                           const double* torqueSecond) {
    GrainSum s;
    for (std::int32_t p = firstStart[i]; p < firstStart[i + 1]; ++p) {
        s.f1 -= force1[p];
        s.f2 -= force2[p];
        s.torque += torqueFirst[p];
    }
    for (std::int32_t q = secondStart[i]; q < secondStart[i + 1]; ++q) {
        const std::int32_t p = secondPairs[q];
        s.f1 += force1[p];
        s.f2 += force2[p];
        s.torque += torqueSecond[p];
    }
    return s;
}

} // namespace grainlab
