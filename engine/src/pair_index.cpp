// See pair_index.h.
#include "grainlab/pair_index.h"

namespace grainlab {

void PairIndex::build(std::size_t n, const std::vector<std::int32_t>& first,
                      const std::vector<std::int32_t>& second) {
    const std::size_t pairs = first.size();
    firstStart.assign(n + 1, 0);
    secondStart.assign(n + 1, 0);
    for (std::size_t p = 0; p < pairs; ++p) {
        ++firstStart[std::size_t(first[p]) + 1];
        ++secondStart[std::size_t(second[p]) + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
        firstStart[i + 1] += firstStart[i];
        secondStart[i + 1] += secondStart[i];
    }
    secondPairs.resize(pairs);
    std::vector<std::int32_t> fill(secondStart.begin(), secondStart.end() - 1);
    for (std::size_t p = 0; p < pairs; ++p) {
        secondPairs[std::size_t(fill[std::size_t(second[p])]++)] = std::int32_t(p);
    }
}

} // namespace grainlab
