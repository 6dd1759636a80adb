// See heat_map_painter.h.
#include "grainlab/ui/heat_map_painter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QPainter>

#include "grainlab/ui/colour_maps.h"

namespace grainlab::ui {
namespace {
const QColor kMarkColour(200, 0, 0);
} // namespace

std::pair<double, double> HeatMapPainter::scale() const {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& v : values) {
        if (v && std::isfinite(*v)) {
            lo = std::min(lo, *v);
            hi = std::max(hi, *v);
        }
    }
    if (mark && std::isfinite(*mark)) {
        lo = std::min(lo, *mark);
        hi = std::max(hi, *mark);
    }
    if (min) {
        lo = *min;
    }
    if (max) {
        hi = *max;
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
        return {0.0, 1.0};
    }
    if (!(hi > lo)) {
        return {lo - 0.5, hi + 0.5};
    }
    return {lo, hi};
}

QColor HeatMapPainter::colourOf(double v) const {
    const auto [lo, hi] = scale();
    return sequentialColour((v - lo) / (hi - lo));
}

QRectF HeatMapPainter::gridArea(const QRectF& rect) const {
    // Room for the title (top), the row labels (left), the column labels and the x title
    // (bottom), and the colour bar (right).
    const double left = std::min(0.28 * rect.width(), 150.0);
    const double right = std::min(0.16 * rect.width(), 110.0);
    return rect.adjusted(left, 40, -right, -60);
}

QRectF HeatMapPainter::cellRect(int x, int y, const QRectF& rect) const {
    const QRectF g = gridArea(rect);
    const double nx = std::max<qsizetype>(1, xLabels.size());
    const double ny = std::max<qsizetype>(1, yLabels.size());
    const double w = g.width() / nx, h = g.height() / ny;
    return QRectF(g.left() + x * w, g.bottom() - (y + 1) * h, w, h);
}

void HeatMapPainter::paint(QPainter& painter, const QRectF& rect) const {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.fillRect(rect, Qt::white);
    QFont font = painter.font();
    font.setPointSizeF(9);
    painter.setFont(font);
    const QRectF g = gridArea(rect);
    const auto [lo, hi] = scale();

    QFont titleFont = font;
    titleFont.setPointSizeF(11);
    titleFont.setBold(true);
    painter.setFont(titleFont);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(rect.left(), rect.top() + 6, rect.width(), 28), Qt::AlignCenter, title);
    painter.setFont(font);

    for (int y = 0; y < yLabels.size(); ++y) {
        for (int x = 0; x < xLabels.size(); ++x) {
            const QRectF c = cellRect(x, y, rect);
            const std::size_t i = std::size_t(y) * std::size_t(xLabels.size()) + std::size_t(x);
            const std::optional<double> v = i < values.size() ? values[i] : std::nullopt;
            const QColor fill = v && std::isfinite(*v) ? colourOf(*v) : QColor(220, 220, 220);
            painter.fillRect(c, fill);
            painter.setPen(QPen(Qt::white, 1.5));
            painter.drawRect(c);
            // Dark text on the light end of the map, white on the dark end.
            painter.setPen(fill.lightnessF() > 0.55 ? Qt::black : Qt::white);
            const QString note = i < notes.size() ? notes[i] : QString();
            QString text = v && std::isfinite(*v) ? QString::number(*v, 'g', 3) : QString();
            if (!note.isEmpty()) {
                text += (text.isEmpty() ? "" : "\n") + note;
            } else if (text.isEmpty()) {
                text = "-";
            }
            painter.drawText(c, Qt::AlignCenter, text);
            if (mark && v && *v < *mark) {
                painter.setPen(QPen(kMarkColour, 3));
                painter.drawRect(c.adjusted(3, 3, -3, -3));
            }
        }
    }
    painter.setPen(Qt::black);
    for (int x = 0; x < xLabels.size(); ++x) {
        const QRectF c = cellRect(x, 0, rect);
        painter.drawText(QRectF(c.left(), g.bottom() + 4, c.width(), 20), Qt::AlignCenter,
                         xLabels[x]);
    }
    for (int y = 0; y < yLabels.size(); ++y) {
        const QRectF c = cellRect(0, y, rect);
        painter.drawText(QRectF(rect.left() + 4, c.top(), g.left() - 10, c.height()),
                         Qt::AlignRight | Qt::AlignVCenter, yLabels[y]);
    }
    painter.drawText(QRectF(g.left(), g.bottom() + 26, g.width(), 24), Qt::AlignCenter, xTitle);
    painter.save();
    painter.translate(rect.left() + 12, g.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-g.height() / 2, -10, g.height(), 20), Qt::AlignCenter, yTitle);
    painter.restore();

    // The colour bar.
    const QRectF bar(g.right() + 16, g.top(), 16, g.height());
    const int bands = 64;
    for (int b = 0; b < bands; ++b) {
        const double t = (b + 0.5) / bands;
        painter.fillRect(QRectF(bar.left(), bar.bottom() - (b + 1) * bar.height() / bands,
                                bar.width(), bar.height() / bands + 0.5),
                         sequentialColour(t));
    }
    painter.setPen(Qt::black);
    painter.drawRect(bar);
    const auto barY = [&](double v) { return bar.bottom() - (v - lo) / (hi - lo) * bar.height(); };
    const bool marked = mark && *mark >= lo && *mark <= hi;
    for (int k = 0; k <= 4; ++k) {
        const double t = k / 4.0;
        const double yPix = bar.bottom() - t * bar.height();
        if (marked && std::fabs(yPix - barY(*mark)) < 14) {
            continue; // the mark's label takes its place
        }
        painter.drawLine(QPointF(bar.right(), yPix), QPointF(bar.right() + 4, yPix));
        painter.drawText(QRectF(bar.right() + 6, yPix - 8, 60, 16),
                         Qt::AlignLeft | Qt::AlignVCenter,
                         QString::number(lo + t * (hi - lo), 'g', 3));
    }
    if (marked) {
        const double yPix = barY(*mark);
        painter.setPen(QPen(kMarkColour, 2.5));
        painter.drawLine(QPointF(bar.left() - 5, yPix), QPointF(bar.right() + 5, yPix));
        painter.drawText(QRectF(bar.right() + 6, yPix - 8, 70, 16),
                         Qt::AlignLeft | Qt::AlignVCenter,
                         QString("%1 %2").arg(markLabel, QString::number(*mark, 'g', 3)));
        painter.setPen(Qt::black);
    }
    painter.save();
    painter.translate(std::min(rect.right() - 8, bar.right() + 70), bar.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-bar.height() / 2, -10, bar.height(), 20), Qt::AlignCenter, valueTitle);
    painter.restore();
    painter.restore();
}

} // namespace grainlab::ui
