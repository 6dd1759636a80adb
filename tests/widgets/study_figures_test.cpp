// The study's figures look at what was drawn: one point per setting with a result, where
// toPixel() puts it and in the colour of its verdict, the reference's noise band behind them,
// and a hit test that finds each point.
#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "../engine/series_builder.h"
#include "grainlab/ui/study_figures.h"

namespace grainlab::ui {
namespace {

StudySummary summaryOfThree() {
    StudySummary s;
    s.tests = {"p015kPa"};
    const double errors[] = {0.0, 0.004, 0.05};
    const double costs[] = {10, 4, 1};
    for (int k = 0; k < 3; ++k) {
        SettingSummary set;
        set.setting = k;
        set.runsDone = 2;
        set.cost = {costs[k], 0.5, 2};
        MetricSummary m;
        m.test = "p015kPa";
        m.metric = "peak_q_over_p";
        m.scatter = {0.5 + errors[k], 0.002, 2};
        m.error = errors[k];
        m.noise = 0.006;
        m.withinNoise = errors[k] <= 0.006;
        m.withinTolerance = errors[k] <= 0.01;
        set.metrics.push_back(m);
        set.valid = *m.withinTolerance;
        s.settings.push_back(set);
    }
    s.recommended = 1;
    return s;
}

StudyPlan planOfThree() {
    StudyPlan p;
    p.settings = {{"ref", {}, true}, {"a", {}, false}, {"b", {}, false}};
    return p;
}

TEST(StudyFigures, CurvesAreLabelledAsAPaperWouldAndDrawnInTheirUnits) {
    // εv = -0.5 ε1 over a shear to 10 %: drawn as εv [%] against ε1 [%], i.e. -5 at 10.
    StudyPlan plan = planOfThree();
    plan.runs = {{"ref-seed1", 0, 1, ""}};
    test::SeriesBuilder b("p015kPa");
    for (int k = 0; k <= 10; ++k) {
        auto& r = b.row("shear 15 kPa");
        b.at(r, "eps1") = 0.01 * k;
        b.at(r, "epsv") = -0.005 * k;
    }
    RunResult result;
    result.tests = {b.t};
    result.pressures = {15e3};
    const PlotPainter plot = curvesPlot(plan, {result}, "p015kPa", "epsv");
    EXPECT_EQ(plot.xAxis.title, QStringLiteral("ε1 [%]"));
    EXPECT_EQ(plot.yAxis.title, QStringLiteral("εv [%]"));
    ASSERT_EQ(plot.curves.size(), 1u);
    EXPECT_NEAR(plot.curves[0].x.back(), 10.0, 1e-12);
    EXPECT_NEAR(plot.curves[0].y.back(), -5.0, 1e-12);
    EXPECT_EQ(plot.curves[0].band.size(), plot.curves[0].y.size());
    EXPECT_EQ(curvesPlot(plan, {result}, "p015kPa", "q_over_p").yAxis.title, QStringLiteral("q/p"));
}

TEST(StudyFigures, ErrorAgainstCostDrawsOnePointPerSettingOverTheNoiseBand) {
    StudySpec spec;
    spec.tolerances["peak_q_over_p"] = {0.01, false};
    const PlotPainter plot =
        errorCostPlot(spec, planOfThree(), summaryOfThree(), "p015kPa", "peak_q_over_p");
    ASSERT_EQ(plot.points.size(), 3u);
    EXPECT_TRUE(plot.xAxis.logarithmic);
    EXPECT_TRUE(plot.yAxis.logarithmic);
    // The reference is drawn last (a cost-only knob's point would hide it otherwise).
    EXPECT_EQ(plot.points[0].label, "a");
    EXPECT_EQ(plot.points[1].label, "b");
    EXPECT_EQ(plot.points[2].label, "ref");
    EXPECT_TRUE(plot.points[0].highlighted); // the recommendation

    const QSize size(800, 600);
    QImage image(size, QImage::Format_ARGB32);
    {
        QPainter painter(&image);
        plot.paint(painter, QRectF(QPointF(0, 0), size));
    }
    const QRectF rect(QPointF(0, 0), size);
    for (std::size_t k = 0; k < plot.points.size(); ++k) {
        const PlotPoint& p = plot.points[k];
        const QPoint at = plot.toPixel(p.x, p.y, rect).toPoint();
        const QColor c = image.pixelColor(at);
        EXPECT_LT(std::abs(c.red() - p.colour.red()) + std::abs(c.green() - p.colour.green()) +
                      std::abs(c.blue() - p.colour.blue()),
                  30)
            << k << " " << c.name().toStdString();
        EXPECT_EQ(plot.pointAt(QPointF(at) + QPointF(2, 1), rect), int(k));
    }
    // Within tolerance green, outside red, the reference dark.
    EXPECT_GT(plot.points[0].colour.green(), plot.points[0].colour.red());
    EXPECT_GT(plot.points[1].colour.red(), plot.points[1].colour.green());
    EXPECT_LT(plot.points[2].colour.lightness(), 80);
    // The noise band: grey behind the plot below the noise level, white above it.
    const double x = plot.points[2].x;
    const QColor inBand = image.pixelColor(plot.toPixel(x * 0.8, 0.003, rect).toPoint());
    const QColor above = image.pixelColor(plot.toPixel(x * 0.8, 0.02, rect).toPoint());
    EXPECT_LT(inBand.red(), 245) << inBand.name().toStdString();
    EXPECT_EQ(above, QColor(Qt::white)) << above.name().toStdString();
}

} // namespace
} // namespace grainlab::ui
