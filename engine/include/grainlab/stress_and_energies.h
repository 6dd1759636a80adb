#pragma once
// Two plain results of the stepper, used by the measures and the recorders: the Love-Weber stress
// of the cell and the energy balance. Plain data, safe to copy to any thread.

namespace grainlab {

/// Symmetric Love-Weber stress, compression positive [Pa].
struct Stress {
    double s11 = 0, s22 = 0, s12 = 0;
};

struct Energies {
    double kinetic = 0;      ///< fluctuating translational + rotational [J]
    double elastic = 0;      ///< spring energy of the contacts [J]
    double boundaryWork = 0; ///< work done by the cell on the assembly [J]
    double frictionWork = 0; ///< cumulative sliding dissipation [J]
    double dampingWork = 0;  ///< cumulative damping dissipation [J]
};

} // namespace grainlab
