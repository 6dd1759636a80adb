// See scene_renderer.h: what frames the scene, the periodic cell below the grains and, on top,
// the contact-normal rose, the scale bar, the caption and the void cells' colour key.
#include "grainlab/ui/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <QFontMetrics>
#include <QPainter>

#include "grainlab/ui/colour_maps.h"

namespace grainlab::ui {
namespace {

constexpr double kPi = std::numbers::pi;

/// A screen direction for a world direction at angle `alpha` from x1 towards x2.
QPointF screenDirection(double alpha) {
    return {std::sin(alpha), -std::cos(alpha)};
}

} // namespace

void SceneRenderer::drawCell(QPainter& p) const {
    const CellMatrix& h = snapshot_->network.cell;
    const QPolygonF cell{view_.toScreen(0.0, 0.0), view_.toScreen(h[0], h[1]),
                         view_.toScreen(h[0] + h[2], h[1] + h[3]), view_.toScreen(h[2], h[3])};
    QPen pen(QColor(90, 90, 90), 1.0);
    pen.setCosmetic(true);
    p.setPen(pen);
    p.setBrush(options_.cellFill);
    p.drawPolygon(cell);
}

void SceneRenderer::drawRose(QPainter& p, QSize viewport) const {
    const double maxCount = *std::max_element(roseCounts_.begin(), roseCounts_.end());
    const double radius = 50.0;
    const QPointF centre(viewport.width() - radius - 14.0, radius + 14.0);
    p.setPen(QPen(QColor(120, 120, 120), 1.0));
    p.setBrush(QColor(255, 255, 255, 220));
    p.drawEllipse(centre, radius, radius);
    p.drawLine(centre + QPointF(0, radius), centre - QPointF(0, radius));
    p.drawText(centre + QPointF(4, -radius + 12), QStringLiteral("x1"));
    if (maxCount <= 0.0) {
        return;
    }
    p.setPen(QPen(QColor(20, 60, 120), 0.8));
    p.setBrush(QColor(60, 110, 190, 170));
    const int bins = static_cast<int>(roseCounts_.size()); // over 180 degrees
    const double width = kPi / bins;
    for (int k = 0; k < bins; ++k) {
        const double r = radius * roseCounts_[k] / maxCount;
        for (double offset : {0.0, kPi}) {
            const double a0 = k * width + offset, a1 = (k + 1) * width + offset;
            p.drawPolygon(QPolygonF{centre, centre + r * screenDirection(a0),
                                    centre + r * screenDirection(a1)});
        }
    }
}

void SceneRenderer::drawScaleBar(QPainter& p, QSize viewport) const {
    const double scale = view_.pixelsPerMetre();
    const double targetMillimetres = 120.0 / scale * 1e3;
    const double decade = std::pow(10.0, std::floor(std::log10(targetMillimetres)));
    double millimetres = decade;
    for (double factor : {2.0, 5.0, 10.0}) {
        if (decade * factor <= targetMillimetres) {
            millimetres = decade * factor;
        }
    }
    const double length = millimetres * 1e-3 * scale;
    const QPointF start(16.0, viewport.height() - 16.0);
    const QPointF end = start + QPointF(length, 0.0);
    p.setPen(QPen(Qt::black, 2.0));
    p.drawLine(start, end);
    p.drawLine(start, start - QPointF(0, 6));
    p.drawLine(end, end - QPointF(0, 6));
    p.drawText(QRectF(start.x(), start.y() - 24.0, std::max(length, 80.0), 16.0),
               Qt::AlignLeft | Qt::AlignBottom,
               QStringLiteral("%1 mm").arg(millimetres, 0, 'g', 3));
}

void SceneRenderer::drawCaption(QPainter& p) const {
    const Snapshot& s = *snapshot_;
    const QString text = QStringLiteral("%1   step %2   ε1 = %3 %")
                             .arg(QString::fromStdString(s.stage))
                             .arg(s.step)
                             .arg(100.0 * s.axialStrain, 0, 'f', 3);
    const QRectF bounds = p.fontMetrics().boundingRect(text);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 200));
    p.drawRect(QRectF(6.0, 4.0, bounds.width() + 12.0, bounds.height() + 6.0));
    p.setPen(Qt::black);
    p.drawText(QPointF(12.0, 7.0 + p.fontMetrics().ascent()), text);
}

void SceneRenderer::drawColourKey(QPainter& p, QSize viewport) const {
    // Swatches as the cells are seen over the white cell: the fills' own alpha over cellFill.
    struct Swatch {
        double valence, areaOverMean;
        QString label;
    };
    const bool area = options_.voidCells == VoidCellShading::Area;
    std::vector<Swatch> swatches;
    QString title;
    if (area) {
        title = QStringLiteral("void-cell area / mean area");
        for (int k = 0; k <= 8; ++k) {
            const double ratio = std::pow(10.0, -1.0 + k / 4.0);
            swatches.push_back(
                {0.0, ratio, k % 4 == 0 ? QString::number(ratio, 'g', 2) : QString()});
        }
    } else {
        title = QStringLiteral("void-cell valence");
        for (int v = 3; v <= 10; ++v) {
            swatches.push_back(
                {double(v), 1.0, v == 10 ? QStringLiteral("10+") : QString::number(v)});
        }
    }
    const QFontMetrics fm = p.fontMetrics();
    const double w = 22.0, h = 14.0, pad = 8.0;
    const double width = std::max(w * double(swatches.size()), double(fm.horizontalAdvance(title)));
    const double height = fm.height() + h + fm.height() + 4.0;
    const QRectF box(viewport.width() - width - 2.0 * pad - 10.0,
                     viewport.height() - height - 2.0 * pad - 10.0, width + 2.0 * pad,
                     height + 2.0 * pad);
    p.setPen(QPen(QColor(120, 120, 120), 1.0));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRect(box);
    p.setPen(Qt::black);
    p.drawText(QRectF(box.left() + pad, box.top() + pad, width, fm.height()),
               Qt::AlignLeft | Qt::AlignVCenter, title);
    const double top = box.top() + pad + fm.height() + 2.0;
    for (std::size_t k = 0; k < swatches.size(); ++k) {
        const QRectF cell(box.left() + pad + w * double(k), top, w, h);
        const QColor shade =
            sequentialColour(voidCellScalePosition(swatches[k].valence, swatches[k].areaOverMean));
        const double a = kVoidCellAlpha / 255.0;
        const QColor under = options_.cellFill;
        p.setPen(Qt::NoPen);
        p.setBrush(QColor::fromRgbF(float(a * shade.redF() + (1 - a) * under.redF()),
                                    float(a * shade.greenF() + (1 - a) * under.greenF()),
                                    float(a * shade.blueF() + (1 - a) * under.blueF())));
        p.drawRect(cell);
        if (!swatches[k].label.isEmpty()) {
            p.setPen(Qt::black);
            p.drawText(QRectF(cell.left() - w, cell.bottom() + 2.0, 3.0 * w, fm.height()),
                       Qt::AlignHCenter | Qt::AlignTop, swatches[k].label);
        }
    }
}

} // namespace grainlab::ui
