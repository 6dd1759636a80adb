// The neighbour list of Simulation (simulation.h): a Verlet list of grain pairs at their
// periodic image, built with a cell list in the fractional coordinates of the deforming cell,
// carrying the contact history over rebuilds; and the test of when it must be rebuilt.
// Runs on the thread that drives the Simulation, between steps.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "grainlab/periodic_cell.h"
#include "grainlab/simulation.h"

namespace grainlab {

void Simulation::refuseNarrowCell() const {
    const auto widths = cellWidths(s_.cell);
    const double needed = 4.0 * maxHalfWidth_;
    for (int d = 0; d < 2; ++d) {
        if (!(widths[d] > needed)) {
            throw SimulationError(
                s_.step, -1,
                fmt::format("the cell is {:.6g} m wide across axis {}, narrower than two largest "
                            "grains ({:.6g} m); periodic images would touch",
                            widths[d], d + 1, needed));
        }
    }
}

void Simulation::rebuildNeighbours() {
    refuseNarrowCell();
    ++rebuilds_;
    const std::size_t n = s_.grains.size();
    const auto& h = s_.cell;
    const double det = cellDeterminant(h);
    auto& g = s_.grains;

    // 1. Wrap every centre into the cell, remembering the whole cells subtracted so that the
    //    stored image shifts of the old pairs can be carried over: k' = k + w_B - w_A.
    std::vector<std::int32_t> wrap1(n), wrap2(n);
    std::vector<double> frac1(n), frac2(n);
    for (std::size_t i = 0; i < n; ++i) {
        double s1 = (h[3] * g.x1[i] - h[2] * g.x2[i]) / det;
        double s2 = (-h[1] * g.x1[i] + h[0] * g.x2[i]) / det;
        const double w1 = std::floor(s1), w2 = std::floor(s2);
        wrap1[i] = static_cast<std::int32_t>(w1);
        wrap2[i] = static_cast<std::int32_t>(w2);
        if (w1 != 0.0 || w2 != 0.0) {
            g.x1[i] -= h[0] * w1 + h[2] * w2;
            g.x2[i] -= h[1] * w1 + h[3] * w2;
        }
        frac1[i] = std::clamp(s1 - w1, 0.0, 1.0);
        frac2[i] = std::clamp(s2 - w2, 0.0, 1.0);
    }

    // 2. Cell list in fractional coordinates; bins at least one cut-off wide. The cell is wider
    //    than two cut-offs (refuseNarrowCell and the skin below), so each pair has one image.
    const auto widths = cellWidths(h);
    const double maxSkin = 0.45 * (std::min(widths[0], widths[1]) - 4.0 * maxHalfWidth_);
    const double skin = std::min(skin_, maxSkin);
    const double cutoff = 2.0 * maxHalfWidth_ + skin;
    const int nb1 = std::clamp(static_cast<int>(widths[0] / cutoff), 1, 1 << 14);
    const int nb2 = std::clamp(static_cast<int>(widths[1] / cutoff), 1, 1 << 14);
    std::vector<std::int32_t> binOf(n), binStart(std::size_t(nb1) * nb2 + 1, 0), binGrains(n);
    for (std::size_t i = 0; i < n; ++i) {
        const int b1 = std::min(nb1 - 1, static_cast<int>(frac1[i] * nb1));
        const int b2 = std::min(nb2 - 1, static_cast<int>(frac2[i] * nb2));
        binOf[i] = b1 * nb2 + b2;
        ++binStart[binOf[i] + 1];
    }
    for (std::size_t b = 0; b + 1 < binStart.size(); ++b) {
        binStart[b + 1] += binStart[b];
    }
    {
        std::vector<std::int32_t> fill(binStart.begin(), binStart.end() - 1);
        for (std::size_t i = 0; i < n; ++i) {
            binGrains[fill[binOf[i]]++] = static_cast<std::int32_t>(i);
        }
    }

    // 3. Candidate pairs (i < j) within a_i + a_j + skin, in (i, j) order.
    PairArrays next;
    struct Candidate {
        std::int32_t j, k1, k2;
    };
    std::vector<Candidate> found;
    for (std::size_t i = 0; i < n; ++i) {
        found.clear();
        const int b1 = binOf[i] / nb2, b2 = binOf[i] % nb2;
        for (int o1 = -1; o1 <= 1; ++o1) {
            for (int o2 = -1; o2 <= 1; ++o2) {
                int c1 = b1 + o1, c2 = b2 + o2, k1 = 0, k2 = 0;
                if (c1 < 0) {
                    c1 += nb1;
                    k1 = -1;
                }
                if (c1 >= nb1) {
                    c1 -= nb1;
                    k1 = 1;
                }
                if (c2 < 0) {
                    c2 += nb2;
                    k2 = -1;
                }
                if (c2 >= nb2) {
                    c2 -= nb2;
                    k2 = 1;
                }
                const int bin = c1 * nb2 + c2;
                for (int q = binStart[bin]; q < binStart[bin + 1]; ++q) {
                    const std::int32_t j = binGrains[q];
                    if (j <= std::int32_t(i)) {
                        continue;
                    }
                    const double l1 = g.x1[j] + h[0] * k1 + h[2] * k2 - g.x1[i];
                    const double l2 = g.x2[j] + h[1] * k1 + h[3] * k2 - g.x2[i];
                    const double reach = halfWidth_[i] + halfWidth_[j] + skin;
                    if (l1 * l1 + l2 * l2 < reach * reach) {
                        found.push_back({j, k1, k2});
                    }
                }
            }
        }
        std::sort(found.begin(), found.end(),
                  [](const Candidate& a, const Candidate& b) { return a.j < b.j; });
        for (const Candidate& c : found) {
            next.first.push_back(static_cast<std::int32_t>(i));
            next.second.push_back(c.j);
            next.shift1.push_back(c.k1);
            next.shift2.push_back(c.k2);
        }
    }
    next.tangentialForce.assign(next.first.size(), 0.0);
    next.sliding.assign(next.first.size(), 0);

    // 4. Carry the contact history over: both lists are sorted by (first, second).
    const PairArrays& old = s_.pairs;
    std::size_t q = 0;
    for (std::size_t p = 0; p < next.size(); ++p) {
        while (q < old.size() &&
               (old.first[q] < next.first[p] ||
                (old.first[q] == next.first[p] && old.second[q] < next.second[p]))) {
            ++q;
        }
        if (q < old.size() && old.first[q] == next.first[p] && old.second[q] == next.second[p]) {
            const std::int32_t a = old.first[q], b = old.second[q];
            const std::int32_t k1 = old.shift1[q] + wrap1[b] - wrap1[a];
            const std::int32_t k2 = old.shift2[q] + wrap2[b] - wrap2[a];
            if (k1 == next.shift1[p] && k2 == next.shift2[p]) {
                next.tangentialForce[p] = old.tangentialForce[q];
                next.sliding[p] = old.sliding[q];
            }
        }
    }
    s_.pairs = std::move(next);
    s_.reference1 = g.x1;
    s_.reference2 = g.x2;
    s_.referenceCell = h;
    skinInUse_ = skin;
    buildPairIndex();
}

void Simulation::buildPairIndex() {
    const std::size_t n = s_.grains.size(), pairCount = s_.pairs.size();
    const auto& first = s_.pairs.first;
    const auto& second = s_.pairs.second;
    for (std::size_t p = 1; p < pairCount; ++p) {
        if (first[p] < first[p - 1]) {
            throw std::invalid_argument("simulation: the pairs must be sorted by first grain");
        }
    }
    pairIndex_.build(n, first, second);
    for (auto* v : {&pairForce1_, &pairForce2_, &torqueFirst_, &torqueSecond_, &normalForce_}) {
        v->assign(pairCount, 0.0);
    }
    pairHalfWidthFirst_.resize(pairCount);
    pairHalfWidthSecond_.resize(pairCount);
    for (std::size_t p = 0; p < pairCount; ++p) {
        pairHalfWidthFirst_[p] = halfWidth_[first[p]];
        pairHalfWidthSecond_[p] = halfWidth_[second[p]];
    }
    if (skinInUse_ <= 0.0) {
        // A restart: the skin of the stored list, from the cell it was built in.
        const auto widths = cellWidths(s_.referenceCell);
        skinInUse_ = std::min(skin_, 0.45 * (std::min(widths[0], widths[1]) - 4.0 * maxHalfWidth_));
    }
}

bool Simulation::neighboursStale() const {
    // An unlisted pair was at least a_i + a_j + skin apart at the rebuild. The affine map F
    // shrinks that distance by at most |F - I| (2 a_max + skin), each grain's own drift by at
    // most maxDrift_: the list is exact while 2 drift + |F - I| (2 a_max + skin) < skin.
    const auto F = cellProduct(s_.cell, cellInverse(s_.referenceCell));
    const double distortion = spectralNormOfDifferenceFromIdentity(F);
    return 2.0 * maxDrift_ + distortion * (2.0 * maxHalfWidth_ + skinInUse_) >= skinInUse_;
}

} // namespace grainlab
