#pragma once
// What a study's runs say, setting by setting: each metric's mean and scatter over seeds, its
// error against the reference setting, whether that error is within the reference's seed noise
// (|error| <= 2 sigma of the reference seeds) and within the study's tolerance, the cost, and
// the recommendation: the cheapest setting within tolerance on every deciding metric at every
// confining pressure. Plain computation over the runs' recorded series and costs; used by
// `grainlab study`, `grainlab study collect`, the Study window and the tests, on any thread.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/series.h"
#include "grainlab/statistics.h"
#include "grainlab/study_plan.h"

namespace grainlab {

/// What one run cost, summed over every process that worked on it (a resumed run included).
struct RunCost {
    double wallSeconds = 0;      ///< [s]
    double cpuSeconds = 0;       ///< processor time, all threads [s]
    std::int64_t steps = 0;      ///< time steps computed
    std::int64_t grainSteps = 0; ///< sum over steps of the grains stepped
    int threads = 0;             ///< engine threads used
};

/// What the study needs of one finished run.
struct RunResult {
    int run = 0;                    ///< index into StudyPlan::runs
    std::vector<SeriesTable> tests; ///< the shear tests' series (the compaction series ignored)
    std::vector<double> pressures;  ///< the confining pressure of each test [Pa]
    RunCost cost;
};

/// The curve metrics, computed against the reference setting's mean curve.
inline constexpr const char* kCurveMetrics[] = {"rms_q_over_p", "rms_epsv"};

struct MetricSummary {
    std::string test;   ///< e.g. "p015kPa"
    std::string metric; ///< e.g. "peak_q_over_p", "rms_q_over_p"
    std::string unit;
    Scatter scatter;             ///< of the metric over this setting's seeds
    std::optional<double> error; ///< this setting's mean minus the reference's mean
    std::optional<double> noise; ///< 2 sigma of the reference seeds (the noise band half-width)
    bool withinNoise = false;
    /// When the study gives this metric a tolerance: |error| plus the seed scatter beyond the
    /// reference's (max(0, sd - sd_ref); 0 for the curve errors) within the tolerance.
    std::optional<bool> withinTolerance;
};

struct SettingSummary {
    int setting = 0;
    int runsDone = 0; ///< runs of this setting with results
    std::vector<MetricSummary> metrics;
    Scatter wallSeconds, cpuSeconds;
    Scatter cost;                  ///< the study's cost measure over seeds
    std::optional<double> speedUp; ///< reference cost / this cost (means)
    /// Within tolerance on every deciding metric at every test (false when any is missing).
    bool valid = false;
};

struct StudySummary {
    std::vector<SettingSummary> settings; ///< in plan order; [0] the reference
    std::optional<int> recommended;       ///< the cheapest valid setting
    std::vector<std::string> tests;       ///< the tests seen, in order
    /// Every run's metrics by "test.metric", in the order of the results given (study.csv).
    std::vector<std::map<std::string, std::optional<double>>> perRun;
};

/// The study's cost measure: "cpu_seconds" (default), "wall_seconds" or "grain_steps".
double costOf(const RunCost& cost, const std::string& measure);

/// Summarises the runs that have results (unfinished runs simply count less). The curve
/// metrics use `curveGrid` points evenly spaced over the eps1 range every run reached.
StudySummary summariseStudy(const StudySpec& spec, const StudyPlan& plan,
                            const std::vector<RunResult>& results,
                            const std::string& costMeasure = "cpu_seconds", int curveGrid = 101);

/// Every metric of one run by "test.metric", the curve metrics against the reference's mean
/// q/p and eps_v curves of each test on that test's eps1 grid (all three maps by test name);
/// the cells of study.csv.
std::map<std::string, std::optional<double>>
runMetrics(const RunResult& result, const std::map<std::string, Curve>& referenceQ,
           const std::map<std::string, Curve>& referenceV,
           const std::map<std::string, std::vector<double>>& grids);

} // namespace grainlab
