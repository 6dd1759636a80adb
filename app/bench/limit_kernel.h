#pragma once
// The `--limit` row of `grainlab bench`: a minimal stand-alone time-stepping kernel with the
// engine's disk physics and nothing else, to tell how close the engine comes to what the
// processor allows on the same work. Same physics as Simulation for disks: linear normal spring
// f_n = k_n delta, incremental tangential spring capped at mu f_n, global viscous damping
// integrated time-centred, central differences with the affine motion of the deforming cell, a
// Verlet list rebuilt by the same skin criterion. Left out: the servo (axis 2 is held at its
// length), stress and energy sums, sliding flags, overlap and runaway checks, restarts.
// Forces per pair in a flat vectorised loop, then gathered per grain in a fixed order (the
// engine's form). Runs on the caller's thread, OpenMP inside; bench only, not thread-safe.

#include <array>
#include <cstdint>
#include <vector>

#include "grainlab/pair_index.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

class LimitKernel {
public:
    /// Takes a state whose every shape is a disk (std::invalid_argument otherwise), with the
    /// engine's parameters; axis 1 shortened at the constant strain rate `axialStrainRate` [1/s]
    /// (L11 = -rate, as the bench drives the engine), axis 2 held. Builds the neighbour list and
    /// the forces of the initial state (stored tangential forces kept, as the engine does).
    LimitKernel(const SimulationState& state, double axialStrainRate, int threads);

    void advance(std::int64_t steps);

    std::size_t grainCount() const { return x1_.size(); }
    std::size_t pairCount() const { return first_.size(); }
    /// Touching pairs (positive normal force).
    std::size_t contactCount() const;
    std::int64_t rebuilds() const { return rebuilds_; }
    const std::vector<double>& x1() const { return x1_; }
    const std::vector<double>& x2() const { return x2_; }
    const std::vector<double>& v1() const { return v1_; }
    const std::vector<double>& omega() const { return omega_; }
    /// Net contact force and torque on every grain [N], [N m].
    void netForces(std::vector<double>& f1, std::vector<double>& f2,
                   std::vector<double>& torque) const;

private:
    void rebuild();
    void buildIndex();
    void pairForces(double timeStep);
    void integrate();

    int threads_ = 1;
    double timeStep_, normalStiffness_, tangentialStiffness_, friction_; // [s], [N/m], [N/m], [-]
    double strainRate_;                                                  // [1/s]
    double skin_, maxRadius_;                                            // [m]
    std::array<double, 4> cell_{}, L_{}; ///< h [m] and the velocity gradient [1/s]
    std::vector<double> x1_, x2_, v1_, v2_, omega_, radius_;
    std::vector<double> keepTrans_, pushTrans_, keepRot_, pushRot_; ///< v <- keep v + push F
    // Neighbour list (pairs sorted by first grain) with its reference positions and cell.
    std::vector<std::int32_t> first_, second_, shift1_, shift2_;
    /// r_i and r_j in pair order [m] (as the engine: no radius gathered); stored f_t [N].
    std::vector<double> radiusFirst_, radiusSecond_, tangential_;
    std::vector<double> force1_, force2_, torqueFirst_, torqueSecond_;
    PairIndex pairIndex_;
    std::vector<double> reference1_, reference2_;
    std::array<double, 4> referenceCell_{};
    double skinInUse_ = 0, maxDrift_ = 0;
    std::int64_t rebuilds_ = 0;
};

} // namespace grainlab
