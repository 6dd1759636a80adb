#pragma once
// A small plot drawn with QPainter, for the figures that Qt Charts does not draw: points with
// error bars and labels on linear or logarithmic axes, curves, bands (a curve's ±1σ band, or a
// horizontal band such as a reference's noise band). The same painting serves a widget on
// screen and exportFigure() (PNG, SVG, PDF). A value type: build it, then paint() it, on the
// GUI thread or any thread that owns its painter.

#include <optional>
#include <string>
#include <vector>

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>

class QFontMetricsF;
class QPainter;

namespace grainlab::ui {

struct PlotPoint {
    double x = 0, y = 0;
    double xError = 0, yError = 0; ///< half-lengths of the error bars (0: none)
    QString label;
    QColor colour{31, 119, 180};
    bool highlighted = false; ///< drawn larger, with a ring (e.g. the recommendation)
};

struct PlotCurve {
    std::vector<double> x, y;
    std::vector<double> band; ///< ±band around y at each point (empty: no band)
    QString label;
    QColor colour{31, 119, 180};
    double width = 1.5;
};

/// A straight line from `from` to `to` in the plot's units (a tolerance, a guard, a bound).
PlotCurve plotLine(QPointF from, QPointF to, const QString& label, QColor colour,
                   double width = 1.5);

/// A horizontal band y in [low, high] across the whole plot.
struct PlotBand {
    double low = 0, high = 0;
    QString label;
    QColor colour{200, 200, 200, 110};
};

struct PlotAxis {
    QString title;
    bool logarithmic = false;
    std::optional<double> min, max; ///< unset: from the data (with a margin)
};

class PlotPainter {
public:
    QString title;
    PlotAxis xAxis, yAxis;
    std::vector<PlotBand> bands;
    std::vector<PlotCurve> curves;
    std::vector<PlotPoint> points;

    /// Draws the plot filling `rect`.
    void paint(QPainter& painter, const QRectF& rect) const;
    /// Where a data point lands in `rect` (as paint() draws it); for hit tests and tests.
    QPointF toPixel(double x, double y, const QRectF& rect) const;
    /// The index of the point drawn within `radius` pixels of `pixel`, or -1.
    int pointAt(QPointF pixel, const QRectF& rect, double radius = 6) const;

private:
    struct Range {
        double lo = 0, hi = 1;
    };
    Range range(bool xAxis) const;
    QRectF plotArea(const QRectF& rect) const;
    /// The bands, the curves with their bands, the points with their error bars and labels
    /// (clipped to the plot area by paint()).
    void paintData(QPainter& painter, const QRectF& rect, const QFontMetricsF& metrics) const;
    /// The legend of the bands and curves that have a label, at the plot area's top right.
    void paintLegend(QPainter& painter, const QRectF& area, const QFontMetricsF& metrics) const;
};

} // namespace grainlab::ui
