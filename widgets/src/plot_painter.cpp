// See plot_painter.h.
#include "grainlab/ui/plot_painter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

namespace grainlab::ui {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double axisValue(double v, bool logarithmic) {
    return logarithmic ? std::log10(v) : v;
}

/// "Nice" linear ticks over [lo, hi]: 1, 2 or 5 times a power of ten apart.
std::vector<double> linearTicks(double lo, double hi) {
    std::vector<double> ticks;
    const double span = hi - lo;
    if (!(span > 0)) {
        return ticks;
    }
    const double raw = span / 5;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    double step = power;
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * power >= raw) {
            step = m * power;
            break;
        }
    }
    for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
        ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    }
    return ticks;
}

QString tickLabel(double v) {
    return QString::number(v, 'g', 4);
}

} // namespace

PlotCurve plotLine(QPointF from, QPointF to, const QString& label, QColor colour, double width) {
    return {.x = {from.x(), to.x()},
            .y = {from.y(), to.y()},
            .band = {},
            .label = label,
            .colour = colour,
            .width = width};
}

PlotPainter::Range PlotPainter::range(bool x) const {
    const PlotAxis& axis = x ? xAxis : yAxis;
    double lo = kInf, hi = -kInf;
    const auto take = [&](double v) {
        if (std::isfinite(v) && (!axis.logarithmic || v > 0)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    };
    for (const PlotPoint& p : points) {
        const double v = x ? p.x : p.y, e = x ? p.xError : p.yError;
        take(v);
        take(v - e);
        take(v + e);
    }
    for (const PlotCurve& c : curves) {
        const auto& values = x ? c.x : c.y;
        for (std::size_t k = 0; k < values.size(); ++k) {
            const double b = !x && k < c.band.size() ? c.band[k] : 0.0;
            take(values[k] - b);
            take(values[k] + b);
        }
    }
    if (!x) {
        for (const PlotBand& b : bands) {
            take(b.low);
            take(b.high);
        }
    }
    if (!(lo <= hi)) {
        lo = axis.logarithmic ? 1 : 0;
        hi = axis.logarithmic ? 10 : 1;
    }
    Range r{axisValue(lo, axis.logarithmic), axisValue(hi, axis.logarithmic)};
    const double span = r.hi - r.lo;
    const double margin =
        span > 0 ? 0.06 * span : (axis.logarithmic ? 0.5 : std::abs(r.lo) * 0.1 + 1e-12);
    r.lo -= margin;
    r.hi += margin;
    if (axis.min) {
        r.lo = axisValue(*axis.min, axis.logarithmic);
    }
    if (axis.max) {
        r.hi = axisValue(*axis.max, axis.logarithmic);
    }
    return r;
}

QRectF PlotPainter::plotArea(const QRectF& rect) const {
    const double left = 78, right = 24, top = title.isEmpty() ? 18 : 40, bottom = 56;
    return QRectF(rect.left() + left, rect.top() + top, std::max(10.0, rect.width() - left - right),
                  std::max(10.0, rect.height() - top - bottom));
}

QPointF PlotPainter::toPixel(double x, double y, const QRectF& rect) const {
    const QRectF area = plotArea(rect);
    const Range rx = range(true), ry = range(false);
    const double u = (axisValue(x, xAxis.logarithmic) - rx.lo) / (rx.hi - rx.lo);
    const double v = (axisValue(y, yAxis.logarithmic) - ry.lo) / (ry.hi - ry.lo);
    return {area.left() + u * area.width(), area.bottom() - v * area.height()};
}

int PlotPainter::pointAt(QPointF pixel, const QRectF& rect, double radius) const {
    int best = -1;
    double bestDistance = radius;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const QPointF p = toPixel(points[k].x, points[k].y, rect);
        const double d = std::hypot(p.x() - pixel.x(), p.y() - pixel.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = int(k);
        }
    }
    return best;
}

void PlotPainter::paint(QPainter& painter, const QRectF& rect) const {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.fillRect(rect, Qt::white);
    const QRectF area = plotArea(rect);
    const Range rx = range(true), ry = range(false);
    QFont font = painter.font();
    font.setPointSizeF(9);
    painter.setFont(font);
    const QFontMetricsF metrics(font);

    // Grid and ticks.
    const auto ticksOf = [](const Range& r, bool logarithmic) {
        if (!logarithmic) {
            return linearTicks(r.lo, r.hi);
        }
        std::vector<double> out;
        for (double e = std::ceil(r.lo); e <= r.hi + 1e-9; e += 1) {
            out.push_back(e);
        }
        if (out.size() < 2) { // less than a decade: linear ticks on the log axis
            out.clear();
            for (double t : linearTicks(std::pow(10, r.lo), std::pow(10, r.hi))) {
                if (t > 0) {
                    out.push_back(std::log10(t));
                }
            }
        }
        return out;
    };
    painter.setPen(QPen(QColor(225, 225, 225), 1));
    const auto xTicks = ticksOf(rx, xAxis.logarithmic), yTicks = ticksOf(ry, yAxis.logarithmic);
    for (double t : xTicks) {
        const double px = area.left() + (t - rx.lo) / (rx.hi - rx.lo) * area.width();
        painter.drawLine(QPointF(px, area.top()), QPointF(px, area.bottom()));
    }
    for (double t : yTicks) {
        const double py = area.bottom() - (t - ry.lo) / (ry.hi - ry.lo) * area.height();
        painter.drawLine(QPointF(area.left(), py), QPointF(area.right(), py));
    }

    painter.setClipRect(area);
    paintData(painter, rect, metrics);
    painter.setClipping(false);

    // Frame, tick labels, titles, legend.
    painter.setPen(QPen(QColor(90, 90, 90), 1));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(area);
    painter.setPen(QColor(40, 40, 40));
    for (double t : xTicks) {
        const double px = area.left() + (t - rx.lo) / (rx.hi - rx.lo) * area.width();
        const QString s = tickLabel(xAxis.logarithmic ? std::pow(10, t) : t);
        painter.drawText(QPointF(px - metrics.horizontalAdvance(s) / 2, area.bottom() + 16), s);
    }
    for (double t : yTicks) {
        const double py = area.bottom() - (t - ry.lo) / (ry.hi - ry.lo) * area.height();
        const QString s = tickLabel(yAxis.logarithmic ? std::pow(10, t) : t);
        painter.drawText(QPointF(area.left() - 6 - metrics.horizontalAdvance(s), py + 4), s);
    }
    painter.drawText(QRectF(area.left(), area.bottom() + 24, area.width(), 24), Qt::AlignCenter,
                     xAxis.title);
    painter.save();
    painter.translate(rect.left() + 14, area.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-area.height() / 2, -10, area.height(), 20), Qt::AlignCenter,
                     yAxis.title);
    painter.restore();
    if (!title.isEmpty()) {
        QFont bold = font;
        bold.setBold(true);
        bold.setPointSizeF(10.5);
        painter.setFont(bold);
        painter.drawText(QRectF(rect.left(), rect.top() + 8, rect.width(), 24), Qt::AlignCenter,
                         title);
        painter.setFont(font);
    }
    paintLegend(painter, area, metrics);
    painter.restore();
}

void PlotPainter::paintData(QPainter& painter, const QRectF& rect,
                            const QFontMetricsF& metrics) const {
    const QRectF area = plotArea(rect);
    const Range rx = range(true), ry = range(false);
    // Horizontal bands.
    const auto yPixel = [&](double y) {
        const double v = yAxis.logarithmic ? (y > 0 ? std::log10(y) : ry.lo) : y;
        return area.bottom() - (v - ry.lo) / (ry.hi - ry.lo) * area.height();
    };
    for (const PlotBand& b : bands) {
        painter.fillRect(
            QRectF(QPointF(area.left(), yPixel(b.high)), QPointF(area.right(), yPixel(b.low))),
            b.colour);
    }
    // Curves with their bands.
    for (const PlotCurve& c : curves) {
        const std::size_t n = std::min(c.x.size(), c.y.size());
        if (c.band.size() >= n && n > 1) {
            QPainterPath band;
            for (std::size_t k = 0; k < n; ++k) {
                const QPointF p = toPixel(c.x[k], c.y[k] + c.band[k], rect);
                k == 0 ? band.moveTo(p) : band.lineTo(p);
            }
            for (std::size_t k = n; k-- > 0;) {
                band.lineTo(toPixel(c.x[k], c.y[k] - c.band[k], rect));
            }
            band.closeSubpath();
            QColor fill = c.colour;
            fill.setAlpha(60);
            painter.fillPath(band, fill);
        }
        QPainterPath line;
        for (std::size_t k = 0; k < n; ++k) {
            const QPointF p = toPixel(c.x[k], c.y[k], rect);
            k == 0 ? line.moveTo(p) : line.lineTo(p);
        }
        painter.setPen(QPen(c.colour, c.width));
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(line);
    }
    // Points with error bars (on a logarithmic axis a bar that reaches zero ends at the axis).
    const auto lowEnd = [](double v, double e, bool logarithmic, double axisLow) {
        return logarithmic && v - e <= 0 ? std::pow(10.0, axisLow) : v - e;
    };
    std::vector<QRectF> labels;
    for (const PlotPoint& p : points) {
        painter.setPen(QPen(p.colour.darker(130), 1.2));
        if (p.yError > 0) {
            const QPointF a = toPixel(p.x, lowEnd(p.y, p.yError, yAxis.logarithmic, ry.lo), rect);
            const QPointF b = toPixel(p.x, p.y + p.yError, rect);
            painter.drawLine(a, b);
            painter.drawLine(a + QPointF(-4, 0), a + QPointF(4, 0));
            painter.drawLine(b + QPointF(-4, 0), b + QPointF(4, 0));
        }
        if (p.xError > 0) {
            const QPointF a = toPixel(lowEnd(p.x, p.xError, xAxis.logarithmic, rx.lo), p.y, rect);
            const QPointF b = toPixel(p.x + p.xError, p.y, rect);
            painter.drawLine(a, b);
            painter.drawLine(a + QPointF(0, -4), a + QPointF(0, 4));
            painter.drawLine(b + QPointF(0, -4), b + QPointF(0, 4));
        }
        const QPointF c = toPixel(p.x, p.y, rect);
        const double r = p.highlighted ? 6.5 : 4.5;
        painter.setBrush(p.colour);
        painter.setPen(QPen(Qt::white, 1));
        painter.drawEllipse(c, r, r);
        if (p.highlighted) {
            painter.setBrush(Qt::NoBrush);
            painter.setPen(QPen(p.colour.darker(150), 1.5));
            painter.drawEllipse(c, r + 3, r + 3);
        }
        if (!p.label.isEmpty()) {
            // Labels of points that nearly coincide are stacked, not drawn over each other.
            QRectF box(c + QPointF(r + 4, -r - 2 - metrics.ascent()),
                       QSizeF(metrics.horizontalAdvance(p.label), metrics.height()));
            if (box.right() > plotArea(rect).right()) {
                box.moveRight(c.x() - r - 4); // a point at the right edge: its label on the left
            }
            for (int tries = 0; tries < 8; ++tries) {
                const bool clash = std::any_of(labels.begin(), labels.end(),
                                               [&](const QRectF& l) { return l.intersects(box); });
                if (!clash) {
                    break;
                }
                box.translate(0, metrics.height());
            }
            labels.push_back(box);
            painter.setPen(QColor(40, 40, 40));
            painter.drawText(QPointF(box.left(), box.top() + metrics.ascent()), p.label);
        }
    }
}

void PlotPainter::paintLegend(QPainter& painter, const QRectF& area,
                              const QFontMetricsF& metrics) const {
    double legendY = area.top() + 14;
    const auto legend = [&](const QColor& colour, const QString& text, bool band) {
        if (text.isEmpty()) {
            return;
        }
        const double w = metrics.horizontalAdvance(text);
        const QPointF at(area.right() - w - 10, legendY);
        if (band) {
            painter.fillRect(QRectF(at + QPointF(-22, -8), QSizeF(16, 10)), colour);
        } else {
            painter.setPen(QPen(colour, 2));
            painter.drawLine(at + QPointF(-22, -4), at + QPointF(-6, -4));
        }
        painter.setPen(QColor(40, 40, 40));
        painter.drawText(at, text);
        legendY += 15;
    };
    for (const PlotBand& b : bands) {
        legend(b.colour, b.label, true);
    }
    for (const PlotCurve& c : curves) {
        legend(c.colour, c.label, false);
    }
}

} // namespace grainlab::ui
