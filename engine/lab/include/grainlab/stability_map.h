#pragma once
// The stability map of the explicit integration: its preset file (JSON, documented in
// docs/stability.md) read with the strict reader, the cells it makes (every combination of
// shape, stiffness ratio, damping and packing state), the result of one cell as JSON (what
// `grainlab stability cell` writes), and the limits.csv and accuracy.csv tables of a map.
// Pure functions and plain data, any thread.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/map_sample.h"
#include "grainlab/simulation_state.h"
#include "grainlab/stability_bisection.h"

namespace grainlab {

/// The packing state a map cell is probed in.
enum class PackingKind {
    Gas,   ///< loose grains on a grid with random velocities, colliding
    Dense, ///< compacted at a pressure, then held at a fixed cell, friction on
    Shear, ///< compacted, then sheared (strain-controlled x1, x2 held at the pressure)
};

struct PackingState {
    PackingKind kind = PackingKind::Gas;
    double pressure = 0; ///< compaction and lateral pressure, Dense and Shear [Pa]
};

/// The scene: 150 grains by default; k_n, density and the compaction rule are the engine's
/// defaults, those of the shared compacted scene.
struct StabilityMapSpec : CompactedSampleMapSpec {
    StabilityMapSpec() {
        name = "stability";
        grains = 150;
    }
    double friction = 0.5;         ///< mu while probing [-]
    double gasGap = 1.0;           ///< free space between grid neighbours, fraction of W_max [-]
    double gasSpeed = 1.0;         ///< rms grain speed of the gas [m/s]
    double shearStrainRate = 1.0;  ///< axial strain rate during shear [1/s]
    double shearPreStrain = 0.002; ///< axial strain sheared before probing [-]
    double compactionRate = 20.0;  ///< servo rate cap while compacting [1/s]
    // The probe and the bisection.
    std::int64_t steps = 2000; ///< steps per probe run [-]
    double precision = 0.02;   ///< relative precision of the limit [-]
    double lowBound = 0.05;    ///< expected stable [sqrt(m_min / k_n)]
    double highBound = 4.0;    ///< expected unstable [sqrt(m_min / k_n)]
    std::vector<double> accuracyFractions{0.25, 0.5, 0.9}; ///< of the limit, damping off [-]
    // The axes.
    std::vector<double> aspectRatios{1.0};       ///< eta = H/W [-]
    std::vector<double> stiffnessRatios{1.0};    ///< k_t / k_n [-]
    std::vector<DampingParameters> dampings{{}}; ///< damping kinds and coefficients
    std::vector<PackingState> packings{{}};
};

/// One cell of the map: one value on each axis.
struct StabilityCell {
    std::string id; ///< e.g. "eta0.6_kt0.5_viscous0.05_dense15kPa" (a file name)
    double aspectRatio = 1;
    double stiffnessRatio = 1;
    DampingParameters damping;
    PackingState packing;
};

/// The map a preset file describes, from its "kind": "time_step" (the default: this file's
/// map), "servo" (servo_map.h) or "geometry" (geometry_map.h). Refuses another kind naming the
/// file (JsonFileError).
std::string stabilityPresetKind(const std::string& text, const std::string& sourceName);

/// Reads and validates a preset file; refuses an unknown key, a wrong type or a value out of
/// range naming the file, the key and the range (JsonFileError, strict_json.h).
StabilityMapSpec readStabilityPreset(const std::string& path);
/// The same from text; `sourceName` names it in messages.
StabilityMapSpec parseStabilityPreset(const std::string& text, const std::string& sourceName);

/// Every cell, in the order aspect ratio, stiffness ratio, damping, packing (the last fastest).
std::vector<StabilityCell> stabilityCells(const StabilityMapSpec& spec);

/// "none", "viscous 0.05", "local 0.7".
std::string dampingLabel(const DampingParameters& damping);
/// "gas", "dense 15 kPa", "shear 100 kPa".
std::string packingLabel(const PackingState& packing);

/// Energy-balance residual with damping off at a step below the limit.
struct AccuracyPoint {
    double fraction = 0;      ///< of the measured limit [-]
    double step = 0;          ///< [sqrt(m_min / k_n)]
    bool stable = true;       ///< the probe's verdict at that step
    double maxResidual = 0;   ///< largest |residual| / E_ref over the run [-]
    double finalResidual = 0; ///< |residual| / E_ref at the end [-]
};

/// What one cell measured.
struct StabilityCellResult {
    StabilityCell cell;
    double timeUnit = 0; ///< sqrt(m_min / k_n) [s]
    StepLimit limit;     ///< in units of timeUnit
    double estimate = 0; ///< the engine's criticalTimeStep (time_step.h) [timeUnit]
    double estimateTranslational = 0, estimateRotational = 0; ///< [timeUnit]
    std::vector<AccuracyPoint> accuracy;
    bool compactionCalm = true; ///< the dense sample reached the equilibrium rule
    double seconds = 0;         ///< wall time of the cell [s]
};

/// The result as JSON text, and back (throws std::runtime_error naming `sourceName`).
std::string cellResultJson(const StabilityCellResult& result);
StabilityCellResult parseCellResult(const std::string& text, const std::string& sourceName);

/// limits.csv: one row per result, header with units.
std::string limitsCsv(const std::vector<StabilityCellResult>& results);
/// accuracy.csv: one row per result and accuracy point.
std::string accuracyCsv(const std::vector<StabilityCellResult>& results);

} // namespace grainlab
