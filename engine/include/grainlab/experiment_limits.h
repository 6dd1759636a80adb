#pragma once
// The ranges of the experiment file that are set by what the engine can honour rather than by
// physics alone: the reader refuses a file outside them up front (docs/experiment-file.md).

#include <cstdint>

namespace grainlab {

/// Memory a run needs per grain, as an upper estimate [B]: the stepper (about 0.5 KiB with its
/// neighbour list), the compacted samples kept for the shear tests, the measures and void cells
/// of a record, and a snapshot.
inline constexpr std::int64_t kBytesPerGrain = 4096;

/// The largest grains.count this machine can hold: its physical memory / kBytesPerGrain (at
/// least 1000, at most 2^31 - 1).
std::int64_t maxGrainCount();

/// The largest cell strain per step [-] the servo (max_strain_rate * time_step) or the shear
/// (axial_strain_per_step) may ask for. The Verlet list is rebuilt when the cell has deformed by
/// about skin / (2 a_max + skin) (about 1/20 with the default skin); a cell strain per step
/// beyond 1e-3 would let pairs cross the skin within a few steps and shrinks the cell below two
/// grains before the servo can react.
inline constexpr double kMaxStrainPerStep = 1e-3;

/// Most size classes (grains.size_classes, or entries of grains.widths): one oval shape is built
/// per class before the run (never more classes than grains either).
inline constexpr std::int64_t kMaxSizeClasses = 1000;

/// Largest grains.grid_gap (free space between grid neighbours, in largest widths) [-]: a looser
/// grid only lengthens the compaction, and past it the initial cell's lengths overflow.
inline constexpr double kMaxGridGap = 100.0;
/// grains.cell_aspect_ratio (L1/L2 of the initial cell) must lie in [1/this, this] [-].
inline constexpr double kMaxCellAspectRatio = 1000.0;

/// Grain widths the engine's arithmetic holds finite (areas, moments of inertia, masses) [m].
inline constexpr double kMinGrainWidth = 1e-9;
inline constexpr double kMaxGrainWidth = 1e3;

/// Largest servo.gain [-]. The servo map (docs/stability.md, `grainlab stability --preset
/// servo-full`) measured the largest gain at which the lateral stress control of a shear
/// neither oscillates nor diverges: 1.84 to 3.34 over 15 and 100 kPa, disks and ovals of aspect
/// ratio 0.6 and intervals of 1 to 100 steps (about 2, the limit 4 / (2 + g_I) of a sampled
/// loop on a plant as stiff as the servo's affine estimate, up to 10 steps). The bound sits at
/// g = 1, below which an update never overshoots (the estimate over-predicts the modulus).
inline constexpr double kMaxServoGain = 1.0;
/// The smallest largest-stable gain the servo map measured (the line the bound stands for) [-].
inline constexpr double kMeasuredServoGainLimit = 1.84;

/// The lag number of a servo interval: n * axial strain per step * k_n / (p * 1 m), the lateral
/// stress error the axial loading builds up over one interval, in units of the pressure p, up
/// to the packing's stiffness factor (k_n / (p * 1 m) is the stiffness number of a 2D assembly
/// of unit thickness) [-].
inline double servoLagNumber(int interval, double strainPerStep, double normalStiffness,
                             double pressure) {
    return double(interval) * strainPerStep * normalStiffness / (pressure * 1.0);
}
/// Largest lag number per unit gain of a servo interval above 1 [-]. A proportional servo
/// removes the fraction g of the error per interval, so the error it leaves grows as lag number
/// / g: the servo map measured the lateral stress out of its 1 % band in shear from lag number
/// / g = 0.04 on (at gains up to kMaxServoGain and intervals of 2 to 100 steps;
/// kMeasuredServoLagPerGain); the bound keeps a margin of 2. An interval of 1 is always
/// accepted: nothing does better, and the servo costs nothing per step.
inline constexpr double kMaxServoLagPerGain = 0.02;
inline constexpr double kMeasuredServoLagPerGain = 0.04;

} // namespace grainlab
