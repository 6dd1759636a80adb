#pragma once
// The servo map of `grainlab stability` (a preset with "kind": "servo", docs/stability.md):
// where the lateral stress control of a drained biaxial shear oscillates or diverges, over the
// servo's gain and interval, for each confining pressure and grain shape. Its preset file read
// with the strict reader, its cells (pressure x shape x interval; each cell runs every gain of
// the grid on one compacted sample and bisects the largest stable gain), a cell's result as
// JSON, and the servo_limits.csv and servo_runs.csv tables. Pure functions and plain data, any
// thread.

#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/experiment_limits.h"
#include "grainlab/map_sample.h"
#include "grainlab/servo_probe.h"
#include "grainlab/stability_bisection.h"

namespace grainlab {

/// The sample (k_n = 1e8 N/m and density 2650 kg/m^3, the engine's defaults; 300 grains by
/// default) is compacted frictionless by the shared compacted scene, then equilibrated at
/// `friction`.
struct ServoMapSpec : CompactedSampleMapSpec {
    ServoMapSpec() {
        name = "servo";
        grains = 300;
    }
    double timeStep = 1e-6;       ///< [s]
    double friction = 0.5;        ///< mu in shear [-]
    double compactionRate = 20.0; ///< servo rate cap while compacting [1/s]
    // The shear (the study base's protocol).
    double strainPerStep = 1e-6; ///< axial engineering strain per step [-]
    double maxStrainRate = 50.0; ///< the lateral servo's rate cap [1/s]
    double strain = 0.005;       ///< axial strain sheared per run [-]
    /// Each run is at least this many servo updates long (a long interval needs more strain) [-].
    std::int64_t minUpdates = 64;
    double integralGain = 0.05; ///< g_I of every run [-]
    ServoThresholds thresholds;
    double precision = 0.02; ///< relative width of the final bracket of the stable gain [-]
    // The axes.
    std::vector<double> pressures{15000.0}; ///< confining pressure [Pa]
    std::vector<double> aspectRatios{1.0};  ///< eta = H/W [-]
    std::vector<int> intervals{1};          ///< servo interval [steps]
    std::vector<double> gains{0.3};         ///< the grid of gains, ascending [-]
};

/// One cell: a sample (pressure, shape) and a servo interval; every gain of the grid is run.
struct ServoCell {
    std::string id; ///< e.g. "servo_eta0.6_p15kPa_n10"
    double pressure = 0;
    double aspectRatio = 1;
    int interval = 1;
};

/// Reads and validates a servo preset (JsonFileError naming the file, the key and the range).
ServoMapSpec readServoPreset(const std::string& path);
ServoMapSpec parseServoPreset(const std::string& text, const std::string& sourceName);

/// Every cell, in the order pressure, aspect ratio, interval (the last fastest).
std::vector<ServoCell> servoCells(const ServoMapSpec& spec);

/// Steps of one run at `interval`: the preset's strain, or minUpdates intervals if longer.
std::int64_t servoRunSteps(const ServoMapSpec& spec, int interval);

/// One run of a cell.
struct ServoRun {
    double gain = 0;
    bool grid = true; ///< a gain of the grid (else one of the bisection)
    ServoResponse response = ServoResponse::Steady;
    ServoErrorStats stats;
};

struct ServoCellResult {
    ServoCell cell;
    std::vector<ServoRun> runs; ///< grid first, then the bisection's, in the order run
    /// The largest stable gain (neither oscillating nor diverging), in units of the gain: the
    /// bracket [low, high] with high / low - 1 <= precision. Not bracketed when every gain of
    /// the grid was stable (limit = the largest) or none was (limit = the smallest).
    StepLimit limit;
    ServoResponse aboveLimit = ServoResponse::Steady; ///< the response at `limit.high`
    double stiffnessOverPressure = 0; ///< the servo's affine E_22 / p at the start of shear [-]
    bool compactionCalm = true;       ///< the sample met the equilibrium rule
    double seconds = 0;               ///< wall time [s]

    /// The smallest and largest grid gain whose run was steady (0 when none).
    double smallestSteadyGain() const;
    double largestSteadyGain() const;
    /// The smallest max |error| over the steady or lagging runs [-] (infinity when none).
    double bestMaxError() const;
};

std::string servoCellResultJson(const ServoCellResult& result);
ServoCellResult parseServoCellResult(const std::string& text, const std::string& sourceName);

/// servo_limits.csv: one row per cell. servo_runs.csv: one row per run.
std::string servoLimitsCsv(const ServoMapSpec& spec, const std::vector<ServoCellResult>& results);
std::string servoRunsCsv(const std::vector<ServoCellResult>& results);

} // namespace grainlab
