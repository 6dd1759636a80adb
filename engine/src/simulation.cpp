#include "grainlab/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "fast_trig.h"
#include "grainlab/contact_geometry.h"
#include "grainlab/contact_law.h"
#include "grainlab/measures.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/time_step.h"

namespace grainlab {
namespace {

/// What one touching (or open) pair contributes: forces, torques, history and the sums.
struct PairResponse {
    double force1 = 0, force2 = 0;            ///< force on B [N]
    double normal = 0;                        ///< f_n [N]
    double tangential = 0;                    ///< new stored f_t [N]
    double torqueFirst = 0, torqueSecond = 0; ///< [N m]
    double slipWork = 0;                      ///< [J]
    bool sliding = false;
    double s11 = 0, s12 = 0, s21 = 0, s22 = 0, e1 = 0, e2 = 0; ///< Love-Weber and Ê terms
};

struct PairKinematics {
    double v1A, v2A, omegaA, v1B, v2B, omegaB; ///< fluctuating velocities [m/s], spins [rad/s]
    double L0, L1, L2, L3;                     ///< velocity gradient, column-major [1/s]
};

/// What one pair contributes: the contact law (linearContactForce) applied along the pair's
/// geometry, turned into forces, torques and the stress sums. Every operation is done
/// unconditionally and the cases are chosen by selects (see linearContactForce), so that the pair
/// loop vectorises. Used by the vectorised pair loop and the scalar reference path alike.
/// Without `Increment` (re-evaluating a restored state) the stored tangential force is taken as
/// it is.
template <bool Frictional, bool Increment>
inline PairResponse respond(const ContactGeometry& c, bool touching, double l1, double l2,
                            double stored, const PairKinematics& k, const ContactLawParameters& law,
                            double kt) {
    PairResponse r;
    const double n1 = c.normalX, n2 = c.normalY, t1 = -n2, t2 = n1;
    // The pair loop's order of operations is part of the result's bits (the compiler fuses
    // multiply-adds by it): the normal force first, then the tangential force.
    const double fn = touching ? normalContactForce(c.overlap, law) : 0.0;
    double ft = 0.0;
    if constexpr (Frictional) {
        if constexpr (Increment) {
            // Velocity of B relative to A at the contact point: fluctuating translation,
            // rotation (omega x r in 2D is omega * (-r2, r1)) and the affine field L l.
            const double pA1 = c.pointX, pA2 = c.pointY;
            const double pB1 = pA1 - l1, pB2 = pA2 - l2;
            const double vr1 =
                k.v1B - k.v1A + k.L0 * l1 + k.L2 * l2 - k.omegaB * pB2 + k.omegaA * pA2;
            const double vr2 =
                k.v2B - k.v2A + k.L1 * l1 + k.L3 * l2 + k.omegaB * pB1 - k.omegaA * pA1;
            ContactForce f;
            tangentialContactForce(fn, vr1 * t1 + vr2 * t2, stored, law, f);
            ft = touching ? f.tangential : 0.0;
            r.sliding = touching & f.sliding;
            // One select on both conditions: GCC 12 turns a nested select here into control
            // flow.
            r.slipWork = (touching & f.sliding) ? f.slipWork : 0.0;
        } else {
            ft = touching ? stored : 0.0;
        }
    }
    r.tangential = ft;
    const double f1 = fn * n1 + ft * t1, f2 = fn * n2 + ft * t2;
    r.force1 = f1;
    r.force2 = f2;
    r.normal = fn;
    // Torques (x_c - x) x F: on A from -F at p_A, on B from F at p_A - l.
    r.torqueFirst = -(c.pointX * f2 - c.pointY * f1);
    r.torqueSecond = (c.pointX - l1) * f2 - (c.pointY - l2) * f1;
    r.s11 = f1 * l1;
    r.s12 = f1 * l2;
    r.s21 = f2 * l1;
    r.s22 = f2 * l2;
    const double kn = law.normalStiffness;
    const double stiff1 = l1 * l1 * (kn * n1 * n1 + kt * t1 * t1);
    const double stiff2 = l2 * l2 * (kn * n2 * n2 + kt * t2 * t2);
    r.e1 = touching ? stiff1 : 0.0;
    r.e2 = touching ? stiff2 : 0.0;
    return r;
}

/// min(W_i, W_j) from the half-widths [m]: the width the overlap guard and the quadrant kernel's
/// depth limit are fractions of.
inline double smallerWidth(double halfWidthA, double halfWidthB) {
    return 2.0 * std::min(halfWidthA, halfWidthB);
}

/// The per-grain arc tables and orientations the pair loop reads.
struct ArcTables {
    const double *endOffset, *sideOffset, *endRadius, *sideRadius, *cosJ, *sinJ, *cosT, *sinT;
};

/// Oval pair geometry as the vector pair loop decides it, from the same per-grain numbers: the
/// quadrant kernel; where that asks, the 16-pair reference (always with `allArcPairs`). Scalar:
/// for the pairs the vector loop hands on, and the network.
ContactGeometry decideOvalPair(const ArcTables& t, const OvalShape& A, const OvalShape& B,
                               std::int32_t i, std::int32_t j, double l1, double l2, double smaller,
                               bool allArcPairs) {
    if (!allArcPairs) {
        const QuadrantContact q = ovalContactQuadrant(
            t.endOffset[i], t.sideOffset[i], t.endRadius[i], t.sideRadius[i], t.cosJ[i], t.sinJ[i],
            t.cosT[i], t.sinT[i], t.endOffset[j], t.sideOffset[j], t.endRadius[j], t.sideRadius[j],
            t.cosJ[j], t.sinJ[j], t.cosT[j], t.sinT[j], l1, l2, smaller);
        if (!q.needsReference) {
            return q.geometry;
        }
    }
    return ovalContactAllPairs(A, t.cosT[i], t.sinT[i], B, t.cosT[j], t.sinT[j], l1, l2);
}

// ConstantArea sets x2's rate from x1's rate of the same step, so it can only drive axis x2.
void checkAxisControl(int axis, const AxisControl& control) {
    if (control.mode == AxisMode::ConstantArea &&
        (axis != 1 || !(control.referenceArea > 0.0) || !std::isfinite(control.referenceArea))) {
        throw std::invalid_argument(fmt::format(
            "axis {}: constant area drives axis x2 (1) only, with a reference area > 0 (got {})",
            axis, control.referenceArea));
    }
}

} // namespace

SimulationError::SimulationError(std::int64_t step_, std::int32_t grain_, std::string cause_)
    : std::runtime_error(grain_ >= 0 ? fmt::format("step {}: grain {}: {}", step_, grain_, cause_)
                                     : fmt::format("step {}: {}", step_, cause_)),
      step(step_), grain(grain_), cause(std::move(cause_)) {}

Simulation::Simulation(SimulationState state) : s_(std::move(state)) {
    const std::size_t n = s_.grains.size();
    if (s_.shapes.empty()) {
        throw std::invalid_argument("simulation: the shape table is empty");
    }
    for (auto* v :
         {&s_.grains.x2, &s_.grains.theta, &s_.grains.v1, &s_.grains.v2, &s_.grains.omega}) {
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
    for (int axis = 0; axis < 2; ++axis) {
        checkAxisControl(axis, s_.axes[axis]);
    }
    if (!s_.parameters.stability.unguarded) {
        checkTimeStep(s_.shapes, s_.parameters);
    }
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
                                                        "outside [0, {})",
                                                        p, n));
            }
        }
        buildPairIndex();
    } else {
        rebuildNeighbours();
    }
    // The forces of the stored state through the very code of a step (its increment kernel with
    // a zero time step, which leaves every stored f_t as it is): another instantiation may be
    // compiled with other rounding (FMA contraction), and a restart would then differ in the
    // last bits from the run that wrote the checkpoint. The sliding flags stay as stored.
    const double timeStep = s_.parameters.timeStep;
    const std::vector<std::uint8_t> sliding = s_.pairs.sliding;
    s_.parameters.timeStep = 0.0;
    evaluateForces(true);
    s_.parameters.timeStep = timeStep;
    s_.pairs.sliding = sliding;
}

void Simulation::derive() {
    const std::size_t n = s_.grains.size();
    const auto& p = s_.parameters;
    for (auto* v : {&mass_, &inertia_, &halfWidth_, &halfHeight_, &dampTrans_, &dampRot_,
                    &cosTheta_, &sinTheta_, &stepLimit_, &endOffset_, &sideOffset_, &endRadius_,
                    &sideRadius_, &cosJunction_, &sinJunction_}) {
        v->resize(n);
    }
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
        halfWidth_[i] = s.halfWidth;
        halfHeight_[i] = s.halfHeight;
        // Fraction beta of the critical damping of one grain on one normal spring, 2 sqrt(k_n m).
        dampTrans_[i] = 2.0 * std::sqrt(p.normalStiffness * mass_[i]);
        dampRot_[i] = 2.0 * std::sqrt(p.normalStiffness * s.halfWidth * s.halfWidth * inertia_[i]);
        sinCos(s_.grains.theta[i], sinTheta_[i], cosTheta_[i]);
        stepLimit_[i] = p.stability.maxStepFraction * s.halfHeight;
        const OvalArcs arcs = ovalArcs(s);
        endOffset_[i] = arcs.endOffset;
        sideOffset_[i] = arcs.sideOffset;
        endRadius_[i] = arcs.endRadius;
        sideRadius_[i] = arcs.sideRadius;
        cosJunction_[i] = arcs.cosJunction;
        sinJunction_[i] = arcs.sinJunction;
        maxHalfWidth_ = std::max(maxHalfWidth_, s.halfWidth);
        minWidth = std::min(minWidth, s.width);
    }
    // One form (the reference study's ovals): every grain's arcs become its half-width times
    // the form's unit arcs, the numbers the one-form pair loop computes from the half-width
    // alone; the scalar paths read them from the tables.
    oneForm_ = !allDisks_ && !p.perGrainArcs && oneFormArcs(s_.shapes, unitArcs_);
    if (oneForm_) {
        for (std::size_t i = 0; i < n; ++i) {
            const double a = halfWidth_[i];
            endOffset_[i] = a * unitArcs_.endOffset;
            sideOffset_[i] = a * unitArcs_.sideOffset;
            endRadius_[i] = a * unitArcs_.endRadius;
            sideRadius_[i] = a * unitArcs_.sideRadius;
            cosJunction_[i] = unitArcs_.cosJunction;
            sinJunction_[i] = unitArcs_.sinJunction;
        }
    }
    skin_ = p.neighbourSkin > 0 ? p.neighbourSkin : 0.1 * minWidth;
    prepareIntegration();
}

double Simulation::cellArea() const {
    return cellDeterminant(s_.cell);
}

void Simulation::evaluateForces(bool increment) {
    const bool frictional = s_.parameters.friction > 0.0;
    const auto run = [&]<PairShape Shape>() {
        if (frictional) {
            increment ? pairForces<Shape, true, true>() : pairForces<Shape, true, false>();
        } else {
            pairForces<Shape, false, false>();
        }
    };
    if (allDisks_) {
        run.operator()<PairShape::Disk>();
    } else if (oneForm_) {
        run.operator()<PairShape::OneForm>();
    } else {
        run.operator()<PairShape::PerGrain>();
    }
}

ContactGeometry Simulation::pairGeometry(std::size_t p, double l1, double l2) const {
    const std::int32_t i = s_.pairs.first[p], j = s_.pairs.second[p];
    if (allDisks_) {
        return diskContact(halfWidth_[i], pairHalfWidthFirst_[p] + pairHalfWidthSecond_[p], l1, l2);
    }
    const OvalShape& A = s_.shapes[s_.grains.shape[i]];
    const OvalShape& B = s_.shapes[s_.grains.shape[j]];
    const ArcTables tables{endOffset_.data(),  sideOffset_.data(),  endRadius_.data(),
                           sideRadius_.data(), cosJunction_.data(), sinJunction_.data(),
                           cosTheta_.data(),   sinTheta_.data()};
    const double smaller = smallerWidth(pairHalfWidthFirst_[p], pairHalfWidthSecond_[p]);
    return decideOvalPair(tables, A, B, i, j, l1, l2, smaller, s_.parameters.allArcPairs);
}

template <Simulation::PairShape Shape, bool Frictional, bool Increment>
void Simulation::pairForces() {
    constexpr bool Disk = Shape == PairShape::Disk;
    const std::size_t pairCount = s_.pairs.size();
    const int blocks = reductionBlocks(pairCount);
    const ContactLawParameters law =
        contactLawParameters(s_.parameters.normalStiffness, s_.parameters.tangentialStiffness,
                             s_.parameters.friction, s_.parameters.timeStep);
    const double kt = Frictional ? law.tangentialStiffness : 0.0;
    const bool fullOvalTest = s_.parameters.allArcPairs;
    const double overlapLimit = s_.parameters.stability.maxOverlapFraction;
    const double h0 = s_.cell[0], h1 = s_.cell[1], h2 = s_.cell[2], h3 = s_.cell[3];
    const auto& Lg = s_.velocityGradient;
    const double L0 = Lg[0], L1 = Lg[1], L2 = Lg[2], L3 = Lg[3];
    // Raw pointers: the loop below is a simd loop over independent pairs.
    const std::int32_t* first = s_.pairs.first.data();
    const std::int32_t* second = s_.pairs.second.data();
    const std::int32_t* shift1 = s_.pairs.shift1.data();
    const std::int32_t* shift2 = s_.pairs.shift2.data();
    double* stored = s_.pairs.tangentialForce.data();
    std::uint8_t* sliding = s_.pairs.sliding.data();
    const double* x1 = s_.grains.x1.data();
    const double* x2 = s_.grains.x2.data();
    const double* v1 = s_.grains.v1.data();
    const double* v2 = s_.grains.v2.data();
    const double* omega = s_.grains.omega.data();
    const double* cosT = cosTheta_.data();
    const double* sinT = sinTheta_.data();
    const double* endOffset = endOffset_.data();
    const double* sideOffset = sideOffset_.data();
    const double* endRadius = endRadius_.data();
    const double* sideRadius = sideRadius_.data();
    const double* cosJ = cosJunction_.data();
    const double* sinJ = sinJunction_.data();
    const double* halfWidthFirst = pairHalfWidthFirst_.data();
    const double* halfWidthSecond = pairHalfWidthSecond_.data();
    // One form: the arcs at half-width 1, the same for every grain.
    const double unitEnd = unitArcs_.endOffset, unitSide = unitArcs_.sideOffset;
    const double unitEndRadius = unitArcs_.endRadius, unitSideRadius = unitArcs_.sideRadius;
    const double unitCosJ = unitArcs_.cosJunction, unitSinJ = unitArcs_.sinJunction;
    double* force1 = pairForce1_.data();
    double* force2 = pairForce2_.data();
    double* torqueA = torqueFirst_.data();
    double* torqueB = torqueSecond_.data();
    double* normal = normalForce_.data();
    blockSums_.resize(std::size_t(blocks) * kBlockSumWidth);
    double maxExcess = -std::numeric_limits<double>::infinity();

    // One pair, as the vectorised loop and the reference path both compute it.
    const auto kinematics = [&](std::int32_t i, std::int32_t j) {
        return PairKinematics{v1[i], v2[i], omega[i], v1[j], v2[j], omega[j], L0, L1, L2, L3};
    };

#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads)                       \
    reduction(max                                                                                  \
              : maxExcess)
    for (int b = 0; b < blocks; ++b) {
        const std::size_t begin = std::size_t(b) * kReductionBlock;
        const std::size_t end = std::min(pairCount, begin + kReductionBlock);
        double s11 = 0, s12 = 0, s21 = 0, s22 = 0, e1 = 0, e2 = 0, slip = 0;
        double excess = -std::numeric_limits<double>::infinity();
        double deferred = 0; // a double: GCC 12 vectorises no loop mixing int and double sums
        // Pairs the quadrant kernel cannot decide (ovals; rare): decided after the loop by the
        // 16-pair reference. The quadrant kernel, not the facing-pair kernel with its single
        // square root: measured on an AMD EPYC (Zen 4), the quadrant loop runs 1.2-1.4x faster
        // (the loop is bound by its gathers there, not by square roots).
        // Flags as doubles, copied to bytes after the loop: a byte store in the simd loop makes
        // GCC 12 choose 32 lanes per iteration (the narrowest type sets the vectorisation
        // factor), and the kernel then spills (1.3x slower for ovals).
        double needsReference[kReductionBlock], slides[kReductionBlock];
#pragma omp simd reduction(+ : s11, s12, s21, s22, e1, e2, slip, deferred) reduction(max : excess)
        for (std::size_t p = begin; p < end; ++p) {
            const std::int32_t i = first[p], j = second[p];
            const double k1 = shift1[p], k2 = shift2[p];
            const double l1 = x1[j] + h0 * k1 + h2 * k2 - x1[i];
            const double l2 = x2[j] + h1 * k1 + h3 * k2 - x2[i];
            // The half-widths in pair order (no gather); the same sum and minimum as before.
            const double aI = halfWidthFirst[p], aJ = halfWidthSecond[p];
            const double reach = aI + aJ, smaller = smallerWidth(aI, aJ);
            const double d2 = l1 * l1 + l2 * l2, reach2 = reach * reach;
            const bool near = (d2 < reach2) & (d2 > 0.0);
            // No aggregate is copied in this loop: GCC 12 vectorises none that does.
            const QuadrantContact q = [&] {
                if constexpr (Disk) {
                    return QuadrantContact{diskContact(aI, reach, l1, l2), false};
                } else if constexpr (Shape == PairShape::OneForm) {
                    // No gather for the arcs (the tables' twelve): the half-widths times the
                    // unit arcs are the tables' numbers (derive()).
                    return ovalContactQuadrant(aI * unitEnd, aI * unitSide, aI * unitEndRadius,
                                               aI * unitSideRadius, unitCosJ, unitSinJ, cosT[i],
                                               sinT[i], aJ * unitEnd, aJ * unitSide,
                                               aJ * unitEndRadius, aJ * unitSideRadius, unitCosJ,
                                               unitSinJ, cosT[j], sinT[j], l1, l2, smaller);
                } else {
                    return ovalContactQuadrant(
                        endOffset[i], sideOffset[i], endRadius[i], sideRadius[i], cosJ[i], sinJ[i],
                        cosT[i], sinT[i], endOffset[j], sideOffset[j], endRadius[j], sideRadius[j],
                        cosJ[j], sinJ[j], cosT[j], sinT[j], l1, l2, smaller);
                }
            }();
            const ContactGeometry& c = q.geometry;
            const bool reference = !Disk & near & (q.needsReference | fullOvalTest);
            const bool touching = near & !reference & (c.overlap > 0.0);
            const double old = stored[p];
            // Loaded here, not by the kinematics lambda: loads through its captures would sit
            // under the contact condition, as masked gathers GCC 12 does not vectorise.
            const double v1A = v1[i], v2A = v2[i], omegaA = omega[i];
            const double v1B = v1[j], v2B = v2[j], omegaB = omega[j];
            const PairResponse r = respond<Frictional, Increment>(
                c, touching, l1, l2, old,
                PairKinematics{v1A, v2A, omegaA, v1B, v2B, omegaB, L0, L1, L2, L3}, law, kt);
            // A deferred pair keeps its history for the reference path below.
            stored[p] = reference ? old : r.tangential;
            slides[p - begin] = r.sliding ? 1.0 : 0.0;
            if constexpr (!Disk) { // disks defer nothing: no store, no sum
                needsReference[p - begin] = reference ? 1.0 : 0.0;
                deferred += reference ? 1.0 : 0.0;
            }
            force1[p] = r.force1;
            force2[p] = r.force2;
            torqueA[p] = r.torqueFirst;
            torqueB[p] = r.torqueSecond;
            normal[p] = r.normal;
            s11 += r.s11;
            s12 += r.s12;
            s21 += r.s21;
            s22 += r.s22;
            e1 += r.e1;
            e2 += r.e2;
            slip += r.slipWork;
            const double over = c.overlap - overlapLimit * smaller;
            excess = std::max(excess, touching ? over : excess);
        }
        if constexpr (!Disk) {
            // The reference path, in pair order after the vector loop: fixed for any threads.
            for (std::size_t p = begin; deferred > 0 && p < end; ++p) {
                if (needsReference[p - begin] == 0.0) {
                    continue;
                }
                deferred -= 1.0;
                const std::int32_t i = first[p], j = second[p];
                const double k1 = shift1[p], k2 = shift2[p];
                const double l1 = x1[j] + h0 * k1 + h2 * k2 - x1[i];
                const double l2 = x2[j] + h1 * k1 + h3 * k2 - x2[i];
                const OvalShape& A = s_.shapes[s_.grains.shape[i]];
                const OvalShape& B = s_.shapes[s_.grains.shape[j]];
                const double smaller = smallerWidth(halfWidthFirst[p], halfWidthSecond[p]);
                const ArcTables tables{endOffset, sideOffset, endRadius, sideRadius,
                                       cosJ,      sinJ,       cosT,      sinT};
                ContactGeometry c =
                    decideOvalPair(tables, A, B, i, j, l1, l2, smaller, fullOvalTest);
                const bool touching = c.overlap > 0.0;
                if (!touching) {
                    c = ContactGeometry{0.0, 1.0, 0.0, 0.0, 0.0}; // finite numbers for the law
                }
                const PairResponse r = respond<Frictional, Increment>(
                    c, touching, l1, l2, stored[p], kinematics(i, j), law, kt);
                stored[p] = r.tangential;
                slides[p - begin] = r.sliding ? 1.0 : 0.0;
                force1[p] = r.force1;
                force2[p] = r.force2;
                torqueA[p] = r.torqueFirst;
                torqueB[p] = r.torqueSecond;
                normal[p] = r.normal;
                s11 += r.s11;
                s12 += r.s12;
                s21 += r.s21;
                s22 += r.s22;
                e1 += r.e1;
                e2 += r.e2;
                slip += r.slipWork;
                if (touching) {
                    excess = std::max(excess, c.overlap - overlapLimit * smaller);
                }
            }
        }
        for (std::size_t p = begin; p < end; ++p) {
            sliding[p] = slides[p - begin] != 0.0;
        }
        double* out = &blockSums_[std::size_t(b) * kBlockSumWidth];
        out[0] = s11;
        out[1] = s12;
        out[2] = s21;
        out[3] = s22;
        out[4] = e1;
        out[5] = e2;
        out[6] = slip;
        maxExcess = std::max(maxExcess, excess);
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
    overlapExcess_ = maxExcess;
}

void Simulation::gatherForces(std::vector<double>& f1, std::vector<double>& f2,
                              std::vector<double>& torque) const {
    const std::size_t n = s_.grains.size();
    f1.assign(n, 0.0);
    f2.assign(n, 0.0);
    torque.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        // The same order as integrateGrains: pairs where i is first, then where it is second.
        const GrainSum sum =
            sumOnGrain(i, pairIndex_.firstStart.data(), pairIndex_.secondStart.data(),
                       pairIndex_.secondPairs.data(), pairForce1_.data(), pairForce2_.data(),
                       torqueFirst_.data(), torqueSecond_.data());
        f1[i] = sum.f1;
        f2[i] = sum.f2;
        torque[i] = sum.torque;
    }
}

void Simulation::checkOverlaps() const {
    if (!(overlapExcess_ > 0.0) || s_.parameters.stability.unguarded) {
        return;
    }
    const double limit = s_.parameters.stability.maxOverlapFraction;
    const auto network = contactNetwork();
    for (const ContactRecord& c : network.contacts) {
        const double ratio = c.overlap / smallerWidth(halfWidth_[c.first], halfWidth_[c.second]);
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
    checkAxisControl(axis, control);
    const AxisControl& old = s_.axes[axis];
    if (old.mode != control.mode || old.targetStress != control.targetStress ||
        old.pathSlope != control.pathSlope || old.pathOrigin != control.pathOrigin) {
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

void Simulation::clearVelocities() {
    auto& g = s_.grains;
    std::fill(g.v1.begin(), g.v1.end(), 0.0);
    std::fill(g.v2.begin(), g.v2.end(), 0.0);
    std::fill(g.omega.begin(), g.omega.end(), 0.0);
}

void Simulation::setVelocities(const std::vector<double>& v1, const std::vector<double>& v2,
                               const std::vector<double>& omega) {
    const std::size_t n = s_.grains.size();
    const auto check = [n](const std::vector<double>& v, const char* name) {
        if (v.size() != n) {
            throw std::invalid_argument(
                fmt::format("{}: {} values for {} grains", name, v.size(), n));
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(v[i])) {
                throw std::invalid_argument(
                    fmt::format("{}: grain {} has {}, not a finite number", name, i, v[i]));
            }
        }
    };
    check(v1, "v1");
    check(v2, "v2");
    check(omega, "omega");
    std::copy(v1.begin(), v1.end(), s_.grains.v1.begin());
    std::copy(v2.begin(), v2.end(), s_.grains.v2.begin());
    std::copy(omega.begin(), omega.end(), s_.grains.omega.begin());
}

SimulationState Simulation::state() const {
    return s_;
}

std::size_t Simulation::contactCount() const {
    return static_cast<std::size_t>(
        std::count_if(normalForce_.begin(), normalForce_.end(), [](double f) { return f > 0.0; }));
}

double Simulation::unbalancedForceIndex() const {
    // The touching pairs in pair order: the network's contacts (contactNetwork()).
    double contactSum = 0;
    std::size_t contacts = 0;
    for (std::size_t p = 0; p < s_.pairs.size(); ++p) {
        if (normalForce_[p] > 0.0) {
            contactSum += contactForceSquared(normalForce_[p], s_.pairs.tangentialForce[p]);
            ++contacts;
        }
    }
    std::vector<double> f1, f2, torque;
    gatherForces(f1, f2, torque);
    return grainlab::unbalancedForceIndex(contactSum, contacts, f1, f2);
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
    std::vector<double> torque;
    gatherForces(net.netForce1, net.netForce2, torque);
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
    // The touching pairs in pair order; each contact's record is its own (the scalar contact
    // geometry, the network's main cost), so the records are made on the engine's threads.
    std::vector<std::int32_t> touching;
    for (std::size_t p = 0; p < s_.pairs.size(); ++p) {
        if (normalForce_[p] > 0.0) {
            touching.push_back(static_cast<std::int32_t>(p));
        }
    }
    net.contacts.resize(touching.size());
    const std::int64_t m = static_cast<std::int64_t>(touching.size());
#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads)
    for (std::int64_t k = 0; k < m; ++k) {
        const std::int32_t p = touching[k];
        const std::int32_t i = s_.pairs.first[p], j = s_.pairs.second[p];
        const double k1 = s_.pairs.shift1[p], k2 = s_.pairs.shift2[p];
        const double l1 = g.x1[j] + h[0] * k1 + h[2] * k2 - g.x1[i];
        const double l2 = g.x2[j] + h[1] * k1 + h[3] * k2 - g.x2[i];
        // The geometry the pair loop used for this force.
        const ContactGeometry c = pairGeometry(p, l1, l2);
        ContactRecord& r = net.contacts[k];
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
