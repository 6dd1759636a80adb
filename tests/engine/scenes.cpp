#include "scenes.h"

#include <map>
#include <mutex>
#include <tuple>

namespace grainlab::test {

SimulationState denseAssembly(int count, double aspect) {
    static std::mutex lock;
    static std::map<std::tuple<int, double>, SimulationState> cache;
    std::lock_guard<std::mutex> guard(lock);
    const auto key = std::make_tuple(count, aspect);
    auto it = cache.find(key);
    if (it == cache.end()) {
        SimulationParameters p;
        p.friction = 0.0;
        Simulation sim = compacted(smallAssembly(count, aspect, 1234, p), 1e5, 40000);
        sim.clearVelocities();
        SimulationState s = sim.state();
        it = cache.emplace(key, std::move(s)).first;
    }
    return it->second;
}

} // namespace grainlab::test
