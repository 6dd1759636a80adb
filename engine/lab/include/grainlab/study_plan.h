#pragma once
// A study: one base experiment run at several settings of its method knobs (time step, loading
// rate, damping, grain count, shape, neighbour skin, threads), each at the same seeds, so that
// every difference can be held against the seed-to-seed scatter of a reference setting. This
// header holds the plain description of a study (read from a study file by study_file.h) and
// its expansion into runs: each run is an ordinary experiment file for `grainlab run`, written
// into its own run folder. Pure functions, no I/O, any thread.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace grainlab {

/// The method knobs a study can turn. Levels are dimensionless where the physics has a scale.
enum class KnobKind {
    TimeStepFraction,   ///< time_step = level * the engine's critical-step estimate [-]
    AxialStrainPerStep, ///< shear.axial_strain_per_step [-]
    InertialNumber,     ///< sets axial_strain_per_step so that I = eps1_rate d sqrt(rho/p) [-]
    Damping,            ///< damping kind and coefficient (a JSON object as in experiment files)
    GrainCount,         ///< grains.count [-]
    Shape,              ///< grains.aspect_ratio (+ closure, end_radius_ratio): a JSON object
    NeighbourSkin,      ///< neighbour_skin = level * grains.width_min [-]
    Threads,            ///< threads (a cost-only knob: results must not change at all)
};

/// The knob's name in study files and CSV headers, e.g. "time_step_fraction".
std::string knobName(KnobKind kind);
/// The knob named `name`, or nothing.
std::optional<KnobKind> knobNamed(const std::string& name);
/// Every knob, in the order of knobName.
const std::vector<KnobKind>& allKnobs();

/// One level of a knob: a number, or (damping, shape) a JSON object's text.
struct KnobLevel {
    double number = 0;
    std::string object; ///< minified JSON object for Damping and Shape levels; "" otherwise
    /// The level as written in labels, folder names and CSV cells, e.g. "0.5", "none",
    /// "cundall_local-0.7", "disk".
    std::string label() const;
    bool operator==(const KnobLevel& other) const {
        return number == other.number && object == other.object;
    }
};

struct Knob {
    KnobKind kind;
    std::vector<KnobLevel> levels;
};

/// How settings are made from the knobs.
enum class StudyDesign {
    OneAtATime, ///< the reference, and each knob at each of its levels with the others held
    Grid,       ///< every combination of levels
};

/// How close a metric must stay to the reference mean for a setting to count as valid.
struct Tolerance {
    double value = 0;      ///< allowed |setting mean - reference mean|
    bool relative = false; ///< value is a fraction of |reference mean| (else in the metric's unit)
};

struct StudySpec {
    std::string name = "study";
    std::string sourcePath; ///< the study file ("" if built in code)
    /// The study file's text with its base experiment written inline: what a study folder keeps
    /// (study.json), so that it is complete on its own.
    std::string sourceText;
    std::string costMeasure = "cpu_seconds"; ///< "cpu_seconds", "wall_seconds" or "grain_steps"
    std::string baseExperiment;              ///< the base experiment file's text (JSON)
    std::string baseSource;                  ///< where it came from (a path, or "<study>:base")
    std::vector<Knob> knobs;
    StudyDesign design = StudyDesign::OneAtATime;
    /// The reference setting: a level per knob; knobs left out stay as the base experiment says.
    std::map<KnobKind, KnobLevel> reference;
    std::vector<std::uint64_t> seeds{1, 2, 3, 4, 5};
    /// Tolerances by metric name ("peak_q_over_p", "rms_q_over_p", ...).
    std::map<std::string, Tolerance> tolerances;
    /// The metrics that decide the recommendation (each must have a tolerance).
    std::vector<std::string> deciding;
};

/// One setting: a level for some knobs (the rest as in the reference, then the base).
struct StudySetting {
    std::string id;                       ///< folder-safe, e.g. "ref", "time_step_fraction-0.5"
    std::map<KnobKind, KnobLevel> levels; ///< every knob of the study, resolved
    bool isReference = false;
};

/// One run: a setting at a seed, with the experiment file it runs.
struct StudyRun {
    std::string id;  ///< folder name under the study's runs/, e.g. "ref-seed3"
    int setting = 0; ///< index into StudyPlan::settings
    std::uint64_t seed = 0;
    std::string experimentText; ///< the complete experiment file (JSON) of this run
};

struct StudyPlan {
    std::vector<StudySetting> settings; ///< settings[0] is the reference
    std::vector<StudyRun> runs;         ///< settings x seeds, setting-major
};

/// Expands a study into its settings and runs. Each run's experiment is the base with the
/// setting's levels and the seed applied, and is validated by the experiment-file reader:
/// a level that makes an invalid experiment throws ExperimentFileError naming the run.
StudyPlan planStudy(const StudySpec& spec);

/// The value a numeric knob has in an experiment (e.g. the base's time step as a fraction of
/// its critical-step estimate, its grain count); nothing for the damping and shape knobs,
/// whose levels are objects. Throws ExperimentFileError on an invalid experiment.
std::optional<double> knobValueIn(const std::string& experimentText, KnobKind kind);

/// The base experiment text with `levels` and `seed` applied (validated).
std::string applySetting(const std::string& baseText, const std::string& baseSource,
                         const std::map<KnobKind, KnobLevel>& levels, std::uint64_t seed);

} // namespace grainlab
