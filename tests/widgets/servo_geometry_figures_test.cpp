// The servo and geometry maps' figures look at what was drawn: each run's response in the cell
// of its gain and interval in that response's colour, the reader's gain bound as a black line
// at its gain, and the overlap guard as a black line at its overlap.
#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "grainlab/ui/geometry_figures.h"
#include "grainlab/ui/servo_figures.h"

namespace grainlab::ui {
namespace {

ServoCellResult cellOf(int interval, std::vector<ServoResponse> responses) {
    ServoCellResult r;
    r.cell = {"c", 15e3, 0.6, interval};
    const double gains[] = {0.5, 2.0, 4.0};
    for (std::size_t k = 0; k < responses.size(); ++k) {
        ServoRun run;
        run.gain = gains[k];
        run.response = responses[k];
        run.stats.maxError = 0.001 * double(k + 1);
        r.runs.push_back(run);
    }
    r.limit = {true, 1.9, 1.95, 1.9};
    return r;
}

QImage render(const std::function<void(QPainter&, const QRectF&)>& paint, QSize size) {
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    paint(painter, QRectF(QPointF(0, 0), size));
    return image;
}

int distance(QColor a, QColor b) {
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) +
           std::abs(a.blue() - b.blue());
}

TEST(ServoFigures, ResponseMapPutsEachRunInItsCell) {
    ServoMapSpec spec;
    spec.pressures = {15e3};
    spec.aspectRatios = {0.6};
    spec.intervals = {1, 10};
    spec.gains = {0.5, 2.0, 4.0};
    const std::vector<ServoCellResult> results = {
        cellOf(1, {ServoResponse::Steady, ServoResponse::Oscillating, ServoResponse::Diverging}),
        cellOf(10, {ServoResponse::Lagging, ServoResponse::Steady, ServoResponse::Diverging})};
    const HeatMapPainter map = servoResponseMap(spec, results, 15e3, 0.6);
    ASSERT_EQ(map.values.size(), 6u);
    // Row 0 is interval 1, row 1 interval 10; columns are the gains.
    EXPECT_EQ(map.values[0], 0.0);
    EXPECT_EQ(map.values[1], 2.0);
    EXPECT_EQ(map.values[2], 3.0);
    EXPECT_EQ(map.values[3], 1.0);
    EXPECT_EQ(map.values[4], 0.0);
    EXPECT_EQ(map.notes[2], "0.3 %");
    const QSize size(900, 600);
    const QRectF rect(QPointF(0, 0), size);
    const QImage image = render([&](QPainter& p, const QRectF& r) { map.paint(p, r); }, size);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            const QRectF cell = map.cellRect(x, y, rect);
            // Near a corner, away from the written value.
            const QPoint at = (cell.topLeft() + QPointF(6, 6)).toPoint();
            const QColor expected = map.colourOf(*map.values[std::size_t(y * 3 + x)]);
            EXPECT_LT(distance(image.pixelColor(at), expected), 30) << x << " " << y;
        }
    }
    // A pressure with no result: grey cells, no values.
    const HeatMapPainter empty = servoResponseMap(spec, results, 100e3, 0.6);
    for (const auto& v : empty.values) {
        EXPECT_FALSE(v.has_value());
    }
}

TEST(ServoFigures, StableGainPlotDrawsTheReadersBound) {
    const std::vector<ServoCellResult> results = {cellOf(1, {ServoResponse::Steady}),
                                                  cellOf(10, {ServoResponse::Steady})};
    const PlotPainter plot = servoStableGainPlot(results, 1.0);
    ASSERT_EQ(plot.curves.size(), 2u); // one pressure and shape, and the bound
    EXPECT_EQ(plot.curves.back().y, (std::vector<double>{1.0, 1.0}));
    const QSize size(900, 600);
    const QRectF rect(QPointF(0, 0), size);
    const QImage image = render([&](QPainter& p, const QRectF& r) { plot.paint(p, r); }, size);
    const QPoint on = plot.toPixel(3.0, 1.0, rect).toPoint();
    EXPECT_LT(image.pixelColor(on).lightness(), 60) << image.pixelColor(on).name().toStdString();
    const QPoint point = plot.toPixel(1.0, 0.5 * (1.9 + 1.95), rect).toPoint();
    EXPECT_LT(distance(image.pixelColor(point), plot.points[0].colour), 60);
}

TEST(GeometryFigures, DeparturePlotDrawsTheGuardAtItsOverlap) {
    GeometryMapSpec spec;
    spec.aspectRatios = {0.6};
    spec.sizeRatios = {1.0};
    spec.overlaps = {0.01, 0.1, 0.5};
    std::vector<GeometryLevel> levels;
    for (double o : spec.overlaps) {
        GeometryLevel l;
        l.aspectRatio = 0.6;
        l.sizeRatio = 1.0;
        l.overlap = o;
        l.pairs = 10;
        l.kernels[0].maxDeparture = 0.0; // drawn at the floor
        l.kernels[2].maxDeparture = o > 0.2 ? 0.1 : 1e-16;
        levels.push_back(l);
    }
    const PlotPainter plot = geometryDeparturePlot(spec, levels, 0.1);
    EXPECT_EQ(plot.curves[0].y.front(), kGeometryDepartureFloor);
    const QSize size(900, 600);
    const QRectF rect(QPointF(0, 0), size);
    const QImage image = render([&](QPainter& p, const QRectF& r) { plot.paint(p, r); }, size);
    const QPoint guard = plot.toPixel(0.1, 3e-12, rect).toPoint();
    EXPECT_LT(image.pixelColor(guard).lightness(), 60)
        << image.pixelColor(guard).name().toStdString();
    const QPoint away = plot.toPixel(0.03, 3e-12, rect).toPoint();
    EXPECT_EQ(image.pixelColor(away), QColor(Qt::white));
}

} // namespace
} // namespace grainlab::ui
