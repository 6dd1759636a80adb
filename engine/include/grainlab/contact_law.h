#pragma once
// Linear spring contact law with Coulomb friction (SPEC §3.3). A pure inline function of plain
// numbers, called once per touching pair per step in the hot loop, and by the tests against
// closed forms.
//
// The tangential force is stored as a signed scalar along t = (-n_y, n_x). In 2D, rotating the
// stored force vector into the current tangent plane (SPEC §3.3) is the same as keeping this
// scalar while t turns with n: the rotation is implicit and exact.

#include <cmath>

namespace grainlab {

struct ContactLawParameters {
    double normalStiffness = 0;     ///< k_n [N/m]
    double tangentialStiffness = 0; ///< k_t [N/m]
    double friction = 0;            ///< Coulomb coefficient mu [-]
    double timeStep = 0;            ///< Delta t [s]
};

struct ContactForce {
    double normal = 0;      ///< f_n >= 0, along n (pushes B away from A) [N]
    double tangential = 0;  ///< f_t on B, along t [N]
    bool sliding = false;   ///< at the Coulomb limit this step
    double slipWork = 0;    ///< energy dissipated by sliding this step [J]
};

/// One step of the law for a touching pair. `overlap` > 0 [m]; `tangentialVelocity` is the
/// velocity of B relative to A at the contact point along t [m/s]; `storedTangential` the
/// tangential force carried from the previous step [N].
inline ContactForce linearContactForce(double overlap, double tangentialVelocity,
                                       double storedTangential, const ContactLawParameters& p) {
    ContactForce f;
    f.normal = p.normalStiffness * overlap;
    const double trial =
        storedTangential - p.tangentialStiffness * tangentialVelocity * p.timeStep;
    const double limit = p.friction * f.normal;
    if (std::fabs(trial) > limit) {
        // Slip: the elastic part is scaled back to the limit; the excess displacement
        // (|trial| - limit)/k_t slid against the limiting force.
        f.tangential = std::copysign(limit, trial);
        f.sliding = true;
        f.slipWork = limit * (std::fabs(trial) - limit) / p.tangentialStiffness;
    } else {
        f.tangential = trial;
    }
    return f;
}

} // namespace grainlab
