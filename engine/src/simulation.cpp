#include "grainlab/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "grainlab/contact_geometry.h"
#include "grainlab/contact_law.h"
#include "grainlab/periodic_cell.h"

namespace grainlab {
namespace {

int blockCount(std::size_t n) { return static_cast<int>((n + kReductionBlock - 1) / kReductionBlock); }

} // namespace

SimulationError::SimulationError(std::int64_t step_, std::int32_t grain_, std::string cause_)
    : std::runtime_error(grain_ >= 0 ? fmt::format("step {}: grain {}: {}", step_, grain_, cause_)
                                     : fmt::format("step {}: {}", step_, cause_)),
      step(step_), grain(grain_), cause(std::move(cause_)) {}

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

TimeStepLimit criticalTimeStep(const std::vector<OvalShape>& shapes,
                               const SimulationParameters& p) {
    // Central differences are stable for omega_max * dt < 2. The stiffest grain with z contacts
    // has a translational stiffness z * max(k_n, k_t) and a rotational stiffness of at most
    // z * max(k_n, k_t) * a^2 (every contact force has a lever arm of at most a).
    TimeStepLimit out;
    out.translational = out.rotational = std::numeric_limits<double>::infinity();
    const double k = std::max(p.normalStiffness, p.tangentialStiffness) *
                     std::max(1, p.stability.designCoordination);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const OvalShape& s = shapes[i];
        const double m = p.density * s.area, inertia = p.density * s.polarMoment;
        const double t = 2.0 * std::sqrt(m / k);
        const double r = 2.0 * std::sqrt(inertia / (k * s.halfWidth * s.halfWidth));
        out.translational = std::min(out.translational, t);
        if (r < out.rotational) {
            out.rotational = r;
        }
        if (std::min(t, r) < out.limit || i == 0) {
            out.limit = std::min(t, r);
            out.stiffestShape = static_cast<int>(i);
        }
    }
    out.limit = std::min(out.translational, out.rotational);
    return out;
}

std::string checkTimeStep(const std::vector<OvalShape>& shapes, const SimulationParameters& p) {
    const TimeStepLimit lim = criticalTimeStep(shapes, p);
    const double dt = p.timeStep;
    if (!(dt > 0.0) || !std::isfinite(dt)) {
        throw std::invalid_argument(fmt::format("time step {} s: must be > 0", dt));
    }
    const auto describe = [&] {
        return fmt::format("the stable limit is {:.4g} s (translational {:.4g} s, rotational "
                           "{:.4g} s, set by the grain of width {:.4g} m with {} contacts)",
                           lim.limit, lim.translational, lim.rotational,
                           shapes[lim.stiffestShape].width, p.stability.designCoordination);
    };
    if (dt > lim.limit) {
        throw std::invalid_argument(
            fmt::format("time step {:.4g} s is above {}; use at most {:.4g} s", dt, describe(),
                        lim.limit));
    }
    if (dt > 0.8 * lim.limit) {
        return fmt::format("time step {:.4g} s is within 20 % of {}", dt, describe());
    }
    return {};
}

Simulation::Simulation(SimulationState state) : s_(std::move(state)) {
    const std::size_t n = s_.grains.size();
    if (s_.shapes.empty()) {
        throw std::invalid_argument("simulation: the shape table is empty");
    }
    for (auto* v : {&s_.grains.x2, &s_.grains.theta, &s_.grains.v1, &s_.grains.v2,
                    &s_.grains.omega}) {
        if (v->size() != n) {
            throw std::invalid_argument("simulation: grain arrays of unequal length");
        }
    }
    if (s_.grains.shape.size() != n) {
        throw std::invalid_argument("simulation: grain arrays of unequal length");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (s_.grains.shape[i] < 0 || s_.grains.shape[i] >= std::int32_t(s_.shapes.size())) {
            throw std::invalid_argument(
                fmt::format("simulation: grain {} has shape index {} outside [0, {})", i,
                            s_.grains.shape[i], s_.shapes.size()));
        }
    }
    if (!(cellDeterminant(s_.cell) > 0.0)) {
        throw std::invalid_argument("simulation: the cell matrix must have a positive determinant");
    }
    if (s_.parameters.threads < 1) {
        throw std::invalid_argument(
            fmt::format("simulation: threads = {}: must be >= 1", s_.parameters.threads));
    }
    checkTimeStep(s_.shapes, s_.parameters);
    derive();
    const bool haveList = s_.reference1.size() == n && s_.reference2.size() == n &&
                          cellDeterminant(s_.referenceCell) > 0.0;
    if (haveList) {
        refuseNarrowCell();
        // Restart: keep the stored list as it is, so the run continues bit for bit.
        const std::size_t pairCount = s_.pairs.size();
        for (std::size_t p = 0; p < pairCount; ++p) {
            if (s_.pairs.first[p] < 0 || s_.pairs.second[p] < 0 ||
                s_.pairs.first[p] >= std::int32_t(n) || s_.pairs.second[p] >= std::int32_t(n)) {
                throw std::invalid_argument(fmt::format("simulation: pair {} names a grain "
                                                        "outside [0, {})", p, n));
            }
        }
        buildPairIndex();
    } else {
        rebuildNeighbours();
    }
    evaluateForces(false);
}

void Simulation::derive() {
    const std::size_t n = s_.grains.size();
    const auto& p = s_.parameters;
    mass_.resize(n);
    inertia_.resize(n);
    invMass_.resize(n);
    invInertia_.resize(n);
    halfWidth_.resize(n);
    halfHeight_.resize(n);
    dampTrans_.resize(n);
    dampRot_.resize(n);
    cosTheta_.resize(n);
    sinTheta_.resize(n);
    force1_.assign(n, 0.0);
    force2_.assign(n, 0.0);
    torque_.assign(n, 0.0);
    allDisks_ = true;
    maxHalfWidth_ = 0;
    double minWidth = std::numeric_limits<double>::infinity();
    for (const OvalShape& s : s_.shapes) {
        allDisks_ = allDisks_ && s.isDisk;
    }
    allDisks_ = allDisks_ && !p.ovalPathForDisks;
    for (std::size_t i = 0; i < n; ++i) {
        const OvalShape& s = s_.shapes[s_.grains.shape[i]];
        mass_[i] = p.density * s.area;
        inertia_[i] = p.density * s.polarMoment;
        invMass_[i] = 1.0 / mass_[i];
        invInertia_[i] = 1.0 / inertia_[i];
        halfWidth_[i] = s.halfWidth;
        halfHeight_[i] = s.halfHeight;
        // Fraction beta of the critical damping of one grain on one normal spring (SPEC §3.6).
        dampTrans_[i] = 2.0 * std::sqrt(p.normalStiffness * mass_[i]);
        dampRot_[i] = 2.0 * std::sqrt(p.normalStiffness * s.halfWidth * s.halfWidth * inertia_[i]);
        cosTheta_[i] = std::cos(s_.grains.theta[i]);
        sinTheta_[i] = std::sin(s_.grains.theta[i]);
        maxHalfWidth_ = std::max(maxHalfWidth_, s.halfWidth);
        minWidth = std::min(minWidth, s.width);
    }
    skin_ = p.neighbourSkin > 0 ? p.neighbourSkin : 0.1 * minWidth;
}

double Simulation::cellArea() const { return cellDeterminant(s_.cell); }

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
                if (c1 < 0) { c1 += nb1; k1 = -1; }
                if (c1 >= nb1) { c1 -= nb1; k1 = 1; }
                if (c2 < 0) { c2 += nb2; k2 = -1; }
                if (c2 >= nb2) { c2 -= nb2; k2 = 1; }
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
        while (q < old.size() && (old.first[q] < next.first[p] ||
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
    grainPairStart_.assign(n + 1, 0);
    for (std::size_t p = 0; p < pairCount; ++p) {
        ++grainPairStart_[s_.pairs.first[p] + 1];
        ++grainPairStart_[s_.pairs.second[p] + 1];
    }
    for (std::size_t i = 0; i < n; ++i) {
        grainPairStart_[i + 1] += grainPairStart_[i];
    }
    grainPairs_.resize(2 * pairCount);
    std::vector<std::int32_t> fill(grainPairStart_.begin(), grainPairStart_.end() - 1);
    for (std::size_t p = 0; p < pairCount; ++p) {
        grainPairs_[fill[s_.pairs.first[p]]++] = static_cast<std::int32_t>(2 * p);
        grainPairs_[fill[s_.pairs.second[p]]++] = static_cast<std::int32_t>(2 * p + 1);
    }
    pairForce1_.assign(pairCount, 0.0);
    pairForce2_.assign(pairCount, 0.0);
    torqueFirst_.assign(pairCount, 0.0);
    torqueSecond_.assign(pairCount, 0.0);
    normalForce_.assign(pairCount, 0.0);
    slipWork_.assign(pairCount, 0.0);
    if (skinInUse_ <= 0.0) {
        const auto widths = cellWidths(s_.cell);
        skinInUse_ = std::min(skin_, 0.45 * (std::min(widths[0], widths[1]) - 4.0 * maxHalfWidth_));
    }
}

void Simulation::evaluateForces(bool increment) {
    const bool frictional = s_.parameters.friction > 0.0;
    if (allDisks_) {
        if (frictional) {
            increment ? pairForces<true, true, true>() : pairForces<true, true, false>();
        } else {
            pairForces<true, false, false>();
        }
    } else {
        if (frictional) {
            increment ? pairForces<false, true, true>() : pairForces<false, true, false>();
        } else {
            pairForces<false, false, false>();
        }
    }
    gatherForces();
}

template <bool Disk, bool Frictional, bool Increment>
void Simulation::pairForces() {
    const std::size_t pairCount = s_.pairs.size();
    const int blocks = blockCount(pairCount);
    const auto& h = s_.cell;
    const auto& L = s_.velocityGradient;
    const auto& g = s_.grains;
    auto& pairs = s_.pairs;
    const ContactLawParameters law{s_.parameters.normalStiffness, s_.parameters.tangentialStiffness,
                                   s_.parameters.friction, s_.parameters.timeStep};
    const double kn = law.normalStiffness, kt = Frictional ? law.tangentialStiffness : 0.0;
    const bool fullOvalTest = s_.parameters.allArcPairs;
    blockSums_.assign(std::size_t(blocks) * kBlockSumWidth, 0.0);
    double maxRatio = 0.0;

#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads) reduction(max : maxRatio)
    for (int b = 0; b < blocks; ++b) {
        double s11 = 0, s12 = 0, s21 = 0, s22 = 0, e1 = 0, e2 = 0, slip = 0;
        const std::size_t end = std::min(pairCount, std::size_t(b + 1) * kReductionBlock);
        for (std::size_t p = std::size_t(b) * kReductionBlock; p < end; ++p) {
            const std::int32_t i = pairs.first[p], j = pairs.second[p];
            const double k1 = pairs.shift1[p], k2 = pairs.shift2[p];
            const double l1 = g.x1[j] + h[0] * k1 + h[2] * k2 - g.x1[i];
            const double l2 = g.x2[j] + h[1] * k1 + h[3] * k2 - g.x2[i];
            const double reach = halfWidth_[i] + halfWidth_[j];
            ContactGeometry c;
            if (l1 * l1 + l2 * l2 < reach * reach) {
                if constexpr (Disk) {
                    c = diskContact(halfWidth_[i], halfWidth_[j], l1, l2);
                } else if (fullOvalTest) {
                    c = ovalContactAllPairs(s_.shapes[g.shape[i]], g.theta[i],
                                            s_.shapes[g.shape[j]], g.theta[j], l1, l2);
                } else {
                    c = ovalContact(s_.shapes[g.shape[i]], cosTheta_[i], sinTheta_[i],
                                    s_.shapes[g.shape[j]], cosTheta_[j], sinTheta_[j], l1, l2);
                }
            }
            if (!(c.overlap > 0.0)) {
                pairs.tangentialForce[p] = 0.0; // an open contact forgets its history
                pairs.sliding[p] = 0;
                pairForce1_[p] = pairForce2_[p] = torqueFirst_[p] = torqueSecond_[p] = 0.0;
                normalForce_[p] = 0.0;
                slipWork_[p] = 0.0;
                continue;
            }
            const double n1 = c.normalX, n2 = c.normalY, t1 = -n2, t2 = n1;
            const double fn = kn * c.overlap;
            double ft = 0.0;
            if constexpr (Frictional) {
                if constexpr (Increment) {
                    // Velocity of B relative to A at the contact point: fluctuating translation,
                    // rotation (omega x r in 2D is omega * (-r2, r1)) and the affine field L l.
                    const double pA1 = c.pointX, pA2 = c.pointY;
                    const double pB1 = pA1 - l1, pB2 = pA2 - l2;
                    const double vr1 = g.v1[j] - g.v1[i] + L[0] * l1 + L[2] * l2 -
                                       g.omega[j] * pB2 + g.omega[i] * pA2;
                    const double vr2 = g.v2[j] - g.v2[i] + L[1] * l1 + L[3] * l2 +
                                       g.omega[j] * pB1 - g.omega[i] * pA1;
                    const ContactForce f =
                        linearContactForce(c.overlap, vr1 * t1 + vr2 * t2,
                                           pairs.tangentialForce[p], law);
                    ft = f.tangential;
                    pairs.tangentialForce[p] = ft;
                    pairs.sliding[p] = f.sliding;
                    slipWork_[p] = f.slipWork;
                    slip += f.slipWork;
                } else {
                    ft = pairs.tangentialForce[p];
                }
            } else {
                pairs.tangentialForce[p] = 0.0;
                pairs.sliding[p] = 0;
            }
            const double f1 = fn * n1 + ft * t1, f2 = fn * n2 + ft * t2;
            pairForce1_[p] = f1;
            pairForce2_[p] = f2;
            normalForce_[p] = fn;
            // Torques (x_c - x) x F: on A from -F at p_A, on B from F at p_A - l.
            torqueFirst_[p] = -(c.pointX * f2 - c.pointY * f1);
            torqueSecond_[p] = (c.pointX - l1) * f2 - (c.pointY - l2) * f1;
            s11 += f1 * l1;
            s12 += f1 * l2;
            s21 += f2 * l1;
            s22 += f2 * l2;
            e1 += l1 * l1 * (kn * n1 * n1 + kt * t1 * t1);
            e2 += l2 * l2 * (kn * n2 * n2 + kt * t2 * t2);
            maxRatio = std::max(maxRatio, c.overlap / (2.0 * std::min(halfWidth_[i], halfWidth_[j])));
        }
        double* out = &blockSums_[std::size_t(b) * kBlockSumWidth];
        out[0] = s11;
        out[1] = s12;
        out[2] = s21;
        out[3] = s22;
        out[4] = e1;
        out[5] = e2;
        out[6] = slip;
    }
    double sum[kBlockSumWidth] = {};
    for (int b = 0; b < blocks; ++b) {
        for (int q = 0; q < kBlockSumWidth; ++q) {
            sum[q] += blockSums_[std::size_t(b) * kBlockSumWidth + q];
        }
    }
    const double area = cellArea();
    stress_.s11 = sum[0] / area;
    stress_.s22 = sum[3] / area;
    stress_.s12 = 0.5 * (sum[1] + sum[2]) / area;
    stiffness_ = {sum[4] / area, sum[5] / area};
    if constexpr (Increment) {
        s_.frictionWork += sum[6];
    }
    maxOverlapRatio_ = maxRatio;
}

void Simulation::gatherForces() {
    const std::int64_t n = static_cast<std::int64_t>(s_.grains.size());
#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads)
    for (std::int64_t i = 0; i < n; ++i) {
        double f1 = 0, f2 = 0, m = 0;
        for (std::int32_t q = grainPairStart_[i]; q < grainPairStart_[i + 1]; ++q) {
            const std::int32_t code = grainPairs_[q];
            const std::int32_t p = code >> 1;
            if (code & 1) { // grain is B: +F
                f1 += pairForce1_[p];
                f2 += pairForce2_[p];
                m += torqueSecond_[p];
            } else {        // grain is A: -F
                f1 -= pairForce1_[p];
                f2 -= pairForce2_[p];
                m += torqueFirst_[p];
            }
        }
        force1_[i] = f1;
        force2_[i] = f2;
        torque_[i] = m;
    }
}

void Simulation::updateServo() {
    auto& L = s_.velocityGradient;
    const auto& servo = s_.parameters.servo;
    const double dtServo = servo.interval * s_.parameters.timeStep;
    const bool servoStep = s_.step % std::max(1, servo.interval) == 0;
    for (int axis = 0; axis < 2; ++axis) {
        const AxisControl& control = s_.axes[axis];
        const int diagonal = axis == 0 ? 0 : 3;
        if (control.mode == AxisMode::Strain) {
            const double length = s_.cell[diagonal];
            L[diagonal] = control.referenceLength > 0.0
                              ? -control.strainRate * control.referenceLength / length
                              : -control.strainRate;
            continue;
        }
        if (!servoStep) {
            continue;
        }
        const double cap = servo.maxStrainRate;
        const double sigma = axis == 0 ? stress_.s11 : stress_.s22;
        const double error = control.targetStress - sigma;
        const double modulus = stiffness_[axis];
        double rate;
        if (modulus > 0.0) {
            // Over one servo interval the stress moves by at most the fraction g of its error
            // (the affine estimate over-predicts the true modulus); the integral term removes
            // the lag of a purely proportional servo during steady loading (SPEC §3.5).
            const double proportional = servo.gain * error / (modulus * dtServo);
            double& integral = s_.servoIntegral[axis];
            integral = std::clamp(integral + servo.integralGain * proportional, -cap, cap);
            rate = std::clamp(proportional + integral, -cap, cap);
        } else {
            rate = error > 0.0 ? cap : (error < 0.0 ? -cap : 0.0);
        }
        L[diagonal] = -rate;
    }
}

void Simulation::integrate() {
    const std::int64_t n = static_cast<std::int64_t>(s_.grains.size());
    const double dt = s_.parameters.timeStep;
    const auto L = s_.velocityGradient;
    auto& g = s_.grains;
    // Cell update h <- (I + L dt) h; the affine map from the last rebuild, F = h h_ref^-1.
    const auto h = s_.cell;
    const std::array<double, 4> hNext = {h[0] + dt * (L[0] * h[0] + L[2] * h[1]),
                                         h[1] + dt * (L[1] * h[0] + L[3] * h[1]),
                                         h[2] + dt * (L[0] * h[2] + L[2] * h[3]),
                                         h[3] + dt * (L[1] * h[2] + L[3] * h[3])};
    const auto F = cellProduct(hNext, cellInverse(s_.referenceCell));
    const DampingKind damping = s_.parameters.damping.kind;
    const double beta = s_.parameters.damping.coefficient;
    const double stepFraction = s_.parameters.stability.maxStepFraction;
    const int blocks = blockCount(std::size_t(n));
    grainBlockSums_.assign(std::size_t(blocks), 0.0);
    double maxDrift2 = 0.0, maxStep = 0.0;
    bool bad = false;

#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads) \
    reduction(max : maxDrift2, maxStep) reduction(|| : bad)
    for (int b = 0; b < blocks; ++b) {
        double dampingWork = 0.0;
        const std::int64_t end = std::min<std::int64_t>(n, std::int64_t(b + 1) * kReductionBlock);
        for (std::int64_t i = std::int64_t(b) * kReductionBlock; i < end; ++i) {
            double f1 = force1_[i], f2 = force2_[i], m = torque_[i];
            double v1 = g.v1[i], v2 = g.v2[i], w = g.omega[i];
            if (damping == DampingKind::GlobalViscous) {
                // Viscous force -c v' integrated time-centred: v_new = ((1 - c dt/2m) v +
                // dt F/m) / (1 + c dt/2m). Damping acts on fluctuations only.
                const double ht = 0.5 * dt * beta * dampTrans_[i] * invMass_[i];
                const double hr = 0.5 * dt * beta * dampRot_[i] * invInertia_[i];
                const double n1 = ((1.0 - ht) * v1 + dt * f1 * invMass_[i]) / (1.0 + ht);
                const double n2 = ((1.0 - ht) * v2 + dt * f2 * invMass_[i]) / (1.0 + ht);
                const double nw = ((1.0 - hr) * w + dt * m * invInertia_[i]) / (1.0 + hr);
                const double a1 = 0.5 * (v1 + n1), a2 = 0.5 * (v2 + n2), aw = 0.5 * (w + nw);
                dampingWork += dt * beta * (dampTrans_[i] * (a1 * a1 + a2 * a2) + dampRot_[i] * aw * aw);
                v1 = n1;
                v2 = n2;
                w = nw;
            } else {
                if (damping == DampingKind::CundallLocal) {
                    // Cundall's local damping: each component's force reduced by alpha |F|
                    // against the current velocity.
                    const double d1 = -beta * std::fabs(f1) * (v1 > 0 ? 1.0 : (v1 < 0 ? -1.0 : 0.0));
                    const double d2 = -beta * std::fabs(f2) * (v2 > 0 ? 1.0 : (v2 < 0 ? -1.0 : 0.0));
                    const double dm = -beta * std::fabs(m) * (w > 0 ? 1.0 : (w < 0 ? -1.0 : 0.0));
                    f1 += d1;
                    f2 += d2;
                    m += dm;
                    const double n1 = v1 + dt * f1 * invMass_[i], n2 = v2 + dt * f2 * invMass_[i];
                    const double nw = w + dt * m * invInertia_[i];
                    dampingWork -= dt * (d1 * 0.5 * (v1 + n1) + d2 * 0.5 * (v2 + n2) +
                                         dm * 0.5 * (w + nw));
                    v1 = n1;
                    v2 = n2;
                    w = nw;
                } else {
                    v1 += dt * f1 * invMass_[i];
                    v2 += dt * f2 * invMass_[i];
                    w += dt * m * invInertia_[i];
                }
            }
            const double x1 = g.x1[i], x2 = g.x2[i];
            const double y1 = x1 + dt * (v1 + L[0] * x1 + L[2] * x2);
            const double y2 = x2 + dt * (v2 + L[1] * x1 + L[3] * x2);
            const double th = g.theta[i] + dt * w;
            g.v1[i] = v1;
            g.v2[i] = v2;
            g.omega[i] = w;
            g.x1[i] = y1;
            g.x2[i] = y2;
            g.theta[i] = th;
            cosTheta_[i] = std::cos(th);
            sinTheta_[i] = std::sin(th);
            // Displacement beyond the affine motion since the last rebuild.
            const double r1 = s_.reference1[i], r2 = s_.reference2[i];
            const double d1 = y1 - (F[0] * r1 + F[2] * r2), d2 = y2 - (F[1] * r1 + F[3] * r2);
            maxDrift2 = std::max(maxDrift2, d1 * d1 + d2 * d2);
            const double travel = dt * (std::sqrt(v1 * v1 + v2 * v2) + std::fabs(w) * halfWidth_[i]);
            maxStep = std::max(maxStep, travel / (stepFraction * halfHeight_[i]));
            bad = bad || !std::isfinite(y1) || !std::isfinite(y2) || !std::isfinite(th) ||
                  !std::isfinite(v1) || !std::isfinite(v2) || !std::isfinite(w);
        }
        grainBlockSums_[b] = dampingWork;
    }
    for (int b = 0; b < blocks; ++b) {
        s_.dampingWork += grainBlockSums_[b];
    }
    s_.cell = hNext;
    maxDrift_ = std::sqrt(maxDrift2);
    if (bad || !(maxStep <= 1.0)) {
        for (std::int64_t i = 0; i < n; ++i) {
            const double v = std::hypot(g.v1[i], g.v2[i]);
            if (!std::isfinite(g.x1[i]) || !std::isfinite(g.x2[i]) || !std::isfinite(g.theta[i]) ||
                !std::isfinite(v) || !std::isfinite(g.omega[i])) {
                throw SimulationError(s_.step + 1, std::int32_t(i),
                                      "non-finite position or velocity (numerical blow-up)");
            }
            const double travel = dt * (v + std::fabs(g.omega[i]) * halfWidth_[i]);
            if (travel > stepFraction * halfHeight_[i]) {
                throw SimulationError(
                    s_.step + 1, std::int32_t(i),
                    fmt::format("runaway motion: moved {:.3g} m in one step, more than {} of its "
                                "half-height {:.3g} m (speed {:.3g} m/s, spin {:.3g} rad/s); "
                                "kinetic energy is growing without bound",
                                travel, stepFraction, halfHeight_[i], v, g.omega[i]));
                }
        }
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

void Simulation::checkOverlaps() const {
    const double limit = s_.parameters.stability.maxOverlapFraction;
    if (maxOverlapRatio_ <= limit) {
        return;
    }
    const auto network = contactNetwork();
    for (const ContactRecord& c : network.contacts) {
        const double ratio =
            c.overlap / (2.0 * std::min(halfWidth_[c.first], halfWidth_[c.second]));
        if (ratio > limit) {
            throw SimulationError(
                s_.step, c.first,
                fmt::format("overlap {:.3g} m with grain {} is {:.3g} of the smaller width, above "
                            "the limit {} (contact force {:.3g} N)",
                            c.overlap, c.second, ratio, limit, c.normalForce));
        }
    }
}

void Simulation::step() {
    updateServo();
    const auto& L = s_.velocityGradient;
    s_.boundaryWork += -cellArea() * s_.parameters.timeStep *
                       (stress_.s11 * L[0] + stress_.s22 * L[3] + stress_.s12 * (L[1] + L[2]));
    integrate();
    ++s_.step;
    s_.time += s_.parameters.timeStep;
    if (neighboursStale()) {
        rebuildNeighbours();
    }
    evaluateForces(true);
    checkOverlaps();
}

void Simulation::advance(std::int64_t steps) {
    for (std::int64_t k = 0; k < steps; ++k) {
        step();
    }
}

void Simulation::setAxisControl(int axis, const AxisControl& control) {
    if (axis < 0 || axis > 1) {
        throw std::invalid_argument(fmt::format("axis {}: must be 0 (x1) or 1 (x2)", axis));
    }
    const AxisControl& old = s_.axes[axis];
    if (old.mode != control.mode || old.targetStress != control.targetStress) {
        s_.servoIntegral[axis] = 0.0;
    }
    s_.axes[axis] = control;
}

void Simulation::setFriction(double friction) {
    if (!(friction >= 0.0) || !std::isfinite(friction)) {
        throw std::invalid_argument(fmt::format("friction {}: must be >= 0", friction));
    }
    s_.parameters.friction = friction;
    evaluateForces(false);
}

void Simulation::setDamping(const DampingParameters& damping) {
    if (!(damping.coefficient >= 0.0)) {
        throw std::invalid_argument(
            fmt::format("damping coefficient {}: must be >= 0", damping.coefficient));
    }
    s_.parameters.damping = damping;
}

void Simulation::setThreads(int threads) {
    if (threads < 1) {
        throw std::invalid_argument(fmt::format("threads = {}: must be >= 1", threads));
    }
    s_.parameters.threads = threads;
}

void Simulation::clearVelocities() {
    auto& g = s_.grains;
    std::fill(g.v1.begin(), g.v1.end(), 0.0);
    std::fill(g.v2.begin(), g.v2.end(), 0.0);
    std::fill(g.omega.begin(), g.omega.end(), 0.0);
}

SimulationState Simulation::state() const { return s_; }

std::size_t Simulation::contactCount() const {
    return static_cast<std::size_t>(
        std::count_if(normalForce_.begin(), normalForce_.end(), [](double f) { return f > 0.0; }));
}

double Simulation::maxOverlap() const {
    double worst = 0.0;
    for (std::size_t p = 0; p < normalForce_.size(); ++p) {
        worst = std::max(worst, normalForce_[p] / s_.parameters.normalStiffness);
    }
    return worst;
}

ContactNetwork Simulation::contactNetwork() const {
    ContactNetwork net;
    const std::size_t n = s_.grains.size();
    const auto& h = s_.cell;
    const auto& g = s_.grains;
    const double det = cellDeterminant(h);
    net.grainCount = static_cast<std::int32_t>(n);
    net.cell = h;
    net.x1.resize(n);
    net.x2.resize(n);
    net.grainArea.resize(n);
    net.grainMass = mass_;
    net.netForce1 = force1_;
    net.netForce2 = force2_;
    std::vector<std::int32_t> wrap1(n), wrap2(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double s1 = (h[3] * g.x1[i] - h[2] * g.x2[i]) / det;
        const double s2 = (-h[1] * g.x1[i] + h[0] * g.x2[i]) / det;
        const double w1 = std::floor(s1), w2 = std::floor(s2);
        wrap1[i] = static_cast<std::int32_t>(w1);
        wrap2[i] = static_cast<std::int32_t>(w2);
        net.x1[i] = g.x1[i] - (h[0] * w1 + h[2] * w2);
        net.x2[i] = g.x2[i] - (h[1] * w1 + h[3] * w2);
        net.grainArea[i] = s_.shapes[g.shape[i]].area;
    }
    for (std::size_t p = 0; p < s_.pairs.size(); ++p) {
        if (!(normalForce_[p] > 0.0)) {
            continue;
        }
        const std::int32_t i = s_.pairs.first[p], j = s_.pairs.second[p];
        const double k1 = s_.pairs.shift1[p], k2 = s_.pairs.shift2[p];
        const double l1 = g.x1[j] + h[0] * k1 + h[2] * k2 - g.x1[i];
        const double l2 = g.x2[j] + h[1] * k1 + h[3] * k2 - g.x2[i];
        ContactGeometry c;
        if (allDisks_) {
            c = diskContact(halfWidth_[i], halfWidth_[j], l1, l2);
        } else if (s_.parameters.allArcPairs) {
            c = ovalContactAllPairs(s_.shapes[g.shape[i]], g.theta[i], s_.shapes[g.shape[j]],
                                    g.theta[j], l1, l2);
        } else {
            c = ovalContact(s_.shapes[g.shape[i]], cosTheta_[i], sinTheta_[i],
                            s_.shapes[g.shape[j]], cosTheta_[j], sinTheta_[j], l1, l2);
        }
        ContactRecord r;
        r.first = i;
        r.second = j;
        r.shift1 = s_.pairs.shift1[p] + wrap1[j] - wrap1[i];
        r.shift2 = s_.pairs.shift2[p] + wrap2[j] - wrap2[i];
        r.branch1 = l1;
        r.branch2 = l2;
        r.normal1 = c.normalX;
        r.normal2 = c.normalY;
        r.point1 = c.pointX;
        r.point2 = c.pointY;
        r.overlap = c.overlap;
        r.normalForce = normalForce_[p];
        r.tangentialForce = s_.pairs.tangentialForce[p];
        r.sliding = s_.pairs.sliding[p] != 0;
        net.contacts.push_back(r);
    }
    return net;
}

Energies Simulation::energies() const {
    Energies e;
    const auto& g = s_.grains;
    for (std::size_t i = 0; i < g.size(); ++i) {
        e.kinetic += 0.5 * mass_[i] * (g.v1[i] * g.v1[i] + g.v2[i] * g.v2[i]) +
                     0.5 * inertia_[i] * g.omega[i] * g.omega[i];
    }
    const double kn = s_.parameters.normalStiffness, kt = s_.parameters.tangentialStiffness;
    for (std::size_t p = 0; p < normalForce_.size(); ++p) {
        if (normalForce_[p] > 0.0) {
            const double ft = s_.pairs.tangentialForce[p];
            e.elastic += 0.5 * normalForce_[p] * normalForce_[p] / kn + 0.5 * ft * ft / kt;
        }
    }
    e.boundaryWork = s_.boundaryWork;
    e.frictionWork = s_.frictionWork;
    e.dampingWork = s_.dampingWork;
    return e;
}

} // namespace grainlab
