#pragma once
// The time-stepping engine: grains in a deforming periodic cell (docs/physics.md). Owns the grain
// state (structure of arrays), the neighbour list with the persistent contact history, the cell and
// its servo. Synchronous: step() runs on the caller's thread (a worker thread in the GUI, the main
// thread headless) and uses OpenMP inside; results are bit-identical for any thread count because
// forces are computed per pair, then gathered per grain in a fixed order, and every sum is taken
// over fixed blocks in a fixed order. Not thread-safe: one thread drives it.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "grainlab/contact_geometry.h"
#include "grainlab/contact_network.h"
#include "grainlab/pair_index.h"
#include "grainlab/periodic_cell.h"
#include "grainlab/simulation_state.h"
#include "grainlab/stress_and_energies.h"

namespace grainlab {

/// A run stopped for a physical reason (blow-up). Names the grain, the step and the cause.
class SimulationError : public std::runtime_error {
public:
    SimulationError(std::int64_t step, std::int32_t grain, std::string cause);
    std::int64_t step;  ///< the step at which the failure was detected
    std::int32_t grain; ///< the grain at fault (-1 if none in particular)
    std::string cause;
};

class Simulation {
public:
    /// Takes ownership of a complete state. Refuses an unstable time step, a cell narrower than
    /// two largest grains, and inconsistent arrays (std::invalid_argument). If the state has no
    /// neighbour list yet, builds one.
    explicit Simulation(SimulationState state);

    /// Advances one time step. Throws SimulationError on blow-up; the state is then the state
    /// of the failed step and must not be checkpointed.
    void step();
    /// Advances `steps` time steps.
    void advance(std::int64_t steps);

    /// Changes how an axis is driven, between steps. Resets that axis's servo integral when the
    /// mode or target changes.
    void setAxisControl(int axis, const AxisControl& control);
    void setFriction(double friction);
    /// Zeroes all fluctuating velocities and spins (e.g. between stages).
    void clearVelocities();
    /// Replaces the fluctuating velocities [m/s] and spins [rad/s] of every grain, between
    /// steps, in place (the arrays keep their storage). Refuses (std::invalid_argument) arrays
    /// of another length than the grain count and non-finite values; nothing is changed then.
    void setVelocities(const std::vector<double>& v1, const std::vector<double>& v2,
                       const std::vector<double>& omega);

    /// A copy of the full state: a complete checkpoint.
    SimulationState state() const;
    const SimulationState& stateRef() const { return s_; }

    std::int64_t stepCount() const { return s_.step; }
    double time() const { return s_.time; }
    std::size_t grainCount() const { return s_.grains.size(); }
    /// The cell matrix h, column-major [m].
    const std::array<double, 4>& cell() const { return s_.cell; }
    double cellArea() const;
    /// Love-Weber stress of the current configuration (symmetric part, compression positive).
    Stress stress() const { return stress_; }
    /// Touching contacts and grain data for the measures (computed on demand).
    ContactNetwork contactNetwork() const;
    Energies energies() const;
    std::size_t contactCount() const;
    /// The unbalanced force index I_uf [%] (measures.h), the same bits as
    /// unbalancedForceIndex(contactNetwork()) without building the network's geometry.
    double unbalancedForceIndex() const;
    std::int64_t neighbourRebuilds() const { return rebuilds_; }
    /// Grain masses [kg].
    const std::vector<double>& grainMass() const { return mass_; }
    /// True when the pair loop runs the one-form oval kernel (every shape an oval of one form,
    /// oneFormArcs; not with the perGrainArcs test switch).
    bool oneFormKernel() const { return oneForm_; }

private:
    void derive();
    void prepareIntegration();
    void rebuildNeighbours();
    bool neighboursStale() const;
    void evaluateForces(bool incrementTangential);
    void integrate();
    template <DampingKind Damping, bool Oval>
    void integrateGrains(const std::array<double, 4>& F);
    void updateServo();
    void buildPairIndex();
    void checkOverlaps() const;
    /// Which contact kernel the pair loop runs: disks; ovals of one form (every grain's arcs
    /// its half-width times one unit table, so that only the half-width is gathered per grain);
    /// ovals through their per-grain arc tables.
    enum class PairShape { Disk, OneForm, PerGrain };
    template <PairShape Shape, bool Frictional, bool Increment>
    void pairForces();
    /// Contact geometry of pair p with branch vector l, exactly as the pair loop computes it.
    ContactGeometry pairGeometry(std::size_t p, double l1, double l2) const;
    /// Net contact force and torque on every grain, summed in the fixed order of the pair loop.
    void gatherForces(std::vector<double>& f1, std::vector<double>& f2,
                      std::vector<double>& torque) const;
    void refuseNarrowCell() const;

    static constexpr int kBlockSumWidth = 7; ///< per block: 4 stress, 2 stiffness, slip work

    SimulationState s_;
    // Derived per grain (rebuilt by derive()).
    std::vector<double> mass_, inertia_;         ///< [kg], [kg m^2]
    std::vector<double> halfWidth_, halfHeight_; ///< a, b [m]
    std::vector<double> dampTrans_, dampRot_;    ///< 2 sqrt(k_n m) [kg/s], 2 sqrt(k_n a^2 I)
    std::vector<double> cosTheta_, sinTheta_;    ///< of the current orientation
    std::vector<double> stepLimit_;              ///< largest travel in one step [m]
    // Oval arcs per grain (copies of the shape's OvalArcs, or with one form the half-width times
    // unitArcs_), read by the vectorised pair loop and the scalar paths.
    std::vector<double> endOffset_, sideOffset_, endRadius_, sideRadius_; ///< [m]
    std::vector<double> cosJunction_, sinJunction_;
    /// Every shape an oval of one form (oneFormArcs): the arcs of that form at half-width 1.
    bool oneForm_ = false;
    OvalArcs unitArcs_;
    // Integration coefficients per grain (prepareIntegration()): v <- keep v + push F, and the
    // damping power factor, for translation and rotation.
    std::vector<double> keepTrans_, pushTrans_, keepRot_,
        pushRot_;                             ///< [-], [s/kg], [-], [s/kg m^2]
    std::vector<double> workTrans_, workRot_; ///< dt beta c [J s^2/m^2], [J s^2]
    // Derived per pair (written by the pair loop, read by the gather in integrate()).
    // Constant per pair (buildPairIndex()): the half-widths a_i and a_j [m], read in pair order
    // (the pair loop takes a_i + a_j and min(W_i, W_j) = 2 min(a_i, a_j) from them, and gathers
    // no half-width).
    std::vector<double> pairHalfWidthFirst_, pairHalfWidthSecond_;
    std::vector<double> pairForce1_, pairForce2_, torqueFirst_, torqueSecond_, normalForce_;
    PairIndex pairIndex_; ///< the pairs on each grain (buildPairIndex())
    std::vector<double> blockSums_, grainBlockSums_;
    bool allDisks_ = true;
    double maxHalfWidth_ = 0;
    double skin_ = 0;          ///< requested Verlet skin [m]
    double skinInUse_ = 0;     ///< skin of the current list (smaller in a narrow cell) [m]
    double maxDrift_ = 0;      ///< largest non-affine displacement since the rebuild [m]
    double overlapExcess_ = 0; ///< max of overlap - limit fraction * smaller width [m]
    bool runaway_ = false;     ///< a grain moved too far or became non-finite this step
    Stress stress_;
    std::array<double, 2> stiffness_{};
    std::int64_t rebuilds_ = 0;
};

/// Block size of every deterministic reduction (pairs or grains per block).
inline constexpr int kReductionBlock = 512;
/// Number of reduction blocks for `n` items.
inline int reductionBlocks(std::size_t n) {
    return static_cast<int>((n + kReductionBlock - 1) / kReductionBlock);
}

} // namespace grainlab
