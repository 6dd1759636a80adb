// The report's figures as plots (app/report/report_figures_writer.h): a figure of points only,
// like the steady ends in the e - ln p' plane, draws its fitted line across its points (it once
// drew no line at all, since only curves set the fit's span).
#include <gtest/gtest.h>

#include "grainlab/ui/plot_painter.h"
#include "report/report_figures_writer.h"

namespace grainlab {
namespace {

TEST(ReportFigures, AFigureOfPointsDrawsItsFitAcrossThePoints) {
    ReportFigure f;
    f.name = "09_e_vs_ln_p";
    for (const auto& [x, y] : {std::pair{9.8, 0.244}, std::pair{12.1, 0.233}}) {
        ReportLine line;
        line.points = true;
        line.x = {x};
        line.y = {y};
        line.sd = {0.001};
        line.xSd = {0.0};
        line.runs = {3};
        f.lines.push_back(line);
    }
    f.fit = LinearFit{-0.005, 0.293, 0.9, 2};
    f.fitLabel = "e = 0.293 - 0.005 ln(p'/1 Pa)";
    const ui::PlotPainter plot = reportPlot(f);
    EXPECT_EQ(plot.points.size(), 2u);
    ASSERT_EQ(plot.curves.size(), 1u) << "the fitted line is missing";
    const ui::PlotCurve& fit = plot.curves.front();
    ASSERT_EQ(fit.x.size(), 2u);
    EXPECT_DOUBLE_EQ(fit.x[0], 9.8);
    EXPECT_DOUBLE_EQ(fit.x[1], 12.1);
    EXPECT_DOUBLE_EQ(fit.y[0], -0.005 * 9.8 + 0.293);
    EXPECT_DOUBLE_EQ(fit.y[1], -0.005 * 12.1 + 0.293);
    EXPECT_EQ(fit.label.toStdString(), f.fitLabel);
}

} // namespace
} // namespace grainlab
