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

} // namespace grainlab
