#pragma once
// The numbers behind the reference study's figure set (`grainlab report`): every figure's
// curves or points as means over the runs (seeds) with their ±1σ band, the pooled fit of Z_eff
// on N_v/N_vi, and the headline numbers per confining pressure with their scatter, set beside
// the values the published study states. Plain computation over recorded series (the shear rows
// of each test, as shear_metrics.h takes them): no Qt, no files, any thread. The report command
// writes these as CSV and draws them; the tests check them against hand computations.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/critical_state.h"
#include "grainlab/series.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/statistics.h"

namespace grainlab {

/// One run of the experiment: the series of its shear tests.
struct ReportRun {
    std::string name;               ///< e.g. the run folder's name
    std::vector<SeriesTable> tests; ///< one table per shear test
    std::vector<double> pressures;  ///< the confining pressure of each test [Pa]
};

/// One line (or set of points) of a figure: a test's mean over the runs, with the sample
/// standard deviation at each point.
struct ReportLine {
    std::string label;            ///< e.g. "15 kPa", "strong contacts"
    std::string test;             ///< e.g. "p015kPa" ("" for a line over every test)
    double pressure = 0;          ///< [Pa] (0 for a line over every test)
    std::vector<double> x, y, sd; ///< sd: of y over the runs (0 with one run)
    std::vector<double> xSd;      ///< of x over the runs, for lines of one series against another
    std::vector<int> runs;        ///< runs that reach each point
    bool points = false;          ///< drawn as markers with error bars, not as a line
    /// Further columns for the CSV only (e.g. the unsmoothed dilatancy index), one value per point.
    std::vector<std::pair<std::string, std::vector<double>>> extra;
};

/// y = slope x + intercept by least squares, with the coefficient of determination.
struct LinearFit {
    double slope = 0;
    double intercept = 0;
    double r2 = 0;         ///< 1 - SS_res / SS_tot
    std::size_t count = 0; ///< points fitted
};
/// The least-squares line through (x[k], y[k]); nothing for fewer than two distinct x.
std::optional<LinearFit> fitLine(const std::vector<double>& x, const std::vector<double>& y);

struct ReportFigure {
    std::string name; ///< the file stem, e.g. "01_q_over_p"
    std::string title;
    std::string xColumn; ///< the series column on x ("eps1", ...; "pressure" for figure 2)
    std::string xLabel;  ///< as a paper prints it, with the drawn unit, e.g. "ε1 [%]"
    std::string yColumn;
    std::string yLabel;
    std::vector<ReportLine> lines; ///< in the columns' stored units (the CSV's)
    std::optional<LinearFit> fit;  ///< drawn as a line with its equation (figure 6)
    std::string note;              ///< a sentence for the report (e.g. the smoothing window)
    double xScale = 1.0; ///< drawn value = stored value * scale (100: a strain in percent)
    double yScale = 1.0;
    std::string fitLabel; ///< the fit line's legend; "" for its equation (fitEquation)
    /// Draw each line's ±1σ band of y (the CSV has the sd either way). Off for paths where
    /// x moves too (q against p′): a band of y alone would misstate the scatter.
    bool bands = true;
};

/// How the figures sample the curves.
struct ReportOptions {
    int gridPoints = 201;           ///< points of the common eps1 axis
    double dilatancyWindow = 0.005; ///< the eps1 window of the smoothed dilatancy index [-]
};

/// The responses of a probes table: each probe's (d sigma11, d sigma22) minus the zero probe's
/// (rows: the start, the zero probe, the K probes); nothing when K is not even and >= 4. With
/// `complete` false, the responses of the probes recorded so far (a probe set still running),
/// nothing before the first.
std::optional<std::vector<std::array<double, 2>>> probeResponses(const SeriesTable& t,
                                                                 bool complete = true);

/// The upper peaks of a cyclic test's eps1 (indices): its reversals 0, 2, 4, ... (a cycle runs
/// from one to the next), and the last record when the test ended on one.
std::vector<std::size_t> upperPeaks(const std::vector<double>& eps1);

/// p'/p0 at the end of each cycle of a cyclic table's test rows (at the upper peaks after the
/// first), cycle 0 being the test's start (ratio 1); empty for a table without test rows.
struct PressurePerCycle {
    std::vector<double> cycle, ratio;
};
PressurePerCycle pressurePerCycle(const SeriesTable& t);

/// The end of one test of one run, as the critical state reads it.
struct TestEndState {
    std::string run;     ///< ReportRun::name
    std::string test;    ///< e.g. "p025kPa-constant-volume"
    std::string kind;    ///< its test rows' stage kind: "shear" (drained), "constant_volume", ...
    double pressure = 0; ///< the confining pressure of its sample [Pa]
    SteadyStateResult steady;
    double q = 0, p = 0, e = 0; ///< at its last record [Pa, Pa, -]
    double stressRatio = 0;     ///< |q|/p there (q < 0 in extension) [-]
};

/// The critical state of the runs' tests: every test's end, M = q/p at the end over the steady
/// ones (all of them, the drained and the constant-volume ones apart), and the critical state
/// line through the steady ends in the e - ln p' plane (when two of them differ in p').
struct CriticalStateSummary {
    SteadyStateCriterion criterion;
    std::vector<TestEndState> ends;
    Scatter m, mDrained, mConstantVolume;
    std::optional<CriticalStateLine> line;
    int steadyCount() const;
};
CriticalStateSummary criticalStateOf(const std::vector<ReportRun>& runs,
                                     const SteadyStateCriterion& criterion = {});

/// The figures of the reference study, in the report's order (1 to 8 of docs/report.md;
/// figure 5, the void-cell pictures, is drawn from checkpoints and is not part of this list).
std::vector<ReportFigure> reportFigures(const std::vector<ReportRun>& runs,
                                        const ReportOptions& options = {});

/// One headline number at one confining pressure, over the runs.
struct HeadlineValue {
    std::string test;
    double pressure = 0; ///< [Pa]
    Scatter value;       ///< mean ± sd over the runs that have it (count 0: none has)
};

/// A published value to compare with: an equality (0.126) or an upper bound (< 0.4).
struct PublishedValue {
    double value = 0;
    bool upperBound = false;
    std::string text; ///< as the study states it, e.g. "0.126", "< 0.4 %"
};

/// How a measured value compares with the published one.
struct Comparison {
    double difference = 0;      ///< measured mean - published value
    bool agrees = false;        ///< bound: mean below it; value: |difference| <= 2 sd
    bool beyondScatter = false; ///< |difference| > 2 sd of the runs (always with one run)
};
Comparison compare(const Scatter& measured, const PublishedValue& published);

struct HeadlineRow {
    std::string key;                   ///< e.g. "e_compacted"
    std::string label;                 ///< e.g. "e after compaction"
    std::string unit;                  ///< e.g. "-", "deg", "%"
    std::vector<HeadlineValue> values; ///< one per test, in pressure order
    std::optional<PublishedValue> published;
};

/// The table of headline numbers: e after compaction, peak q/p, phi and eps1 at the peak, eps_v
/// at 10 %, Z_eff - Z averaged over shear, N_v/N_vi at 10 %, the slope and intercept of the fit
/// of Z_eff on N_v/N_vi (per test, over its shear records), the mean I_uf during shear and the
/// largest lateral-stress error; with the published values where the study states one.
std::vector<HeadlineRow> headlineTable(const std::vector<ReportRun>& runs);

/// The pooled fit of Z_eff on N_v/N_vi of each run (every shear record of every test), as the
/// scatter over runs of its slope, intercept and R².
struct PooledFitScatter {
    Scatter slope, intercept, r2;
};
PooledFitScatter pooledFitOverRuns(const std::vector<ReportRun>& runs);

/// The published study's statements the report compares with.
inline constexpr double kPublishedVoidRatio = 0.126; ///< after compaction, every pressure
inline constexpr double kPublishedFitSlope = 3.45;   ///< Z_eff = 3.45 N_v/N_vi + 2.1
inline constexpr double kPublishedFitIntercept = 2.1;
inline constexpr double kPublishedUnbalancedForceMax = 0.4; ///< mean I_uf during shear < 0.4 %
/// The same statements as compared in the table, with their text.
PublishedValue publishedVoidRatio();
PublishedValue publishedFitSlope();
PublishedValue publishedFitIntercept();
PublishedValue publishedUnbalancedForce();

} // namespace grainlab
