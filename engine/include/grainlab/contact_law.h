#pragma once
// Linear spring contact law with Coulomb friction. A pure inline function of plain numbers: the
// engine's pair loop calls it once per neighbour pair per step (vectorised), and the tests check
// it against closed forms.
//
// Normal force f_n = k_n delta (delta > 0 the overlap). Tangential force: an incremental spring,
// f_t <- f_t - k_t v_t dt, capped at the Coulomb limit mu f_n; at the cap the excess
// displacement (|trial| - mu f_n) / k_t slides against the limiting force and dissipates
// mu f_n (|trial| - mu f_n) / k_t.
//
// The tangential force is stored as a signed scalar along t = (-n_y, n_x). In 2D, rotating the
// stored force vector into the current tangent plane is the same as keeping this scalar while t
// turns with n: the rotation is implicit and exact.

#include <cmath>

namespace grainlab {

struct ContactLawParameters {
    double normalStiffness = 0;     ///< k_n [N/m]
    double tangentialStiffness = 0; ///< k_t [N/m]
    double friction = 0;            ///< Coulomb coefficient mu [-]
    double timeStep = 0;            ///< Delta t [s]
    /// 1 / k_t, or 0 without a tangential spring [m/N]: the slip work multiplies by it, so that
    /// the pair loop divides once per step, not once per pair.
    double tangentialCompliance = 0;
};

/// The parameters with the compliance 1 / k_t filled in (0 when k_t <= 0).
inline ContactLawParameters contactLawParameters(double normalStiffness, double tangentialStiffness,
                                                 double friction, double timeStep) {
    return {normalStiffness, tangentialStiffness, friction, timeStep,
            tangentialStiffness > 0.0 ? 1.0 / tangentialStiffness : 0.0};
}

struct ContactForce {
    double normal = 0;     ///< f_n = k_n delta, along n (pushes B away from A) [N]
    double tangential = 0; ///< f_t on B, along t [N]
    bool sliding = false;  ///< at the Coulomb limit this step
    double slipWork = 0;   ///< energy dissipated by sliding this step [J]
};

// Every operation below is done unconditionally and the cases are chosen by selects: GCC keeps
// -ftrapping-math, so it does not if-convert (vectorise) a loop whose arithmetic sits under a
// condition. For the same reason a caller that must ignore a pair (not touching) calls the law
// all the same and selects zero afterwards; every number stays finite for a finite input.

/// The normal part: f_n = k_n delta [N] for an overlap `overlap` > 0 [m].
inline double normalContactForce(double overlap, const ContactLawParameters& p) {
    return p.normalStiffness * overlap;
}

/// The tangential part, given the normal force `normal` [N]: the incremental spring capped at
/// the Coulomb limit. `tangentialVelocity` is the velocity of B relative to A at the contact
/// point along t [m/s]; `storedTangential` the tangential force carried from the previous step
/// [N]. Fills tangential, sliding and slipWork of `f`.
inline void tangentialContactForce(double normal, double tangentialVelocity,
                                   double storedTangential, const ContactLawParameters& p,
                                   ContactForce& f) {
    const double trial = storedTangential - p.tangentialStiffness * tangentialVelocity * p.timeStep;
    const double limit = p.friction * normal;
    const double size = std::fabs(trial);
    const double clipped = std::copysign(limit, trial);
    const double slid = limit * (size - limit) * p.tangentialCompliance;
    const bool slide = size > limit;
    f.tangential = slide ? clipped : trial;
    f.slipWork = slide ? slid : 0.0;
    f.sliding = slide;
}

/// One step of the law for a touching pair: both parts. `overlap` > 0 [m]; the other arguments
/// as for tangentialContactForce.
inline ContactForce linearContactForce(double overlap, double tangentialVelocity,
                                       double storedTangential, const ContactLawParameters& p) {
    ContactForce f;
    f.normal = normalContactForce(overlap, p);
    tangentialContactForce(f.normal, tangentialVelocity, storedTangential, p, f);
    return f;
}

} // namespace grainlab
