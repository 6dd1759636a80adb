#pragma once
// The figures of a study, as plots (plot_painter.h) for the Study window and for the files
// `grainlab study` writes: error against cost for each deciding metric (log-log, one labelled
// point per setting with its seed scatter as error bars, the reference's noise band drawn), each
// metric against each knob, and the q/p and eps_v curves of every setting over the reference's
// ±1σ band. GUI thread, or any thread with a Qt application for fonts.

#include <string>
#include <vector>

#include <QSize>
#include <QStringList>

#include "grainlab/study_plan.h"
#include "grainlab/study_summary.h"
#include "grainlab/ui/plot_painter.h"

namespace grainlab::ui {

/// The summary of `metric` at `test` among `setting`'s, or null when it has none.
const MetricSummary* findMetricSummary(const SettingSummary& setting, const std::string& test,
                                       const std::string& metric);

/// |error| of `metric` at `test` against cost, one point per setting with results.
PlotPainter errorCostPlot(const StudySpec& spec, const StudyPlan& plan, const StudySummary& summary,
                          const std::string& test, const std::string& metric);

/// `metric` at `test` (mean ± sd over seeds) against the levels of `knob`, with the other knobs
/// at the reference; the reference's mean ± noise as a band.
PlotPainter metricKnobPlot(const StudySpec& spec, const StudyPlan& plan,
                           const StudySummary& summary, KnobKind knob, const std::string& test,
                           const std::string& metric);

/// The mean curve of `column` ("q_over_p" or "epsv") against eps1 at `test` of every setting,
/// over the reference's mean ± 1σ band.
PlotPainter curvesPlot(const StudyPlan& plan, const std::vector<RunResult>& results,
                       const std::string& test, const std::string& column);

/// Writes every figure of the study into `folder` (figures/ of the study folder) in each of
/// `formats`; returns the files written. Stops at the first failure, setting `error`.
QStringList writeStudyFigures(const QString& folder, const StudySpec& spec, const StudyPlan& plan,
                              const std::vector<RunResult>& results, const StudySummary& summary,
                              QString* error = nullptr,
                              const QStringList& formats = {"png", "svg", "pdf"},
                              QSize size = {1000, 700});

} // namespace grainlab::ui
