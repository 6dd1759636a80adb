#pragma once
// The shared compacted scene: N grains generated on a loose grid, then compacted isotropically
// by the servo to a pressure until the experiment runner's equilibrium rule holds
// (equilibrium.h), or a step cap. Used by the engine tests, the engine bench and the window
// bench, so that "compact N grains to p" is written once. Synchronous, on the caller's thread;
// progress is reported through a callback after every check.

#include <cstdint>
#include <functional>
#include <vector>

#include "grainlab/equilibrium.h"
#include "grainlab/experiment.h"
#include "grainlab/simulation.h"

namespace grainlab::scenes {

struct CompactedSceneSpec {
    int grains = 1000;           ///< N [-]
    double aspectRatio = 1.0;    ///< b / a, 1 for disks [-]
    std::vector<double> widths;  ///< the size classes; empty: 11 classes over 1-2 mm [m]
    std::uint64_t seed = 42;     ///< of the grid assembly
    double pressure = 1e5;       ///< target of both axes [Pa]
    double friction = 0.0;       ///< mu during compaction [-]
    double maxStrainRate = 20.0; ///< servo rate cap [1/s]
    int threads = 1;             ///< engine threads (results are the same bits)
    /// The rule and the cap: checks every checkInterval steps; stops after calmChecks passing
    /// checks in a row, or at maxSteps (never an error: the result says which).
    EquilibriumCriterion criterion{0.01, 1.0, 100, 20, 400000};
};

struct CompactionProgress {
    std::int64_t step = 0;     ///< steps done [-]
    std::int64_t maxSteps = 0; ///< the cap [-]
    EquilibriumCheck check;    ///< the latest check
    int calm = 0;              ///< consecutive passing checks so far
};
using CompactionCallback = std::function<void(const CompactionProgress&)>;

struct CompactedScene {
    Simulation simulation;
    bool equilibrium = false;         ///< the rule held (else the step cap stopped it)
    std::int64_t steps = 0;           ///< compaction steps taken
    std::vector<double> initialTheta; ///< orientations as generated [rad]
};

/// Generates and compacts the scene; velocities are left as they are at the end.
CompactedScene compactScene(const CompactedSceneSpec& spec,
                            const CompactionCallback& progress = {});

/// The compacted state with velocities cleared (the bench's and the tests' dense assembly).
SimulationState compactedState(const CompactedSceneSpec& spec,
                               const CompactionCallback& progress = {});

} // namespace grainlab::scenes
