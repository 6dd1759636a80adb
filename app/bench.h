#pragma once
// `grainlab bench`: times the engine on a dense periodic assembly under biaxial compression
// and prints grain-steps per second. Runs on the main thread.

#include <cstdint>
#include <string>

namespace grainlab {

struct BenchOptions {
    std::string shape = "oval";   ///< "oval", "disk" or "both"
    int grains = 8450;
    std::int64_t steps = 20000;   ///< timed steps
    std::string threads = "1,2";  ///< thread counts to time, comma separated
    std::uint64_t seed = 42;
};

int runBench(const BenchOptions& options);

} // namespace grainlab
