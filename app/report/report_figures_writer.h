#pragma once
// The report's figures for the headless `grainlab report` and the window (GUI builds only):
// every ReportFigure drawn by the study figures' plot code (mean lines over their ±1σ band, points
// with error bars, the pooled fit with its equation), and figure 5, the void-cell network of the
// first run at eps1 = 0, at the peak of q/p and at eps1 = 10 % for the lowest and highest
// pressure, drawn by the scene renderer from the run file's checkpoints (cells coloured by
// valence). PNG, SVG and PDF each. Main thread; starts an offscreen Qt application when none runs.

#include <string>
#include <vector>

#include "grainlab/report_data.h"
#include "report/report_command.h"

namespace grainlab::ui {
class PlotPainter;
} // namespace grainlab::ui

namespace grainlab {

/// The plot of one report figure: its lines (curves, or points with error bars) and its fit,
/// drawn from the smallest to the largest x of its lines.
ui::PlotPainter reportPlot(const ReportFigure& f);

std::string writeReportFiguresHeadless(const std::string& folder,
                                       const std::vector<ReportFigure>& figures,
                                       const std::vector<ReportSource>& sources);

} // namespace grainlab
