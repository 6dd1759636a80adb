#pragma once
// The experiment: everything one experiment file (JSON) says, as plain data
// (docs/experiment-file.md). Read by experiment_file.h, run by experiment_runner.h, stored verbatim
// in the run file. Immutable once a run starts; read from any thread.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/assembly.h"
#include "grainlab/loading_path.h"
#include "grainlab/simulation_state.h"

namespace grainlab {

/// When a stress-controlled stage counts as finished: stress within tolerance and the
/// unbalanced-force index below its threshold at `calmChecks` consecutive checks (a single
/// check can pass during a transient), or the stage fails after `maxSteps`.
struct EquilibriumCriterion {
    double stressTolerance = 0.01;    ///< |sigma_ii - target| / target [-]
    double unbalancedForceMax = 1.0;  ///< I_uf threshold [%]
    std::int64_t checkInterval = 100; ///< steps between checks
    int calmChecks = 20;              ///< consecutive passing checks needed
    std::int64_t maxSteps = 2000000;  ///< the stage fails (error) beyond this many steps
};

struct CompactionSpec {
    double friction = 0.0;         ///< mu during compaction [-]
    std::vector<double> pressures; ///< confining pressures, ascending [Pa]
    double maxStrainRate = 20.0;   ///< servo rate cap while compacting [1/s]
    EquilibriumCriterion criterion;
};

struct ShearSpec {
    double friction = 0.5;              ///< mu before and during shear [-]
    std::vector<double> pressures;      ///< which compacted samples to shear [Pa]
    double axialStrainPerStep = 2e-7;   ///< strain increment per step (strain control) [-]
    double targetAxialStrain = 0.15;    ///< eps1 at which the test ends [-]
    double maxStrainRate = 1.0;         ///< lateral servo rate cap [1/s]
    EquilibriumCriterion equilibration; ///< re-equilibration at mu before shear
};

struct RecordSpec {
    double strainInterval = 1e-4;              ///< record every this much eps1 during shear [-]
    std::int64_t stepInterval = 1000;          ///< record every this many steps before shear
    double snapshotStrainInterval = 0.01;      ///< snapshot (checkpoint) every this much eps1 [-]
    std::int64_t snapshotStepInterval = 50000; ///< snapshot every this many steps before shear
};

struct ExperimentConfig {
    std::string name = "experiment";
    std::string sourcePath;          ///< the file it was read from ("" if built in code)
    std::string sourceText;          ///< the file's text, stored in the run file
    AssemblySpec assembly;           ///< grains and cell (seed lives here)
    SimulationParameters parameters; ///< contact law, time step, damping, servo, threads
    CompactionSpec compaction;
    ShearSpec shear;
    RecordSpec record;
    /// The tests each sheared sample gets, in order, each from the re-equilibrated sample (the
    /// "test" key: one object or a list). One drained test when the file names none.
    std::vector<LoadingPath> tests{LoadingPath{}};
};

} // namespace grainlab
