#pragma once
// The complete state of a simulation: everything a checkpoint holds and everything needed to
// continue a run bit for bit (docs/formats.md). Plain data, structure of arrays. A SimulationState
// is built by the generator or read from a run file, handed to Simulation, and copied out of it for
// checkpoints and snapshots. Not shared between threads while being written.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/oval_shape.h"

namespace grainlab {

/// How the fluctuating motion is damped (docs/physics.md).
enum class DampingKind {
    None,          ///< no damping (closed-form tests)
    GlobalViscous, ///< F = -2 beta sqrt(k_n m) v', M = -2 beta sqrt(k_n a^2 I) omega
    CundallLocal,  ///< F_i = -alpha |F_i| sign(v'_i) per component (Cundall's local damping)
};

struct DampingParameters {
    DampingKind kind = DampingKind::GlobalViscous;
    double coefficient = 0.05; ///< beta (viscous) or alpha (local) [-]
};

/// How one axis of the cell is driven. Compression positive.
///  - Strain: a strain rate.
///  - Stress: sigma_ii held at targetStress by the servo.
///  - ConstantArea (axis x2 only): the rate of x2 is chosen each step so that the cell's area
///    after the step is referenceArea, the DEM analogue of an undrained test. The next length
///    follows from A0 and the other axis's next length, so round-off does not accumulate.
///  - StressPath: the servo holds sigma_ii at targetStress + pathSlope (sigma_jj - pathOrigin),
///    j the other axis, the target recomputed from the current sigma_jj at every servo update
///    (slope 0: constant sigma_ii; slope -1 on x2: constant p = (sigma11 + sigma22) / 2).
enum class AxisMode { Strain, Stress, ConstantArea, StressPath };

struct AxisControl {
    AxisMode mode = AxisMode::Strain;
    double strainRate = 0; ///< compressive strain rate, Strain mode [1/s]
    /// Target sigma_ii, Stress mode; sigma_ii at the path origin, StressPath mode [Pa]
    double targetStress = 0;
    /// Strain mode: 0 makes strainRate the true (logarithmic) rate; a length L0 > 0 makes it
    /// the engineering rate d(L0 - L)/(L0 dt), i.e. a constant length change per step [m].
    double referenceLength = 0;
    double referenceArea = 0; ///< A0 held, ConstantArea mode [m^2]
    double pathSlope = 0;     ///< a = d sigma_ii / d sigma_jj along the path, StressPath [-]
    double pathOrigin = 0;    ///< sigma_jj at the path origin, StressPath mode [Pa]
};

struct ServoParameters {
    double gain = 0.3;          ///< g <= 1: fraction of the error removed per servo interval
    double integralGain = 0.05; ///< integral term, per servo interval, in units of the P rate
    double maxStrainRate = 1.0; ///< rate cap [1/s]
    int interval = 1;           ///< servo update every `interval` steps
};

struct StabilityParameters {
    int designCoordination = 6;      ///< contacts on the stiffest grain in the Delta t estimate
    double maxOverlapFraction = 0.1; ///< overlap above this fraction of the smaller width: blow-up
    double maxStepFraction = 0.1;    ///< a step moving a grain more than this fraction of its
                                     ///< half-height: runaway (kinetic energy without bound)
    /// Stability probes only (stability_probe.h), never set from a file: no refusal of a time
    /// step above the estimate, no overlap or runaway stop (the guards being measured). A
    /// non-finite state still stops the run.
    bool unguarded = false;
};

struct SimulationParameters {
    double timeStep = 1e-6;           ///< Delta t [s]
    double normalStiffness = 1e8;     ///< k_n [N/m]
    double tangentialStiffness = 1e8; ///< k_t [N/m]
    double friction = 0.5;            ///< mu [-]
    double density = 2650;            ///< rho [kg/m^3], unit thickness 1 m
    DampingParameters damping;
    ServoParameters servo;
    StabilityParameters stability;
    double neighbourSkin = 0;      ///< Verlet skin [m]; 0 picks 0.1 * smallest width
    int threads = 1;               ///< OpenMP threads (results are bit-identical for any)
    bool allArcPairs = false;      ///< use the 16-pair reference oval test (tests only)
    bool ovalPathForDisks = false; ///< run disks through the oval kernel (tests only)
    bool perGrainArcs = false;     ///< one-form ovals through per-grain tables (tests only)
};

/// Grain state, structure of arrays. Index = grain id. x1 is the axial direction.
struct GrainArrays {
    std::vector<double> x1, x2;      ///< centre [m]
    std::vector<double> theta;       ///< orientation of the body x axis from x1 [rad]
    std::vector<double> v1, v2;      ///< fluctuating velocity v' [m/s]
    std::vector<double> omega;       ///< angular velocity [rad/s]
    std::vector<std::int32_t> shape; ///< index into the shape table

    std::size_t size() const { return x1.size(); }
    void resize(std::size_t n);
};

/// Neighbour pairs with their contact history, structure of arrays, sorted by (first, second).
/// A pair is one grain pair at one periodic image: the image of `second` is x + h * shift.
struct PairArrays {
    std::vector<std::int32_t> first, second;
    std::vector<std::int32_t> shift1, shift2; ///< image shift k (cell vectors)
    std::vector<double> tangentialForce;      ///< stored f_t along t [N]
    std::vector<std::uint8_t> sliding;        ///< at the Coulomb limit at the last step

    std::size_t size() const { return first.size(); }
    void resize(std::size_t n);
};

struct SimulationState {
    std::vector<OvalShape> shapes;
    GrainArrays grains;
    PairArrays pairs;
    std::array<double, 4> cell{};             ///< h, column-major: (h11, h21, h12, h22) [m]
    std::array<double, 4> velocityGradient{}; ///< L, column-major [1/s]
    std::array<AxisControl, 2> axes{};        ///< control of x1 and x2
    std::array<double, 2> servoIntegral{};    ///< integral servo rate per axis [1/s]
    // Neighbour-list reference: positions and cell at the last rebuild.
    std::vector<double> reference1, reference2;
    std::array<double, 4> referenceCell{};
    std::int64_t step = 0;
    double time = 0; ///< [s]
    // Cumulative energy bookkeeping [J].
    double boundaryWork = 0;
    double frictionWork = 0;
    double dampingWork = 0;
    SimulationParameters parameters;
};

/// True when two states hold the same bits in everything that evolves: grains, neighbour pairs
/// with their history, cell, velocity gradient, servo, step, time and energy totals. The
/// determinism and restart checks (tests, `grainlab bench`) use it.
bool identicalDynamics(const SimulationState& a, const SimulationState& b);

} // namespace grainlab
