#pragma once
// The numbers a researcher compares between runs of a biaxial test, taken from one test's
// recorded series (a SeriesTable with the columns of docs/measures.md): the peak of q/p, values
// at fixed axial strains, the servo's worst lateral-stress error, the mean unbalanced force and
// the share of the boundary work that damping took. Plain computation over recorded rows, no
// simulation needed: used by the many-run commands, the window and the tests on any thread.
//
// Only the rows of the shear stage count (the test's series also holds its re-equilibration
// before shear); the void ratio of the compacted sample is the test's first row.

#include <optional>
#include <string>
#include <vector>

#include "grainlab/series.h"
#include "grainlab/statistics.h"

namespace grainlab {

/// Axial strains at which values are reported [-] (2, 5 and 10 %).
inline constexpr double kMetricStrains[] = {0.02, 0.05, 0.10};

struct ShearMetrics {
    /// largest q/p during shear; in extension (eps1 < 0), the most negative, and the values
    /// "at a strain" below are at eps1 = -strain [-]
    std::optional<double> peakStressRatio;
    std::optional<double> peakAxialStrain;       ///< eps1 at that peak [-]
    std::optional<double> peakFrictionAngle;     ///< phi at that peak [deg]
    std::optional<double> stressRatioAt[3];      ///< q/p at eps1 = kMetricStrains [-]
    std::optional<double> volumetricStrainAt[3]; ///< eps_v at eps1 = kMetricStrains [-]
    std::optional<double> maxDilatancy;          ///< largest dilatancy index -d eps_v/d eps1 [-]
    std::optional<double> voidRatioAtStart;      ///< e of the compacted sample (first row) [-]
    std::optional<double> coordinationAt5;       ///< Z at eps1 = 5 % [-]
    std::optional<double> coordinationAt10;      ///< Z at eps1 = 10 % [-]
    std::optional<double> effectiveCoordinationAt10; ///< Z_eff at eps1 = 10 % [-]
    std::optional<double> voidCountRatioAt10;        ///< N_v/N_vi at eps1 = 10 % [-]
    std::optional<double> fabricAt10;                ///< H11 - H22 at eps1 = 10 % [-]
    /// max |sigma22 - p0| / p0 during a drained test (empty for other kinds, whose sigma22
    /// follows their path) [-]
    std::optional<double> maxLateralStressError;
    std::optional<double> meanUnbalancedForce; ///< mean I_uf over the shear records [%]
    /// Work dissipated by damping during shear as a fraction of the boundary work, the latter
    /// taken from the energy balance: W_b = dE_kin + dE_elastic + dW_friction + dW_damping [-].
    std::optional<double> dampingWorkFraction;
    std::optional<double> peakDeviator;             ///< largest q during the test [Pa]
    std::optional<double> meanStressAtPeakDeviator; ///< p′ there [Pa]
    /// |q|/p at the test's end when the end is steady (critical_state.h, default criterion): the
    /// test's estimate of M (the same in compression and extension in 2D); empty when it is not
    /// steady [-]
    std::optional<double> criticalStressRatio;
    /// A cyclic test's completed cycles (reversals of eps1 over its records, halved): with a
    /// stop on p', the cycles to that criterion; empty for other kinds [-]
    std::optional<double> cyclesCompleted;
    std::optional<double> lowestPressureRatio; ///< min p′/p0 over the test (p0 its first) [-]
};

/// True for a table whose test rows are a cyclic test's (its eps1 goes back and forth: no curve
/// against eps1 on a common grid, no steady end).
bool isCyclicTable(const SeriesTable& t);
/// True for a table of stress probes (a start, a zero probe, one record per probe).
bool isProbesTable(const SeriesTable& t);
/// Neither cyclic nor probes: a test whose records follow eps1 one way.
bool isMonotonicTable(const SeriesTable& t);

/// The metrics of one test recorded at confining pressure `confiningPressure` [Pa]. Values the
/// test does not reach (it was sheared less far, or has no shear rows) are left empty.
ShearMetrics shearMetrics(const SeriesTable& test, double confiningPressure);

/// The rows of the test (the drained shear or another loading path): by each row's stage kind
/// (the runner and the run file record it); a table without them (read from CSV) by the stage
/// name, "<kind> <pressure>" ("shear 15 kPa", "constant_volume 15 kPa").
std::vector<std::size_t> shearRows(const SeriesTable& test);

/// A column of the shear rows as a curve against eps1 (e.g. "q_over_p", "epsv").
Curve shearCurve(const SeriesTable& test, const std::string& column);

/// One metric with its name and unit, as written in CSV headers ("name [unit]").
struct NamedMetric {
    std::string name; ///< e.g. "peak_q_over_p"
    std::string unit; ///< e.g. "-", "deg", "%"
    std::optional<double> value;
};

/// Every metric of `m` with its column name and unit, in a fixed order.
std::vector<NamedMetric> namedMetrics(const ShearMetrics& m);

} // namespace grainlab
