// See scene_renderer.h: the void cells and the force chains, over the grains.
//
// Measured on an 8450-grain scene like that of `grainlab bench --gui` (1000 x 1000 pixels, Qt 6.4
// raster engine, the void cells alone): fills aliased 6.5 ms, antialiased 80 ms (Qt's
// antialiasing rasteriser costs much per shape, and the larger shapes went to its thread pool).
// Zoomed x8, the 133 visible cells filled aliased in one piece each took 6 ms with 90 hand-overs
// to the thread pool a frame, and their outlines 12 ms as whole polygons but 1.4 ms in pieces of
// at most 32 pixels (no hand-over); with the bands and pieces below, the whole zoomed layer takes
// under 3 ms.
//
// The whole cell with strong chains and void cells by valence (6260 cells, 28600 edge segments of
// ~6 pixels, 3900 chains), each layer alone on a blank image: fills 8 ms, edges 9 ms, chains 5 ms
// with round caps, 2.3 ms with square caps; besides, the renderer spent ~5 ms a frame of its own
// reaching contacts, grains and polygons in force or colour order (cache misses), computing the
// cells' colours and sorting them. So the chain lines and the colour-sorted fills are gathered
// once per snapshot (and shading), and thin chains get square caps (drawForceChains). What is
// left is Qt's: ~0.4 us a call plus ~75 ns a row for an aliased fill, ~25 ns per span (two per
// pixel) for an antialiased line; batching more polygons into one path or polygon costs more
// (larger bounds, thread-pool hand-overs), and aliased edges (5.3 instead of 9 ms) look visibly
// thinner and stepped.
#include "grainlab/ui/scene_renderer.h"

#include <algorithm>
#include <cmath>

#include <QLineF>
#include <QPainter>
#include <QPainterPath>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/pixel_canvas.h"

namespace grainlab::ui {
namespace {

/// Translucent fills and antialiased lines are cut so that each drawing call stays below the
/// ~100 spans (one per row of an aliased fill, about two per pixel of an antialiased line) at
/// which Qt 6 hands the blending to its thread pool and waits for it.
constexpr double kRowsPerFill = 64.0;   ///< [pixel]
constexpr double kPixelsPerLine = 32.0; ///< [pixel]
/// Force-chain lines at least this wide have round caps, thinner ones square caps.
constexpr double kRoundCapWidth = 2.5; ///< [pixel]

/// The part of `polygon` between the screen rows `top` and `bottom` (Sutherland-Hodgman against
/// the two lines) into `out`. Bands that meet at whole rows share no pixel of an aliased fill.
void clipToRows(const QPolygonF& polygon, double top, double bottom, QPolygonF& out,
                QPolygonF& scratch) {
    auto clip = [](const QPolygonF& in, double y, bool keepBelow, QPolygonF& result) {
        result.clear();
        const qsizetype n = in.size();
        for (qsizetype k = 0; k < n; ++k) {
            const QPointF a = in[k], b = in[(k + 1) % n];
            const bool aIn = keepBelow ? a.y() >= y : a.y() <= y;
            const bool bIn = keepBelow ? b.y() >= y : b.y() <= y;
            if (aIn) {
                result.append(a);
            }
            if (aIn != bIn) {
                result.append(a + (b - a) * ((y - a.y()) / (b.y() - a.y())));
            }
        }
    };
    clip(polygon, top, true, scratch);
    clip(scratch, bottom, false, out);
}

/// Cuts the segment ab to the rectangle `r` (Liang-Barsky); false when nothing is left.
bool clipSegment(QPointF& a, QPointF& b, const QRectF& r) {
    const QPointF d = b - a;
    double t0 = 0.0, t1 = 1.0;
    const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double q[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) {
                return false;
            }
        } else if (p[k] < 0.0) {
            t0 = std::max(t0, q[k] / p[k]);
        } else {
            t1 = std::min(t1, q[k] / p[k]);
        }
    }
    if (t0 > t1) {
        return false;
    }
    b = a + t1 * d;
    a = a + t0 * d;
    return true;
}

/// Appends the part of segment ab inside `view` in pieces of at most kPixelsPerLine.
void addLinePieces(std::vector<QLineF>& lines, QPointF a, QPointF b, const QRectF& view) {
    const QPointF d = b - a;
    if (d.x() * d.x() + d.y() * d.y() <= kPixelsPerLine * kPixelsPerLine && view.contains(a) &&
        view.contains(b)) {
        lines.emplace_back(a, b); // the common case: short and in view
        return;
    }
    if (!clipSegment(a, b, view)) {
        return;
    }
    const int pieces =
        std::max(1, static_cast<int>(std::ceil(QLineF(a, b).length() / kPixelsPerLine)));
    for (int k = 0; k < pieces; ++k) {
        lines.emplace_back(a + (b - a) * (double(k) / pieces),
                           a + (b - a) * (double(k + 1) / pieces));
    }
}

} // namespace

const std::vector<std::array<double, 4>>& SceneRenderer::voidEdges() const {
    if (voidEdgesReady_ || !snapshot_) {
        return voidEdges_;
    }
    // Each edge once: neighbouring cells share an edge (a contact). End points are compared on
    // a grid of 1e-9 of the cell size (the two cells may place a grain through different
    // periodic images), through a 64-bit hash of the rounded end points. Built on first use,
    // as only the QPainter view of void cells needs them.
    const CellMatrix& h = snapshot_->network.cell;
    const double grid = 1e-9 * std::max(cellWidths(h)[0], cellWidths(h)[1]);
    std::vector<std::array<double, 4>> edges;
    std::vector<std::pair<std::uint64_t, std::int32_t>> keys;
    for (const QPolygonF& polygon : voidPolygons_) {
        for (qsizetype k = 0; k < polygon.size(); ++k) {
            QPointF a = polygon[k], b = polygon[(k + 1) % polygon.size()];
            if (a.x() > b.x() || (a.x() == b.x() && a.y() > b.y())) {
                std::swap(a, b);
            }
            std::uint64_t key = 1469598103934665603ull; // FNV-1a over the rounded coordinates
            for (double c : {a.x(), a.y(), b.x(), b.y()}) {
                key = (key ^ static_cast<std::uint64_t>(std::llround(c / grid))) * 1099511628211ull;
            }
            keys.push_back({key, static_cast<std::int32_t>(edges.size())});
            edges.push_back({a.x(), a.y(), b.x(), b.y()});
        }
    }
    std::sort(keys.begin(), keys.end());
    voidEdges_.clear();
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (k == 0 || keys[k].first != keys[k - 1].first) {
            voidEdges_.push_back(edges[keys[k].second]);
        }
    }
    // Down the screen (x1 is up): the overview reaches their pixels in order (see drawGrains).
    std::sort(voidEdges_.begin(), voidEdges_.end(),
              [](const auto& a, const auto& b) { return a[0] + a[2] < b[0] + b[2]; });
    voidEdgesReady_ = true;
    return voidEdges_;
}

const std::vector<SceneRenderer::ChainLine>& SceneRenderer::chainLines(std::int32_t from) const {
    if (from >= chainLinesFrom_ || !snapshot_) {
        return chainLines_;
    }
    // Only from `from` on: forceOrder_ ends with the strong contacts, often all that is drawn.
    const Snapshot& s = *snapshot_;
    const auto& contacts = s.network.contacts;
    chainLines_.resize(forceOrder_.size());
    for (std::int32_t k = from; k < chainLinesFrom_; ++k) {
        const ContactRecord& r = contacts[forceOrder_[k]];
        chainLines_[k] = {s.x1[r.first],
                          s.x2[r.first],
                          r.branch1,
                          r.branch2,
                          std::hypot(r.branch1, r.branch2),
                          s.x1[r.second],
                          s.x2[r.second],
                          r.shift1 != 0 || r.shift2 != 0};
    }
    chainLinesFrom_ = from;
    return chainLines_;
}

template <class Visit>
void SceneRenderer::forEachVisibleChain(const WorldBox& box, Visit&& visit) const {
    if (maxForce_ <= 0.0 || options_.forceChains == ForceChains::Off) {
        return;
    }
    std::int32_t from = static_cast<std::int32_t>(forceOrder_.size());
    for (const ChainBin& bin : chainBins_) {
        if (options_.forceChains == ForceChains::All || bin.strong) {
            from = std::min(from, bin.begin);
        }
    }
    const std::vector<ChainLine>& lines = chainLines(from);
    for (const ChainBin& bin : chainBins_) {
        if (options_.forceChains == ForceChains::Strong && !bin.strong) {
            continue;
        }
        for (std::int32_t k = bin.begin; k < bin.end; ++k) {
            const ChainLine& c = lines[k];
            if (box.intersectsCircle(c.a1, c.a2, c.length)) {
                visit(bin, c.a1, c.a2, c.a1 + c.branch1, c.a2 + c.branch2);
            }
            if (c.crossesBorder && box.intersectsCircle(c.b1, c.b2, c.length)) {
                // The contact crosses the border: also draw it from B's side.
                visit(bin, c.b1, c.b2, c.b1 - c.branch1, c.b2 - c.branch2);
            }
        }
    }
}

const std::vector<SceneRenderer::VoidFill>& SceneRenderer::voidFills() const {
    if (voidFillsShading_ == options_.voidCells || !snapshot_) {
        return voidFills_;
    }
    voidFills_.clear();
    voidFillPoints_.clear();
    voidFillsShading_ = options_.voidCells;
    if (voidFillsShading_ == VoidCellShading::Off) {
        return voidFills_;
    }
    // By colour, then cell: a counting sort over the few distinct colours (at most 128).
    const int cells = static_cast<int>(voidPolygons_.size());
    std::vector<QRgb> colours(cells);
    std::size_t points = 0;
    for (int v = 0; v < cells; ++v) {
        colours[v] = voidCellShade(v, kVoidCellAlpha).rgba();
        points += voidPolygons_[v].size();
    }
    std::vector<QRgb> distinct = colours;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    std::vector<std::int32_t> rank(cells), start(distinct.size() + 1, 0);
    for (int v = 0; v < cells; ++v) {
        rank[v] = static_cast<std::int32_t>(
            std::lower_bound(distinct.begin(), distinct.end(), colours[v]) - distinct.begin());
        ++start[rank[v] + 1];
    }
    for (std::size_t c = 1; c < start.size(); ++c) {
        start[c] += start[c - 1];
    }
    voidFills_.resize(cells);
    for (int v = 0; v < cells; ++v) {
        voidFills_[start[rank[v]]++] = {colours[v], v, 0, 0};
    }
    voidFillPoints_.reserve(points);
    for (VoidFill& fill : voidFills_) {
        const QPolygonF& polygon = voidPolygons_[fill.cell];
        fill.begin = static_cast<std::int32_t>(voidFillPoints_.size());
        voidFillPoints_.insert(voidFillPoints_.end(), polygon.begin(), polygon.end());
        fill.end = static_cast<std::int32_t>(voidFillPoints_.size());
    }
    return voidFills_;
}

std::vector<ChainSegment> SceneRenderer::forceChainSegments(QSize viewport) const {
    std::vector<ChainSegment> out;
    if (!snapshot_) {
        return out;
    }
    const ChainBin* current = nullptr;
    double width = 0.0;
    QRgb colour = 0;
    forEachVisibleChain(view_.visibleBox(QSizeF(viewport)),
                        [&](const ChainBin& bin, double a1, double a2, double b1, double b2) {
                            if (&bin != current) {
                                current = &bin;
                                width = forceChainWidth(bin.force);
                                colour = forceChainColour(bin.force).rgba();
                            }
                            out.push_back({a1, a2, b1, b2, width, colour});
                        });
    return out;
}

template <class F>
void SceneRenderer::forEachVisibleVoidImage(int v, const WorldBox& box, F&& f) const {
    const CellMatrix& h = snapshot_->network.cell;
    const int images = options_.periodicImages ? 1 : 0;
    const auto& b = voidBoxes_[v];
    for (int i = -images; i <= images; ++i) {
        for (int j = -images; j <= images; ++j) {
            const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
            if (b[1] + s1 >= box.min1 && b[0] + s1 <= box.max1 && b[3] + s2 >= box.min2 &&
                b[2] + s2 <= box.max2) {
                f(i, j);
            }
        }
    }
}

template <class F>
void SceneRenderer::forEachVisibleVoidEdge(const WorldBox& box, F&& f) const {
    const CellMatrix& h = snapshot_->network.cell;
    const int images = options_.periodicImages ? 1 : 0;
    for (int i = -images; i <= images; ++i) {
        for (int j = -images; j <= images; ++j) {
            const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
            for (const auto& e : voidEdges()) {
                const double a1 = e[0] + s1, a2 = e[1] + s2, b1 = e[2] + s1, b2 = e[3] + s2;
                if (std::max(a1, b1) >= box.min1 && std::min(a1, b1) <= box.max1 &&
                    std::max(a2, b2) >= box.min2 && std::min(a2, b2) <= box.max2) {
                    f(view_.toScreen(a1, a2), view_.toScreen(b1, b2));
                }
            }
        }
    }
}

void SceneRenderer::drawVoidCellShading(PixelCanvas& canvas, const WorldBox& box) const {
    // As drawVoidCells(QPainter&) draws the shading: the fills (but the selected cell's), then
    // each shared edge once, with the colour and alpha of its QPainter outline (a 0.8-pixel
    // cosmetic pen of alpha 220: a one-pixel line of 0.8 of that alpha).
    if (options_.voidCells == VoidCellShading::Off) {
        return;
    }
    const CellMatrix& h = snapshot_->network.cell;
    // The cells down the screen (see drawGrains), with their colours of voidFills().
    std::vector<QRgb> colour(voidPolygons_.size());
    for (const VoidFill& fill : voidFills()) {
        colour[fill.cell] = fill.colour;
    }
    std::vector<QPointF> screen;
    for (const std::int32_t v : voidOrder_) {
        if (v == options_.selectedVoidCell) {
            continue;
        }
        forEachVisibleVoidImage(v, box, [&](int i, int j) {
            const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
            const QPolygonF& polygon = voidPolygons_[v];
            screen.resize(polygon.size());
            for (qsizetype k = 0; k < polygon.size(); ++k) {
                screen[k] = view_.toScreen(polygon[k].x() + s1, polygon[k].y() + s2);
            }
            canvas.fillPolygon(screen.data(), static_cast<int>(screen.size()), colour[v]);
        });
    }
    const QRgb edge = qRgba(30, 30, 90, static_cast<int>(std::lround(0.8 * 220)));
    forEachVisibleVoidEdge(box, [&](QPointF a, QPointF b) { canvas.drawLine(a, b, edge); });
}

void SceneRenderer::drawVoidCells(QPainter& p, const WorldBox& box, bool shading) const {
    const CellMatrix& h = snapshot_->network.cell;
    const int selected = options_.selectedVoidCell;
    const int cells = static_cast<int>(voidPolygons_.size());
    auto forEachVisibleImage = [&](int v, auto&& f) { forEachVisibleVoidImage(v, box, f); };
    auto screenPolygon = [&](int v, int i, int j, QPolygonF& screen) {
        const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
        const QPolygonF& polygon = voidPolygons_[v];
        screen.resize(polygon.size());
        for (qsizetype k = 0; k < polygon.size(); ++k) {
            screen[k] = view_.toScreen(polygon[k].x() + s1, polygon[k].y() + s2);
        }
    };
    // The view in screen pixels, grown by two.
    const QRectF screenBox =
        QRectF(view_.toScreen(box.max1, box.min2), view_.toScreen(box.min1, box.max2))
            .normalized()
            .adjusted(-2.0, -2.0, 2.0, 2.0);
    if (shading && options_.voidCells != VoidCellShading::Off) {
        // The fills, by colour (one brush each), aliased: the outlines drawn next cover their
        // staircase, and aliased fills of cells that tile the plane meet without seams.
        p.setRenderHint(QPainter::Antialiasing, false);
        p.setPen(Qt::NoPen);
        QRgb brush = 0;
        bool brushSet = false;
        QPolygonF screen, band, scratch;
        for (const VoidFill& fill : voidFills()) {
            if (fill.cell == selected) {
                continue; // drawn last, on top
            }
            forEachVisibleImage(fill.cell, [&](int i, int j) {
                if (!brushSet || fill.colour != brush) {
                    p.setBrush(QColor::fromRgba(fill.colour));
                    brush = fill.colour;
                    brushSet = true;
                }
                const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
                screen.resize(fill.end - fill.begin);
                for (std::int32_t k = fill.begin; k < fill.end; ++k) {
                    const QPointF& q = voidFillPoints_[k];
                    screen[k - fill.begin] = view_.toScreen(q.x() + s1, q.y() + s2);
                }
                const QRectF bounds = screen.boundingRect();
                if (bounds.height() <= kRowsPerFill) {
                    p.drawPolygon(screen);
                    return;
                }
                // A tall translucent fill in one call would go to Qt's thread pool: in bands.
                for (double top = std::floor(std::max(bounds.top(), screenBox.top())),
                            bottom = std::min(bounds.bottom(), screenBox.bottom());
                     top < bottom; top += kRowsPerFill) {
                    clipToRows(screen, top, top + kRowsPerFill, band, scratch);
                    if (band.size() >= 3) {
                        p.drawPolygon(band);
                    }
                }
            });
        }
        // The outlines: each shared edge once, with the look of the two strokes of a cosmetic
        // 0.8 pixel pen of alpha 160 it used to get (1 - (1 - 160/255)^2 = 0.86), in pieces of
        // at most kPixelsPerLine.
        QPen pen(QColor(30, 30, 90, 220), 0.8);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.setRenderHint(QPainter::Antialiasing, true);
        std::vector<QLineF> lines;
        lines.reserve(voidEdges().size());
        forEachVisibleVoidEdge(
            box, [&](QPointF a, QPointF b) { addLinePieces(lines, a, b, screenBox); });
        p.drawLines(lines.data(), static_cast<int>(lines.size()));
    }
    if (selected >= 0 && selected < cells) {
        QPainterPath path;
        QPolygonF screen;
        forEachVisibleImage(selected, [&](int i, int j) {
            screenPolygon(selected, i, j, screen);
            path.addPolygon(screen);
            path.closeSubpath();
        });
        QPen pen(QColor(255, 140, 0), 2.5);
        pen.setCosmetic(true);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.setPen(pen);
        p.setBrush(voidCellColour(selected));
        p.drawPath(path);
    }
}

void SceneRenderer::drawForceChains(QPainter& p, const WorldBox& box) const {
    // One pen per force bin. The lines are drawn one by one: QPainter strokes a list of wide
    // lines as one shape, which costs more when they are scattered over the whole view. Lines
    // thinner than kRoundCapWidth get square caps: the raster engine draws lines with square or
    // flat caps with its own line rasteriser, round ones through the general stroker, at twice
    // the cost (whole cell, ~3900 strong chains: 2.3 instead of 5.0 ms), and at that width the
    // two caps differ only in the corner pixels (by less than a third of their coverage).
    const ChainBin* current = nullptr;
    p.setRenderHint(QPainter::Antialiasing, true);
    forEachVisibleChain(box, [&](const ChainBin& bin, double a1, double a2, double b1, double b2) {
        if (&bin != current) {
            current = &bin;
            const double width = forceChainWidth(bin.force);
            QPen pen(forceChainColour(bin.force), width);
            pen.setCapStyle(width < kRoundCapWidth ? Qt::SquareCap : Qt::RoundCap);
            p.setPen(pen);
        }
        p.drawLine(view_.toScreen(a1, a2), view_.toScreen(b1, b2));
    });
}

} // namespace grainlab::ui
