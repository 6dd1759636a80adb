// Time integration of Simulation (simulation.h): the servo that sets the velocity gradient, and
// the grain loop (force gather in a fixed order, damping, central differences, affine motion,
// blow-up checks). Runs on the thread that drives the Simulation; OpenMP inside.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "fast_trig.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/simulation.h"

namespace grainlab {

void Simulation::prepareIntegration() {
    // Per-grain coefficients of the velocity update v <- keep v + push F, so that the grain
    // loop does no division. Viscous damping -c v' is integrated time-centred:
    // v_new = ((1 - h) v + dt F / m) / (1 + h) with h = c dt / 2m.
    const std::size_t n = s_.grains.size();
    const double dt = s_.parameters.timeStep;
    const double beta = s_.parameters.damping.coefficient;
    const bool viscous = s_.parameters.damping.kind == DampingKind::GlobalViscous;
    for (auto* v : {&keepTrans_, &pushTrans_, &keepRot_, &pushRot_, &workTrans_, &workRot_}) {
        v->resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double ht = viscous ? 0.5 * dt * beta * dampTrans_[i] / mass_[i] : 0.0;
        const double hr = viscous ? 0.5 * dt * beta * dampRot_[i] / inertia_[i] : 0.0;
        keepTrans_[i] = (1.0 - ht) / (1.0 + ht);
        pushTrans_[i] = dt / mass_[i] / (1.0 + ht);
        keepRot_[i] = (1.0 - hr) / (1.0 + hr);
        pushRot_[i] = dt / inertia_[i] / (1.0 + hr);
        workTrans_[i] = dt * beta * dampTrans_[i];
        workRot_[i] = dt * beta * dampRot_[i];
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
        if (control.mode == AxisMode::ConstantArea) {
            // det(h') = det(I + L dt) det(h) with det(I + L dt) = (1 + dt L11)(1 + dt L22) -
            // dt^2 L12 L21: solve for L22 so that det(h') = A0. Axis x1 has set L11 above
            // (setAxisControl keeps this mode off axis x1). Using the current det(h), not the
            // previous step's rate, corrects each step's round-off instead of summing it.
            const double dt = s_.parameters.timeStep;
            const double factor =
                (control.referenceArea / cellArea() + dt * dt * L[1] * L[2]) / (1.0 + dt * L[0]);
            L[3] = (factor - 1.0) / dt;
            continue;
        }
        if (!servoStep) {
            continue;
        }
        const double cap = servo.maxStrainRate;
        const double sigma = axis == 0 ? stress_.s11 : stress_.s22;
        const double target =
            control.mode == AxisMode::StressPath
                ? control.targetStress +
                      control.pathSlope *
                          ((axis == 0 ? stress_.s22 : stress_.s11) - control.pathOrigin)
                : control.targetStress;
        const double error = target - sigma;
        const double modulus = stiffness_[axis];
        double rate;
        if (modulus > 0.0) {
            // Over one servo interval the stress moves by at most the fraction g of its error
            // (the affine estimate over-predicts the true modulus); the integral term removes
            // the lag of a purely proportional servo during steady loading.
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
    const double dt = s_.parameters.timeStep;
    const auto L = s_.velocityGradient;
    // Cell update h <- (I + L dt) h; the affine map from the last rebuild, F = h h_ref^-1.
    const auto h = s_.cell;
    const std::array<double, 4> hNext = {
        h[0] + dt * (L[0] * h[0] + L[2] * h[1]), h[1] + dt * (L[1] * h[0] + L[3] * h[1]),
        h[2] + dt * (L[0] * h[2] + L[2] * h[3]), h[3] + dt * (L[1] * h[2] + L[3] * h[3])};
    const auto F = cellProduct(hNext, cellInverse(s_.referenceCell));
    const bool oval = !allDisks_;
    switch (s_.parameters.damping.kind) {
    case DampingKind::GlobalViscous:
        oval ? integrateGrains<DampingKind::GlobalViscous, true>(F)
             : integrateGrains<DampingKind::GlobalViscous, false>(F);
        break;
    case DampingKind::CundallLocal:
        oval ? integrateGrains<DampingKind::CundallLocal, true>(F)
             : integrateGrains<DampingKind::CundallLocal, false>(F);
        break;
    default:
        oval ? integrateGrains<DampingKind::None, true>(F)
             : integrateGrains<DampingKind::None, false>(F);
        break;
    }
    s_.cell = hNext;
    if (!runaway_) {
        return;
    }
    auto& g = s_.grains;
    const double stepFraction = s_.parameters.stability.maxStepFraction;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double v = std::hypot(g.v1[i], g.v2[i]);
        if (!std::isfinite(g.x1[i]) || !std::isfinite(g.x2[i]) || !std::isfinite(g.theta[i]) ||
            !std::isfinite(v) || !std::isfinite(g.omega[i])) {
            throw SimulationError(s_.step + 1, std::int32_t(i),
                                  "non-finite position or velocity (numerical blow-up)");
        }
        const double travel = dt * (v + std::fabs(g.omega[i]) * halfWidth_[i]);
        if (travel > stepLimit_[i] && !s_.parameters.stability.unguarded) {
            throw SimulationError(
                s_.step + 1, std::int32_t(i),
                fmt::format("runaway motion: moved {:.3g} m in one step, more than {} of its "
                            "half-height {:.3g} m (speed {:.3g} m/s, spin {:.3g} rad/s); "
                            "kinetic energy is growing without bound",
                            travel, stepFraction, halfHeight_[i], v, g.omega[i]));
        }
    }
}

template <DampingKind Damping, bool Oval>
void Simulation::integrateGrains(const std::array<double, 4>& F) {
    const std::size_t n = s_.grains.size();
    const double dt = s_.parameters.timeStep;
    const double beta = s_.parameters.damping.coefficient;
    const auto& Lg = s_.velocityGradient;
    const double L0 = Lg[0], L1 = Lg[1], L2 = Lg[2], L3 = Lg[3];
    const double F0 = F[0], F1 = F[1], F2 = F[2], F3 = F[3];
    auto& g = s_.grains;
    double* x1 = g.x1.data();
    double* x2 = g.x2.data();
    double* theta = g.theta.data();
    double* v1 = g.v1.data();
    double* v2 = g.v2.data();
    double* omega = g.omega.data();
    double* cosT = cosTheta_.data();
    double* sinT = sinTheta_.data();
    const double* ref1 = s_.reference1.data();
    const double* ref2 = s_.reference2.data();
    const double* keepT = keepTrans_.data();
    const double* pushT = pushTrans_.data();
    const double* keepR = keepRot_.data();
    const double* pushR = pushRot_.data();
    const double* workT = workTrans_.data();
    const double* workR = workRot_.data();
    const double* halfWidth = halfWidth_.data();
    const double* stepLimit = stepLimit_.data();
    const double* pairF1 = pairForce1_.data();
    const double* pairF2 = pairForce2_.data();
    const double* pairTA = torqueFirst_.data();
    const double* pairTB = torqueSecond_.data();
    const std::int32_t* firstStart = pairIndex_.firstStart.data();
    const std::int32_t* secondStart = pairIndex_.secondStart.data();
    const std::int32_t* secondPairs = pairIndex_.secondPairs.data();
    const int blocks = reductionBlocks(n);
    grainBlockSums_.resize(std::size_t(blocks));
    double maxDrift2 = 0.0;
    double bad = 0.0; // grains that ran away or became non-finite

#pragma omp parallel for schedule(static) num_threads(s_.parameters.threads)                     \
    reduction(max : maxDrift2) reduction(+ : bad)
    for (int b = 0; b < blocks; ++b) {
        const std::size_t begin = std::size_t(b) * kReductionBlock;
        const std::size_t end = std::min(n, begin + kReductionBlock);
        // 1. Gather the per-pair forces onto the block's grains in a fixed order: the pairs
        //    where the grain is first (contiguous, -F), then those where it is second (+F).
        double force1[kReductionBlock], force2[kReductionBlock], torque[kReductionBlock];
        for (std::size_t i = begin; i < end; ++i) {
            const GrainSum sum =
                sumOnGrain(i, firstStart, secondStart, secondPairs, pairF1, pairF2, pairTA, pairTB);
            force1[i - begin] = sum.f1;
            force2[i - begin] = sum.f2;
            torque[i - begin] = sum.torque;
        }
        // 2. Central differences on the fluctuating velocity; positions also move with the
        //    affine field L x. Vectorised over the block.
        double work = 0.0;
#pragma omp simd reduction(+ : work, bad) reduction(max : maxDrift2)
        for (std::size_t i = begin; i < end; ++i) {
            double f1 = force1[i - begin], f2 = force2[i - begin], m = torque[i - begin];
            const double u1 = v1[i], u2 = v2[i], w = omega[i];
            double n1, n2, nw;
            if constexpr (Damping == DampingKind::GlobalViscous) {
                n1 = keepT[i] * u1 + pushT[i] * f1;
                n2 = keepT[i] * u2 + pushT[i] * f2;
                nw = keepR[i] * w + pushR[i] * m;
                const double a1 = 0.5 * (u1 + n1), a2 = 0.5 * (u2 + n2), aw = 0.5 * (w + nw);
                work += workT[i] * (a1 * a1 + a2 * a2) + workR[i] * aw * aw;
            } else if constexpr (Damping == DampingKind::CundallLocal) {
                // Cundall's local damping: each component's force reduced by alpha |F| against
                // the current velocity.
                const double d1 = -beta * std::fabs(f1) * (u1 > 0 ? 1.0 : (u1 < 0 ? -1.0 : 0.0));
                const double d2 = -beta * std::fabs(f2) * (u2 > 0 ? 1.0 : (u2 < 0 ? -1.0 : 0.0));
                const double dm = -beta * std::fabs(m) * (w > 0 ? 1.0 : (w < 0 ? -1.0 : 0.0));
                f1 += d1;
                f2 += d2;
                m += dm;
                n1 = u1 + pushT[i] * f1;
                n2 = u2 + pushT[i] * f2;
                nw = w + pushR[i] * m;
                work -= dt * (d1 * 0.5 * (u1 + n1) + d2 * 0.5 * (u2 + n2) + dm * 0.5 * (w + nw));
            } else {
                n1 = u1 + pushT[i] * f1;
                n2 = u2 + pushT[i] * f2;
                nw = w + pushR[i] * m;
            }
            const double y1 = x1[i], y2 = x2[i];
            const double z1 = y1 + dt * (n1 + L0 * y1 + L2 * y2);
            const double z2 = y2 + dt * (n2 + L1 * y1 + L3 * y2);
            const double th = theta[i] + dt * nw;
            v1[i] = n1;
            v2[i] = n2;
            omega[i] = nw;
            x1[i] = z1;
            x2[i] = z2;
            theta[i] = th;
            if constexpr (Oval) {
                sinCos(th, sinT[i], cosT[i]);
            }
            // Displacement beyond the affine motion since the last rebuild.
            const double r1 = ref1[i], r2 = ref2[i];
            const double d1 = z1 - (F0 * r1 + F2 * r2), d2 = z2 - (F1 * r1 + F3 * r2);
            maxDrift2 = std::max(maxDrift2, d1 * d1 + d2 * d2);
            // Runaway or non-finite (a NaN fails every comparison): the caller finds the grain.
            const double travel =
                dt * (std::sqrt(n1 * n1 + n2 * n2) + std::fabs(nw) * halfWidth[i]);
            const bool fine = (travel <= stepLimit[i]) & (std::fabs(z1) + std::fabs(z2) < 1e300) &
                              (std::fabs(th) < 1e300);
            bad += fine ? 0.0 : 1.0;
        }
        grainBlockSums_[b] = work;
    }
    for (int b = 0; b < blocks; ++b) {
        s_.dampingWork += grainBlockSums_[b];
    }
    maxDrift_ = std::sqrt(maxDrift2);
    runaway_ = bad != 0.0;
}

} // namespace grainlab
