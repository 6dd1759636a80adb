// See scene_renderer.h: the grains, each as a polygon of its true four-arc outline.
//
// How they are painted on a raster device was chosen by measurement (Qt 6.4 raster engine, one
// frame of the grains alone, drawPolygon per grain; 800 grains 13 to 27 pixels in half width as
// in the window's default view, 1000 x 900 pixels):
//
//   antialiased fill and 1-pixel outline in one call, 64 vertices  9.5 ms
//   the same, 24 vertices                                           7.4 ms
//   aliased fills, then antialiased 1-pixel outlines, 24 vertices   4.1 ms
//   antialiased fills without outline, 24 vertices                  4.5 ms
//   aliased fills only, 24 vertices                                 1.4 ms
//
// Antialiased fills cost a lot per shape in Qt's antialiasing rasteriser; an aliased fill under
// an antialiased outline looks the same, the outline covering the fill's staircase. Gathering
// the grains of one colour into one QPainterPath was slower than a drawPolygon each (building
// the path costs more than the calls it saves), so the grains are sorted by colour only to set
// each pen and brush once. A 1-pixel pen goes through Qt's fast cosmetic line drawer whether or
// not it is cosmetic (on an untransformed raster device); it stays non-cosmetic here so that
// vector exports keep a 1-pixel line at their scale.
#include "grainlab/ui/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QPaintEngine>
#include <QPainter>
#include <QPainterPath>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/pixel_canvas.h"

namespace grainlab::ui {
namespace {

constexpr double kPi = std::numbers::pi;
/// Outline vertices per detail level. The vertices are evenly spaced in the direction of the
/// outward normal, so the chords of an arc of radius R stray R (1 - cos(pi / n)) from it.
constexpr int kOutlineVertices[] = {8, 12, 16, 24, 32, 48, 64, 96, 128};
constexpr int kMostVertices = 128;
/// [pixel] largest stray of the chords from the arcs; with the vertices pushed out by half of
/// it (outline()), the polygon stays within half of it of the true outline, on either side.
constexpr double kOutlineTolerance = 0.25;
constexpr double kOutlinedRadius = 6.0; ///< [pixel] wider grains (half width) get an outline
constexpr double kBandRows = 16.0;      ///< [pixel] the overview draws grains band by band
const QColor kSelection(255, 140, 0);

/// The coarsest detail level whose chords stay within kOutlineTolerance of an arc of radius
/// `radiusPixels`.
int outlineLevel(double radiusPixels) {
    const int levels = static_cast<int>(std::size(kOutlineVertices));
    for (int level = 0; level + 1 < levels; ++level) {
        if (radiusPixels * (1.0 - std::cos(kPi / kOutlineVertices[level])) <= kOutlineTolerance) {
            return level;
        }
    }
    return levels - 1;
}

/// The outline's colour for a grain filled with `fill`.
QRgb outlineColour(QRgb fill) {
    return QColor::fromRgba(fill).darker(160).rgba();
}

} // namespace

const QPolygonF& SceneRenderer::outline(int shape, int level) const {
    static_assert(std::size(kOutlineVertices) == kOutlineLevels);
    QPolygonF& polygon = outlines_[shape][level];
    if (polygon.isEmpty()) {
        const OvalShape& oval = snapshot_->shapes[shape];
        const int n = kOutlineVertices[level];
        // Each vertex is pushed out along its normal by half the stray of its arc's chords, so
        // that the polygon lies as much outside the outline as inside it (the area matches).
        const double halfStray = 0.5 * (1.0 - std::cos(kPi / n));
        polygon.resize(n);
        for (int j = 0; j < n; ++j) {
            const double alpha = 2.0 * kPi * j / n; // direction of the outward normal
            const auto p = oval.boundaryPoint(alpha);
            // The end arcs hold the normals within the junction angle of the long axis.
            const double radius =
                std::fabs(std::cos(alpha)) >= oval.cosJunction ? oval.endRadius : oval.sideRadius;
            polygon[j] = QPointF(p[0] + halfStray * radius * std::cos(alpha),
                                 p[1] + halfStray * radius * std::sin(alpha));
        }
    }
    return polygon;
}

int SceneRenderer::grainScreenOutline(int g, std::array<int, 2> shift, int level,
                                      QPointF* screen) const {
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    const QPolygonF& body = outline(s.shape[g], level);
    const double c1 = s.x1[g] + h[0] * shift[0] + h[2] * shift[1];
    const double c2 = s.x2[g] + h[1] * shift[0] + h[3] * shift[1];
    const double c = std::cos(s.theta[g]), sn = std::sin(s.theta[g]);
    const double scale = view_.pixelsPerMetre();
    const QPointF origin = view_.toScreen(0.0, 0.0);
    // Screen x = origin + scale * x2, screen y = origin - scale * x1 (view_transform.h), with
    // x1 = c1 + c bx - sn by and x2 = c2 + sn bx + c by for a body-frame point (bx, by).
    const double x0 = origin.x() + scale * c2, y0 = origin.y() - scale * c1;
    const double xx = scale * sn, xy = scale * c, yx = -scale * c, yy = scale * sn;
    const int n = static_cast<int>(body.size());
    for (int j = 0; j < n; ++j) {
        const double bx = body[j].x(), by = body[j].y();
        screen[j] = QPointF(x0 + xx * bx + xy * by, y0 + yx * bx + yy * by);
    }
    return n;
}

std::vector<GrainInstance> SceneRenderer::grainInstances() const {
    std::vector<GrainInstance> out;
    if (!snapshot_) {
        return out;
    }
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    std::array<std::array<int, 2>, 9> shifts;
    out.reserve(s.x1.size());
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        const QColor fill = grainColour(static_cast<int>(g));
        const int count = grainImages(static_cast<int>(g), shifts);
        for (int k = 0; k < count; ++k) {
            out.push_back({s.x1[g] + h[0] * shifts[k][0] + h[2] * shifts[k][1],
                           s.x2[g] + h[1] * shifts[k][0] + h[3] * shifts[k][1], s.theta[g],
                           s.shape[g], (k == 0 ? fill : lighter(fill, 0.45)).rgba()});
        }
    }
    return out;
}

/// The visible grains and images, by fill colour, then grain and image (a fixed order), each with
/// its screen outline: item k has points first[k] to first[k + 1].
struct SceneRenderer::GrainItems {
    struct Item {
        QRgb colour;
        std::int32_t grain;
        std::int8_t image, shift0, shift1;
        bool operator<(const Item& o) const {
            return colour != o.colour ? colour < o.colour
                                      : (grain != o.grain ? grain < o.grain : image < o.image);
        }
    };
    std::vector<Item> items;
    std::vector<QPointF> points;
    std::vector<std::size_t> first;
    std::vector<std::uint8_t> outlined; ///< per shape: wide enough at this zoom for an outline
};

SceneRenderer::GrainItems SceneRenderer::visibleGrains(const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    const double scale = view_.pixelsPerMetre();
    GrainItems out;
    // Per shape at this zoom: outline detail (set by its flatter arc) and whether it is outlined.
    std::vector<std::int8_t> level(s.shapes.size());
    out.outlined.resize(s.shapes.size());
    for (std::size_t k = 0; k < s.shapes.size(); ++k) {
        const OvalShape& shape = s.shapes[k];
        level[k] = static_cast<std::int8_t>(
            outlineLevel(std::max(shape.sideRadius, shape.endRadius) * scale));
        out.outlined[k] = shape.halfWidth * scale > kOutlinedRadius;
    }
    std::vector<GrainItems::Item>& items = out.items;
    items.reserve(s.x1.size());
    std::array<std::array<int, 2>, 9> shifts;
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        const double radius = s.shapes[s.shape[g]].halfWidth;
        const int count = grainImages(static_cast<int>(g), shifts);
        QColor fill;
        for (int k = 0; k < count; ++k) {
            if (!box.intersectsCircle(s.x1[g] + h[0] * shifts[k][0] + h[2] * shifts[k][1],
                                      s.x2[g] + h[1] * shifts[k][0] + h[3] * shifts[k][1],
                                      radius)) {
                continue;
            }
            if (!fill.isValid()) {
                fill = grainColour(static_cast<int>(g));
            }
            items.push_back({(k == 0 ? fill : lighter(fill, 0.45)).rgba(),
                             static_cast<std::int32_t>(g), static_cast<std::int8_t>(k),
                             static_cast<std::int8_t>(shifts[k][0]),
                             static_cast<std::int8_t>(shifts[k][1])});
        }
    }
    std::sort(items.begin(), items.end());

    // Their screen polygons, once for both passes.
    std::vector<QPointF>& points = out.points;
    std::vector<std::size_t>& first = out.first;
    first.assign(items.size() + 1, 0);
    for (std::size_t k = 0; k < items.size(); ++k) {
        const int shape = s.shape[items[k].grain];
        points.resize(first[k] + outline(shape, level[shape]).size());
        first[k + 1] =
            first[k] + grainScreenOutline(items[k].grain, {items[k].shift0, items[k].shift1},
                                          level[shape], &points[first[k]]);
    }
    return out;
}

void SceneRenderer::drawGrains(PixelCanvas& canvas, const WorldBox& box) const {
    // As drawGrains(QPainter&) draws on raster devices: the fills, then the outlines.
    // In bands of rows down the screen, not by colour (no brush to change here): the pixels a
    // grain touches are then near those of the grain before.
    const Snapshot& s = *snapshot_;
    const GrainItems g = visibleGrains(box);
    std::vector<std::pair<std::int64_t, std::int32_t>> order(g.items.size());
    for (std::size_t k = 0; k < g.items.size(); ++k) {
        const QPointF& p = g.points[g.first[k]];
        const auto band = static_cast<std::int64_t>(std::floor(p.y() / kBandRows));
        order[k] = {(band << 32) + static_cast<std::int64_t>(std::max(0.0, p.x())),
                    static_cast<std::int32_t>(k)};
    }
    std::sort(order.begin(), order.end());
    for (const auto& [key, k] : order) {
        canvas.fillConvexPolygon(&g.points[g.first[k]],
                                 static_cast<int>(g.first[k + 1] - g.first[k]), g.items[k].colour);
    }
    for (const auto& [key, k] : order) {
        if (g.outlined[s.shape[g.items[k].grain]]) {
            canvas.drawPolygonOutline(&g.points[g.first[k]],
                                      static_cast<int>(g.first[k + 1] - g.first[k]),
                                      outlineColour(g.items[k].colour));
        }
    }
}

void SceneRenderer::drawGrains(QPainter& p, const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    const GrainItems g = visibleGrains(box);
    const auto& items = g.items;
    const auto& outlined = g.outlined;
    const auto& points = g.points;
    const auto& first = g.first;
    auto draw = [&](std::size_t k) {
        p.drawPolygon(&points[first[k]], static_cast<int>(first[k + 1] - first[k]));
    };
    auto outlinePen = [](QRgb fill) { return QPen(QColor::fromRgba(outlineColour(fill)), 1.0); };
    const QPaintEngine* engine = p.paintEngine();
    if (engine && engine->type() != QPaintEngine::Raster) {
        // Vector devices (SVG, PDF) and OpenGL: one smoothed shape per grain, fill and outline.
        p.setRenderHint(QPainter::Antialiasing, true);
        for (std::size_t k = 0; k < items.size(); ++k) {
            p.setPen(outlined[s.shape[items[k].grain]] ? outlinePen(items[k].colour)
                                                       : QPen(Qt::NoPen));
            p.setBrush(QColor::fromRgba(items[k].colour));
            draw(k);
        }
    } else {
        // Raster: every fill aliased, then the outlines of the wide grains antialiased on top.
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(Qt::NoPen);
        for (std::size_t k = 0; k < items.size(); ++k) {
            if (k == 0 || items[k].colour != items[k - 1].colour) {
                p.setBrush(QColor::fromRgba(items[k].colour));
            }
            draw(k);
        }
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setBrush(Qt::NoBrush);
        QRgb penColour = 0;
        bool penSet = false;
        for (std::size_t k = 0; k < items.size(); ++k) {
            if (!outlined[s.shape[items[k].grain]]) {
                continue;
            }
            if (!penSet || items[k].colour != penColour) {
                p.setPen(outlinePen(items[k].colour));
                penColour = items[k].colour;
                penSet = true;
            }
            draw(k);
        }
    }
    drawSelectedGrainOutline(p, box);
}

void SceneRenderer::drawSelectedGrainOutline(QPainter& p, const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    const int g = options_.selectedGrain;
    if (g < 0 || g >= static_cast<int>(s.x1.size())) {
        return;
    }
    const CellMatrix& h = s.network.cell;
    const OvalShape& shape = s.shapes[s.shape[g]];
    const double radiusPixels = shape.halfWidth * view_.pixelsPerMetre();
    const int level = outlineLevel(shape.sideRadius * view_.pixelsPerMetre());
    std::array<std::array<int, 2>, 9> shifts;
    const int count = grainImages(g, shifts);
    QPointF screen[kMostVertices];
    QPainterPath path;
    for (int k = 0; k < count; ++k) {
        if (box.intersectsCircle(s.x1[g] + h[0] * shifts[k][0] + h[2] * shifts[k][1],
                                 s.x2[g] + h[1] * shifts[k][0] + h[3] * shifts[k][1],
                                 shape.halfWidth)) {
            const int n = grainScreenOutline(g, shifts[k], level, screen);
            path.addPolygon(QPolygonF(screen, screen + n));
            path.closeSubpath();
        }
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    p.strokePath(path, QPen(kSelection, std::max(2.0, 0.15 * radiusPixels)));
}

} // namespace grainlab::ui
