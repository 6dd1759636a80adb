#include "grainlab/simulation_state.h"

#include <cstring>

namespace grainlab {

void GrainArrays::resize(std::size_t n) {
    for (auto* v : {&x1, &x2, &theta, &v1, &v2, &omega}) {
        v->resize(n, 0.0);
    }
    shape.resize(n, 0);
}

void PairArrays::resize(std::size_t n) {
    first.resize(n);
    second.resize(n);
    shift1.resize(n);
    shift2.resize(n);
    tangentialForce.resize(n);
    sliding.resize(n);
}

namespace {

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <typename T, std::size_t N>
bool sameBits(const std::array<T, N>& a, const std::array<T, N>& b) {
    return std::memcmp(a.data(), b.data(), N * sizeof(T)) == 0;
}

} // namespace

bool identicalDynamics(const SimulationState& a, const SimulationState& b) {
    const auto& g = a.grains;
    const auto& h = b.grains;
    const auto& p = a.pairs;
    const auto& q = b.pairs;
    return sameBits(g.x1, h.x1) && sameBits(g.x2, h.x2) && sameBits(g.theta, h.theta) &&
           sameBits(g.v1, h.v1) && sameBits(g.v2, h.v2) && sameBits(g.omega, h.omega) &&
           sameBits(p.first, q.first) && sameBits(p.second, q.second) &&
           sameBits(p.shift1, q.shift1) && sameBits(p.shift2, q.shift2) &&
           sameBits(p.tangentialForce, q.tangentialForce) && sameBits(p.sliding, q.sliding) &&
           sameBits(a.cell, b.cell) && sameBits(a.velocityGradient, b.velocityGradient) &&
           sameBits(a.servoIntegral, b.servoIntegral) && a.step == b.step &&
           sameBits(std::array<double, 4>{a.time, a.boundaryWork, a.frictionWork, a.dampingWork},
                    std::array<double, 4>{b.time, b.boundaryWork, b.frictionWork, b.dampingWork});
}

} // namespace grainlab
