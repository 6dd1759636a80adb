// The plot widget: it draws its plot (pixels at toPixel() of each point are the point's colour,
// and are not without the points), reports the point under the pointer and the point clicked,
// and nothing for a click beside every point.
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include "grainlab/ui/plot_view.h"

namespace grainlab::ui {
namespace {

PlotPainter threePoints() {
    PlotPainter plot;
    plot.title = QStringLiteral("three points");
    plot.xAxis = {QStringLiteral("x"), false, 0.0, 10.0};
    plot.yAxis = {QStringLiteral("y"), true, 1e-3, 1.0};
    plot.points = {{2, 0.01, 0, 0, QStringLiteral("a"), QColor(214, 39, 40), false},
                   {5, 0.1, 0, 0, QStringLiteral("b"), QColor(44, 160, 44), false},
                   {8, 0.5, 0, 0, QStringLiteral("c"), QColor(31, 119, 180), true}};
    return plot;
}

/// Shows `view` at 600 x 400 with the three points, and waits until it is on the screen.
void showThreePoints(PlotView& view) {
    view.resize(600, 400);
    view.setPlot(threePoints());
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
}

bool near(QColor a, QColor b, int tolerance = 8) {
    return std::abs(a.red() - b.red()) <= tolerance &&
           std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

TEST(PlotView, DrawsEachPointWhereToPixelSays) {
    PlotView view;
    ASSERT_NO_FATAL_FAILURE(showThreePoints(view));
    const QImage drawn = view.grab().toImage();
    PlotPainter empty = threePoints();
    empty.points.clear();
    view.setPlot(empty);
    const QImage without = view.grab().toImage();
    const PlotPainter plot = threePoints();
    for (const PlotPoint& p : plot.points) {
        const QPoint c = plot.toPixel(p.x, p.y, view.plotRect()).toPoint();
        EXPECT_TRUE(near(drawn.pixelColor(c), p.colour))
            << p.label.toStdString() << ": " << drawn.pixelColor(c).name().toStdString();
        EXPECT_FALSE(near(without.pixelColor(c), p.colour)) << p.label.toStdString();
    }
    // render() paints the same as the screen.
    view.setPlot(threePoints());
    const QImage rendered = view.render();
    for (const PlotPoint& p : plot.points) {
        const QPoint c = plot.toPixel(p.x, p.y, view.plotRect()).toPoint();
        EXPECT_TRUE(near(rendered.pixelColor(c), p.colour)) << p.label.toStdString();
    }
}

TEST(PlotView, ReportsTheHoveredAndTheClickedPoint) {
    PlotView view;
    ASSERT_NO_FATAL_FAILURE(showThreePoints(view));
    QSignalSpy hovered(&view, &PlotView::pointHovered);
    QSignalSpy clicked(&view, &PlotView::pointClicked);
    const PlotPainter& plot = view.plot();
    for (int k = 0; k < 3; ++k) {
        const QPoint c = plot.toPixel(plot.points[std::size_t(k)].x, plot.points[std::size_t(k)].y,
                                      view.plotRect())
                             .toPoint();
        QTest::mouseMove(&view, c + QPoint(2, 1));
        EXPECT_EQ(view.hoveredPoint(), k);
        ASSERT_FALSE(hovered.isEmpty());
        EXPECT_EQ(hovered.last().at(0).toInt(), k);
        QTest::mouseClick(&view, Qt::LeftButton, {}, c);
        ASSERT_EQ(clicked.size(), k + 1);
        EXPECT_EQ(clicked.last().at(0).toInt(), k);
    }
    // Beside every point: no point hovered, no click reported.
    const QPoint away = plot.toPixel(3.5, 0.3, view.plotRect()).toPoint();
    QTest::mouseMove(&view, away);
    EXPECT_EQ(view.hoveredPoint(), -1);
    EXPECT_EQ(hovered.last().at(0).toInt(), -1);
    QTest::mouseClick(&view, Qt::LeftButton, {}, away);
    EXPECT_EQ(clicked.size(), 3);
}

} // namespace
} // namespace grainlab::ui
