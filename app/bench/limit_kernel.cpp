#include "bench/limit_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/contact_law.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/simulation.h"

namespace grainlab {

LimitKernel::LimitKernel(const SimulationState& state, double axialStrainRate, int threads)
    : threads_(threads) {
    const SimulationParameters& p = state.parameters;
    if (threads < 1) {
        throw std::invalid_argument(
            fmt::format("limit kernel: threads = {}: must be >= 1", threads));
    }
    if (p.damping.kind != DampingKind::GlobalViscous) {
        throw std::invalid_argument("limit kernel: only global viscous damping (the default)");
    }
    timeStep_ = p.timeStep;
    normalStiffness_ = p.normalStiffness;
    tangentialStiffness_ = p.tangentialStiffness;
    friction_ = p.friction;
    strainRate_ = axialStrainRate;
    cell_ = state.cell;
    const std::size_t n = state.grains.size();
    x1_ = state.grains.x1;
    x2_ = state.grains.x2;
    v1_ = state.grains.v1;
    v2_ = state.grains.v2;
    omega_ = state.grains.omega;
    radius_.resize(n);
    for (auto* v : {&keepTrans_, &pushTrans_, &keepRot_, &pushRot_}) {
        v->resize(n);
    }
    // The engine's coefficients (Simulation::derive, prepareIntegration), in the same order.
    const double dt = timeStep_, beta = p.damping.coefficient;
    double minWidth = std::numeric_limits<double>::infinity();
    maxRadius_ = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const OvalShape& s = state.shapes.at(std::size_t(state.grains.shape[i]));
        if (!s.isDisk) {
            throw std::invalid_argument("limit kernel: disks only");
        }
        radius_[i] = s.halfWidth;
        const double mass = p.density * s.area, inertia = p.density * s.polarMoment;
        const double dampTrans = 2.0 * std::sqrt(p.normalStiffness * mass);
        const double dampRot =
            2.0 * std::sqrt(p.normalStiffness * s.halfWidth * s.halfWidth * inertia);
        const double ht = 0.5 * dt * beta * dampTrans / mass;
        const double hr = 0.5 * dt * beta * dampRot / inertia;
        keepTrans_[i] = (1.0 - ht) / (1.0 + ht);
        pushTrans_[i] = dt / mass / (1.0 + ht);
        keepRot_[i] = (1.0 - hr) / (1.0 + hr);
        pushRot_[i] = dt / inertia / (1.0 + hr);
        maxRadius_ = std::max(maxRadius_, s.halfWidth);
        minWidth = std::min(minWidth, s.width);
    }
    skin_ = p.neighbourSkin > 0 ? p.neighbourSkin : 0.1 * minWidth;
    first_ = state.pairs.first;
    second_ = state.pairs.second;
    shift1_ = state.pairs.shift1;
    shift2_ = state.pairs.shift2;
    tangential_ = state.pairs.tangentialForce;
    if (state.reference1.size() == n && state.reference2.size() == n &&
        cellDeterminant(state.referenceCell) > 0.0) {
        // As the engine does: keep the stored list, its reference and its skin.
        reference1_ = state.reference1;
        reference2_ = state.reference2;
        referenceCell_ = state.referenceCell;
        const auto widths = cellWidths(referenceCell_);
        skinInUse_ = std::min(skin_, 0.45 * (std::min(widths[0], widths[1]) - 4.0 * maxRadius_));
        buildIndex();
    } else {
        rebuild();
    }
    pairForces(0.0); // the initial forces: a zero time step leaves every stored f_t as it is
}

void LimitKernel::rebuild() {
    ++rebuilds_;
    const std::size_t n = x1_.size();
    const auto& h = cell_;
    const double det = cellDeterminant(h);
    // Wrap the centres into the cell; remember the wraps to carry the history over.
    std::vector<std::int32_t> wrap1(n), wrap2(n);
    std::vector<double> frac1(n), frac2(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double s1 = (h[3] * x1_[i] - h[2] * x2_[i]) / det;
        const double s2 = (-h[1] * x1_[i] + h[0] * x2_[i]) / det;
        const double w1 = std::floor(s1), w2 = std::floor(s2);
        wrap1[i] = std::int32_t(w1);
        wrap2[i] = std::int32_t(w2);
        if (w1 != 0.0 || w2 != 0.0) {
            x1_[i] -= h[0] * w1 + h[2] * w2;
            x2_[i] -= h[1] * w1 + h[3] * w2;
        }
        frac1[i] = std::clamp(s1 - w1, 0.0, 1.0);
        frac2[i] = std::clamp(s2 - w2, 0.0, 1.0);
    }
    const auto widths = cellWidths(h);
    const double skin = std::min(skin_, 0.45 * (std::min(widths[0], widths[1]) - 4.0 * maxRadius_));
    if (!(skin > 0.0)) {
        throw std::invalid_argument("limit kernel: the cell is narrower than two largest grains");
    }
    const double cutoff = 2.0 * maxRadius_ + skin;
    const int nb1 = std::clamp(int(widths[0] / cutoff), 1, 1 << 14);
    const int nb2 = std::clamp(int(widths[1] / cutoff), 1, 1 << 14);
    std::vector<std::int32_t> binOf(n), binStart(std::size_t(nb1) * nb2 + 1, 0), binGrains(n);
    for (std::size_t i = 0; i < n; ++i) {
        binOf[i] =
            std::min(nb1 - 1, int(frac1[i] * nb1)) * nb2 + std::min(nb2 - 1, int(frac2[i] * nb2));
        ++binStart[binOf[i] + 1];
    }
    for (std::size_t b = 0; b + 1 < binStart.size(); ++b) {
        binStart[b + 1] += binStart[b];
    }
    std::vector<std::int32_t> fill(binStart.begin(), binStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        binGrains[fill[binOf[i]]++] = std::int32_t(i);
    }
    // Pairs i < j within r_i + r_j + skin, sorted by (i, j); one image per pair (wide cell).
    struct Candidate {
        std::int32_t j, k1, k2;
    };
    std::vector<std::int32_t> first, second, shift1, shift2;
    std::vector<Candidate> found;
    for (std::size_t i = 0; i < n; ++i) {
        found.clear();
        const int b1 = binOf[i] / nb2, b2 = binOf[i] % nb2;
        for (int o1 = -1; o1 <= 1; ++o1) {
            for (int o2 = -1; o2 <= 1; ++o2) {
                const int c1 = b1 + o1, c2 = b2 + o2;
                const int k1 = c1 < 0 ? -1 : (c1 >= nb1 ? 1 : 0);
                const int k2 = c2 < 0 ? -1 : (c2 >= nb2 ? 1 : 0);
                const int bin = (c1 - k1 * nb1) * nb2 + (c2 - k2 * nb2);
                for (int q = binStart[bin]; q < binStart[bin + 1]; ++q) {
                    const std::int32_t j = binGrains[q];
                    if (j <= std::int32_t(i)) {
                        continue;
                    }
                    const double l1 = x1_[j] + h[0] * k1 + h[2] * k2 - x1_[i];
                    const double l2 = x2_[j] + h[1] * k1 + h[3] * k2 - x2_[i];
                    const double reach = radius_[i] + radius_[j] + skin;
                    if (l1 * l1 + l2 * l2 < reach * reach) {
                        found.push_back({j, k1, k2});
                    }
                }
            }
        }
        std::sort(found.begin(), found.end(),
                  [](const Candidate& a, const Candidate& b) { return a.j < b.j; });
        for (const Candidate& c : found) {
            first.push_back(std::int32_t(i));
            second.push_back(c.j);
            shift1.push_back(c.k1);
            shift2.push_back(c.k2);
        }
    }
    // Carry the tangential history over (both lists sorted by (first, second)).
    std::vector<double> tangential(first.size(), 0.0);
    std::size_t q = 0;
    for (std::size_t p = 0; p < first.size(); ++p) {
        while (q < first_.size() &&
               (first_[q] < first[p] || (first_[q] == first[p] && second_[q] < second[p]))) {
            ++q;
        }
        if (q < first_.size() && first_[q] == first[p] && second_[q] == second[p] &&
            shift1_[q] + wrap1[second[p]] - wrap1[first[p]] == shift1[p] &&
            shift2_[q] + wrap2[second[p]] - wrap2[first[p]] == shift2[p]) {
            tangential[p] = tangential_[q];
        }
    }
    first_ = std::move(first);
    second_ = std::move(second);
    shift1_ = std::move(shift1);
    shift2_ = std::move(shift2);
    tangential_ = std::move(tangential);
    reference1_ = x1_;
    reference2_ = x2_;
    referenceCell_ = h;
    skinInUse_ = skin;
    buildIndex();
}

void LimitKernel::buildIndex() {
    const std::size_t n = x1_.size();
    const std::size_t pairs = first_.size();
    pairIndex_.build(n, first_, second_);
    radiusFirst_.resize(pairs);
    radiusSecond_.resize(pairs);
    for (std::size_t p = 0; p < pairs; ++p) {
        radiusFirst_[p] = radius_[first_[p]];
        radiusSecond_[p] = radius_[second_[p]];
    }
    for (auto* v : {&force1_, &force2_, &torqueFirst_, &torqueSecond_}) {
        v->assign(pairs, 0.0);
    }
}

void LimitKernel::pairForces(double dt) {
    const std::size_t pairs = first_.size();
    const int blocks = reductionBlocks(pairs);
    const ContactLawParameters parameters =
        contactLawParameters(normalStiffness_, tangentialStiffness_, friction_, dt);
    const double h0 = cell_[0], h1 = cell_[1], h2 = cell_[2], h3 = cell_[3];
    const double L0 = L_[0], L1 = L_[1], L2 = L_[2], L3 = L_[3];
    const std::int32_t* first = first_.data();
    const std::int32_t* second = second_.data();
    const std::int32_t* shift1 = shift1_.data();
    const std::int32_t* shift2 = shift2_.data();
    const double* x1 = x1_.data();
    const double* x2 = x2_.data();
    const double* v1 = v1_.data();
    const double* v2 = v2_.data();
    const double* omega = omega_.data();
    const double* radiusA = radiusFirst_.data();
    const double* radiusB = radiusSecond_.data();
    double* stored = tangential_.data();
    double* force1 = force1_.data();
    double* force2 = force2_.data();
    double* torqueA = torqueFirst_.data();
    double* torqueB = torqueSecond_.data();
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (int b = 0; b < blocks; ++b) {
        const std::size_t begin = std::size_t(b) * kReductionBlock;
        const std::size_t end = std::min(pairs, begin + kReductionBlock);
#pragma omp simd
        for (std::size_t p = begin; p < end; ++p) {
            const std::int32_t i = first[p], j = second[p];
            const double k1 = shift1[p], k2 = shift2[p];
            const double l1 = x1[j] + h0 * k1 + h2 * k2 - x1[i];
            const double l2 = x2[j] + h1 * k1 + h3 * k2 - x2[i];
            // The engine's disk geometry and contact law: the same inline kernels its pair loop
            // calls, in the same order.
            const double d2 = l1 * l1 + l2 * l2;
            const ContactGeometry g = diskContact(radiusA[p], radiusA[p] + radiusB[p], l1, l2);
            const bool touching = (d2 > 0.0) & (g.overlap > 0.0);
            const double n1 = g.normalX, n2 = g.normalY, t1 = -n2, t2 = n1;
            const double pA1 = g.pointX, pA2 = g.pointY;
            ContactForce law;
            law.normal = touching ? normalContactForce(g.overlap, parameters) : 0.0;
            const double pB1 = pA1 - l1, pB2 = pA2 - l2;
            const double vr1 = v1[j] - v1[i] + L0 * l1 + L2 * l2 - omega[j] * pB2 + omega[i] * pA2;
            const double vr2 = v2[j] - v2[i] + L1 * l1 + L3 * l2 + omega[j] * pB1 - omega[i] * pA1;
            tangentialContactForce(law.normal, vr1 * t1 + vr2 * t2, stored[p], parameters, law);
            const double fn = law.normal;
            const double ft = touching ? law.tangential : 0.0;
            const double f1 = fn * n1 + ft * t1, f2 = fn * n2 + ft * t2;
            stored[p] = ft;
            force1[p] = f1;
            force2[p] = f2;
            torqueA[p] = -(pA1 * f2 - pA2 * f1);
            torqueB[p] = (pA1 - l1) * f2 - (pA2 - l2) * f1;
        }
    }
}

void LimitKernel::integrate() {
    const std::size_t n = x1_.size();
    const double dt = timeStep_;
    const double L0 = L_[0], L1 = L_[1], L2 = L_[2], L3 = L_[3];
    const auto& h = cell_;
    const std::array<double, 4> hNext = {
        h[0] + dt * (L0 * h[0] + L2 * h[1]), h[1] + dt * (L1 * h[0] + L3 * h[1]),
        h[2] + dt * (L0 * h[2] + L2 * h[3]), h[3] + dt * (L1 * h[2] + L3 * h[3])};
    const auto F = cellProduct(hNext, cellInverse(referenceCell_));
    const double F0 = F[0], F1 = F[1], F2 = F[2], F3 = F[3];
    double* x1 = x1_.data();
    double* x2 = x2_.data();
    double* v1 = v1_.data();
    double* v2 = v2_.data();
    double* omega = omega_.data();
    const double* ref1 = reference1_.data();
    const double* ref2 = reference2_.data();
    const double* keepT = keepTrans_.data();
    const double* pushT = pushTrans_.data();
    const double* keepR = keepRot_.data();
    const double* pushR = pushRot_.data();
    const double* pairF1 = force1_.data();
    const double* pairF2 = force2_.data();
    const double* pairTA = torqueFirst_.data();
    const double* pairTB = torqueSecond_.data();
    const std::int32_t* firstStart = pairIndex_.firstStart.data();
    const std::int32_t* secondStart = pairIndex_.secondStart.data();
    const std::int32_t* secondPairs = pairIndex_.secondPairs.data();
    const int blocks = reductionBlocks(n);
    double maxDrift2 = 0.0;
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : maxDrift2)
    for (int b = 0; b < blocks; ++b) {
        const std::size_t begin = std::size_t(b) * kReductionBlock;
        const std::size_t end = std::min(n, begin + kReductionBlock);
        double force1[kReductionBlock], force2[kReductionBlock], torque[kReductionBlock];
        for (std::size_t i = begin; i < end; ++i) {
            const GrainSum sum =
                sumOnGrain(i, firstStart, secondStart, secondPairs, pairF1, pairF2, pairTA, pairTB);
            force1[i - begin] = sum.f1;
            force2[i - begin] = sum.f2;
            torque[i - begin] = sum.torque;
        }
#pragma omp simd reduction(max : maxDrift2)
        for (std::size_t i = begin; i < end; ++i) {
            const double n1 = keepT[i] * v1[i] + pushT[i] * force1[i - begin];
            const double n2 = keepT[i] * v2[i] + pushT[i] * force2[i - begin];
            const double nw = keepR[i] * omega[i] + pushR[i] * torque[i - begin];
            const double y1 = x1[i], y2 = x2[i];
            const double z1 = y1 + dt * (n1 + L0 * y1 + L2 * y2);
            const double z2 = y2 + dt * (n2 + L1 * y1 + L3 * y2);
            v1[i] = n1;
            v2[i] = n2;
            omega[i] = nw;
            x1[i] = z1;
            x2[i] = z2;
            const double d1 = z1 - (F0 * ref1[i] + F2 * ref2[i]);
            const double d2 = z2 - (F1 * ref1[i] + F3 * ref2[i]);
            maxDrift2 = std::max(maxDrift2, d1 * d1 + d2 * d2);
        }
    }
    cell_ = hNext;
    maxDrift_ = std::sqrt(maxDrift2);
}

void LimitKernel::advance(std::int64_t steps) {
    for (std::int64_t k = 0; k < steps; ++k) {
        // Axis 1 at a constant (true) strain rate, as the bench drives the engine's axis 1;
        // axis 2 held (no servo).
        L_[0] = -strainRate_;
        integrate();
        // The engine's skin criterion (Simulation::neighboursStale).
        const auto F = cellProduct(cell_, cellInverse(referenceCell_));
        const double distortion = spectralNormOfDifferenceFromIdentity(F);
        if (2.0 * maxDrift_ + distortion * (2.0 * maxRadius_ + skinInUse_) >= skinInUse_) {
            rebuild();
        }
        pairForces(timeStep_);
    }
}

std::size_t LimitKernel::contactCount() const {
    std::size_t count = 0;
    for (std::size_t p = 0; p < first_.size(); ++p) {
        // Touching pairs carry a nonzero force; an exactly tangent pair counts as open.
        count += (force1_[p] != 0.0 || force2_[p] != 0.0) ? 1 : 0;
    }
    return count;
}

void LimitKernel::netForces(std::vector<double>& f1, std::vector<double>& f2,
                            std::vector<double>& torque) const {
    const std::size_t n = x1_.size();
    f1.assign(n, 0.0);
    f2.assign(n, 0.0);
    torque.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const GrainSum sum =
            sumOnGrain(i, pairIndex_.firstStart.data(), pairIndex_.secondStart.data(),
                       pairIndex_.secondPairs.data(), force1_.data(), force2_.data(),
                       torqueFirst_.data(), torqueSecond_.data());
        f1[i] = sum.f1;
        f2[i] = sum.f2;
        torque[i] = sum.torque;
    }
}

} // namespace grainlab
