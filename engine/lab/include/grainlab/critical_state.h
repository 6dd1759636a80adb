#pragma once
// The critical state from finished tests: whether a test's end is steady (q and the volume no
// longer changing with eps1), the critical stress ratio M = q/p over the steady tests, and the
// critical state line e = e_Gamma - lambda ln p' in the e - ln p' plane. Pure functions of
// recorded series, used by the CLI, the report, the window and studies on their own threads; the
// least squares are the report's fitLine() (report_data.h).

#include <cstddef>
#include <string>
#include <vector>

namespace grainlab {

/// The steady-state criterion: least-squares slopes over the last `window` of axial strain.
/// Defaults: a window of 0.05 axial strain averages the stick-slip fluctuations of a few hundred
/// grains (their q oscillates over strain increments of order 1e-3); |dq/deps1| / p below 0.5
/// means q drifts by under 2.5 % of p across the window, a small fraction of the initial
/// modulus (hundreds of p); |deps_v/deps1| below 0.05 is an order below the dilatancy of a dense
/// sample near its peak (0.3 to 0.5).
struct SteadyStateCriterion {
    double window = 0.05;         ///< width of the last window in eps1 [-]
    double maxStressSlope = 0.5;  ///< bound on |dq/deps1| / mean p over the window [-]
    double maxVolumeSlope = 0.05; ///< bound on |deps_v/deps1| over the window [-]
};

struct SteadyStateResult {
    bool steady = false;
    double stressSlope = 0;  ///< dq/deps1 / mean p over the window [-]
    double volumeSlope = 0;  ///< deps_v/deps1 over the window [-]
    std::size_t samples = 0; ///< records in the window
    std::string reason;      ///< why not steady ("" when steady)
};

/// Applies `criterion` to series of equal length, eps1 monotonic (either sign: extension
/// works), compression positive. Not steady when the series spans less than the window or
/// the window holds fewer than 3 records.
SteadyStateResult steadyState(const std::vector<double>& eps1, const std::vector<double>& q,
                              const std::vector<double>& p, const std::vector<double>& epsV,
                              const SteadyStateCriterion& criterion = {});

// M with its scatter is scatterOf() (statistics.h) of the end q/p of the steady tests.

/// e = eGamma - lambda ln(p / 1 Pa), fitted by least squares in (ln p, e).
struct CriticalStateLine {
    double eGamma = 0;   ///< e at p = 1 Pa [-]
    double lambda = 0;   ///< slope in the e - ln p plane [-]
    double rSquared = 0; ///< 1 - SS_res / SS_tot (1 when every point lies on the line) [-]
    std::size_t points = 0;
    double voidRatioAt(double p) const;
    std::string equation() const; ///< "e = 0.812 - 0.0213 ln(p'/1 Pa)"
};

/// Fits the line through the end states (p' [Pa], e) of the steady tests. Refuses fewer than two
/// points, a p' <= 0 and all p' equal (std::invalid_argument).
CriticalStateLine fitCriticalStateLine(const std::vector<double>& p, const std::vector<double>& e);

} // namespace grainlab
