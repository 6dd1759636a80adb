#pragma once
// Points where the scene's overlays have a known colour, for the QPainter and OpenGL tests:
// void-cell centroids well inside their polygon (the cell's fill blended over what is below)
// and midpoints of strong force-chain segments that no other segment comes near (the chain's
// opaque colour).

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <QImage>
#include <QPoint>

#include "grainlab/ui/scene_renderer.h"

namespace grainlab::testing {

/// Distance from p to the segment ab.
inline double segmentDistance(QPointF p, QPointF a, QPointF b) {
    const QPointF ab = b - a, ap = p - a;
    const double length2 = QPointF::dotProduct(ab, ab);
    const double t =
        length2 > 0.0 ? std::clamp(QPointF::dotProduct(ap, ab) / length2, 0.0, 1.0) : 0.0;
    const QPointF d = ap - t * ab;
    return std::hypot(d.x(), d.y());
}

struct VoidCellPoint {
    int cell;
    QPoint pixel;
};

/// For each void cell whose area centroid (of the polygon as drawn) lies inside it, at least
/// `margin` pixels from its outline and inside the viewport: the pixel there.
inline std::vector<VoidCellPoint> voidCellCentroids(const ui::SceneRenderer& r, QSize viewport,
                                                    double margin = 3.0) {
    std::vector<VoidCellPoint> out;
    const int cells = static_cast<int>(r.snapshot()->voidCells.size());
    for (int v = 0; v < cells; ++v) {
        QPolygonF screen;
        for (const QPointF& w : r.voidCellPolygon(v)) {
            screen << r.view().toScreen(w.x(), w.y());
        }
        double area = 0.0, cx = 0.0, cy = 0.0;
        for (qsizetype k = 0; k < screen.size(); ++k) {
            const QPointF a = screen[k], b = screen[(k + 1) % screen.size()];
            const double cross = a.x() * b.y() - b.x() * a.y();
            area += cross;
            cx += (a.x() + b.x()) * cross;
            cy += (a.y() + b.y()) * cross;
        }
        if (std::fabs(area) < 1e-9) {
            continue;
        }
        const QPoint pixel(int(std::floor(cx / (3.0 * area))), int(std::floor(cy / (3.0 * area))));
        const QPointF centre(pixel.x() + 0.5, pixel.y() + 0.5);
        double nearest = std::numeric_limits<double>::max();
        for (qsizetype k = 0; k < screen.size(); ++k) {
            nearest = std::min(nearest,
                               segmentDistance(centre, screen[k], screen[(k + 1) % screen.size()]));
        }
        if (nearest >= margin && screen.containsPoint(centre, Qt::OddEvenFill) &&
            QRect(QPoint(0, 0), viewport).contains(pixel)) {
            out.push_back({v, pixel});
        }
    }
    return out;
}

/// `fill` (with its alpha) over `below`, as a source-over blend.
inline QColor blended(const QColor& fill, QRgb below) {
    const double a = fill.alphaF();
    return QColor::fromRgbF(float(fill.redF() * a + qRed(below) / 255.0 * (1.0 - a)),
                            float(fill.greenF() * a + qGreen(below) / 255.0 * (1.0 - a)),
                            float(fill.blueF() * a + qBlue(below) / 255.0 * (1.0 - a)));
}

struct ChainPoint {
    double force; ///< [N]
    QPoint pixel;
};

/// Midpoints of the visible strong force-chain segments at least 3 pixels wide whose pixel no
/// other visible segment comes within its half width (plus 1.5 pixels) of.
inline std::vector<ChainPoint> strongChainMidpoints(const ui::SceneRenderer& r, QSize viewport) {
    std::vector<ChainPoint> out;
    const auto segments = r.forceChainSegments(viewport);
    const Snapshot& s = *r.snapshot();
    for (const ContactRecord& c : s.network.contacts) {
        const auto f = c.force();
        const double force = std::hypot(f[0], f[1]);
        if (force <= r.strongForceThreshold() || r.forceChainWidth(force) < 3.0) {
            continue;
        }
        const double a1 = s.x1[c.first], a2 = s.x2[c.first];
        const QPointF a = r.view().toScreen(a1, a2);
        const QPointF b = r.view().toScreen(a1 + c.branch1, a2 + c.branch2);
        const QPointF middle = 0.5 * (a + b);
        const QPoint pixel(int(std::floor(middle.x())), int(std::floor(middle.y())));
        const QPointF centre(pixel.x() + 0.5, pixel.y() + 0.5);
        if (!QRect(QPoint(0, 0), viewport).contains(pixel)) {
            continue;
        }
        bool alone = true;
        for (const ui::ChainSegment& other : segments) {
            const QPointF oa = r.view().toScreen(other.a1, other.a2);
            const QPointF ob = r.view().toScreen(other.b1, other.b2);
            const bool same = (std::hypot(oa.x() - a.x(), oa.y() - a.y()) < 1e-6 &&
                               std::hypot(ob.x() - b.x(), ob.y() - b.y()) < 1e-6);
            if (!same && segmentDistance(centre, oa, ob) < 0.5 * other.width + 1.5) {
                alone = false;
                break;
            }
        }
        if (alone) {
            out.push_back({force, pixel});
        }
    }
    return out;
}

} // namespace grainlab::testing
