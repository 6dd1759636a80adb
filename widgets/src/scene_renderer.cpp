// See scene_renderer.h.
#include "grainlab/ui/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include "grainlab/ui/colour_maps.h"

namespace grainlab::ui {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kOutlineDetail[3] = {12, 24, 64}; ///< outline vertices per detail level
constexpr int kRoseBins = 18;

/// Grains of the load-bearing graph (SPEC §4): drop grains without contacts, then repeatedly
/// those with a single remaining contact.
std::vector<std::uint8_t> loadBearingGrains(const ContactNetwork& net, std::size_t grains) {
    std::vector<int> degree(grains, 0);
    std::vector<std::vector<int>> neighbours(grains);
    for (const auto& c : net.contacts) {
        if (c.first == c.second) {
            continue;
        }
        ++degree[c.first];
        ++degree[c.second];
        neighbours[c.first].push_back(c.second);
        neighbours[c.second].push_back(c.first);
    }
    std::vector<std::uint8_t> alive(grains, 1);
    std::vector<int> queue;
    for (std::size_t g = 0; g < grains; ++g) {
        if (degree[g] <= 1) {
            queue.push_back(static_cast<int>(g));
        }
    }
    while (!queue.empty()) {
        const int g = queue.back();
        queue.pop_back();
        if (!alive[g]) {
            continue;
        }
        alive[g] = 0;
        for (int n : neighbours[g]) {
            if (alive[n] && --degree[n] <= 1) {
                queue.push_back(n);
            }
        }
    }
    return alive;
}

/// A screen direction for a world direction at angle `alpha` from x1 towards x2.
QPointF screenDirection(double alpha) {
    return {std::sin(alpha), -std::cos(alpha)};
}

} // namespace

SceneRenderer::SceneRenderer() = default;

void SceneRenderer::setSnapshot(SnapshotPtr snapshot) {
    snapshot_ = std::move(snapshot);
    coordination_.clear();
    forceMagnitude_.clear();
    forceOrder_.clear();
    outlines_.clear();
    voidPolygons_.clear();
    voidBoxes_.clear();
    roseCounts_.fill(0.0);
    maxForce_ = strongThreshold_ = meanVoidArea_ = 0.0;
    if (!snapshot_) {
        return;
    }
    const Snapshot& s = *snapshot_;
    const std::size_t n = s.x1.size();

    // Shapes: size range and outlines at three detail levels.
    minDiameter_ = 1e300;
    maxDiameter_ = maxHalfWidth_ = 0.0;
    outlines_.resize(s.shapes.size());
    for (std::size_t k = 0; k < s.shapes.size(); ++k) {
        const OvalShape& shape = s.shapes[k];
        minDiameter_ = std::min(minDiameter_, shape.equivalentDiameter());
        maxDiameter_ = std::max(maxDiameter_, shape.equivalentDiameter());
        maxHalfWidth_ = std::max(maxHalfWidth_, shape.halfWidth);
        for (int level = 0; level < 3; ++level) {
            const int m = kOutlineDetail[level];
            QPolygonF outline(m);
            for (int j = 0; j < m; ++j) {
                const auto p = shape.boundaryPoint(2.0 * kPi * j / m);
                outline[j] = QPointF(p[0], p[1]);
            }
            outlines_[k][level] = outline;
        }
    }

    // Contacts: coordination, force magnitudes and order, normal rose.
    const auto& contacts = s.network.contacts;
    coordination_.assign(n, 0);
    forceMagnitude_.resize(contacts.size());
    double sumSquares = 0.0;
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const auto& r = contacts[c];
        if (r.first >= 0 && static_cast<std::size_t>(r.first) < n) {
            ++coordination_[r.first];
        }
        if (r.second >= 0 && static_cast<std::size_t>(r.second) < n) {
            ++coordination_[r.second];
        }
        const auto f = r.force();
        forceMagnitude_[c] = std::hypot(f[0], f[1]);
        sumSquares += forceMagnitude_[c] * forceMagnitude_[c];
        maxForce_ = std::max(maxForce_, forceMagnitude_[c]);
        double alpha = std::atan2(r.normal2, r.normal1);
        if (alpha < 0.0) {
            alpha += kPi;
        }
        roseCounts_[std::min(kRoseBins - 1, static_cast<int>(alpha / kPi * kRoseBins))] += 1.0;
    }
    loadBearing_ = s.loadBearing.size() == n ? s.loadBearing : loadBearingGrains(s.network, n);
    strongThreshold_ = contacts.empty() ? 0.0 : std::sqrt(sumSquares / double(contacts.size()));
    forceOrder_.resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        forceOrder_[c] = static_cast<std::int32_t>(c);
    }
    std::sort(forceOrder_.begin(), forceOrder_.end(),
              [this](int a, int b) { return forceMagnitude_[a] < forceMagnitude_[b]; });

    // Void cells: shift each polygon so that its vertex mean lies inside the cell.
    const CellMatrix& h = s.network.cell;
    voidPolygons_.resize(s.voidCells.size());
    voidBoxes_.resize(s.voidCells.size());
    double areaSum = 0.0;
    for (std::size_t v = 0; v < s.voidCells.size(); ++v) {
        const VoidCellView& cell = s.voidCells[v];
        const std::size_t m = std::min(cell.x1.size(), cell.x2.size());
        double mean1 = 0.0, mean2 = 0.0;
        for (std::size_t j = 0; j < m; ++j) {
            mean1 += cell.x1[j];
            mean2 += cell.x2[j];
        }
        if (m > 0) {
            mean1 /= double(m);
            mean2 /= double(m);
        }
        const auto frac = toFractional(h, mean1, mean2);
        const double k0 = std::floor(frac[0]), k1 = std::floor(frac[1]);
        const double shift1 = -(h[0] * k0 + h[2] * k1), shift2 = -(h[1] * k0 + h[3] * k1);
        QPolygonF polygon(static_cast<int>(m));
        std::array<double, 4> box{1e300, -1e300, 1e300, -1e300};
        for (std::size_t j = 0; j < m; ++j) {
            const double p1 = cell.x1[j] + shift1, p2 = cell.x2[j] + shift2;
            polygon[static_cast<int>(j)] = QPointF(p1, p2);
            box = {std::min(box[0], p1), std::max(box[1], p1), std::min(box[2], p2),
                   std::max(box[3], p2)};
        }
        voidPolygons_[v] = polygon;
        voidBoxes_[v] = box;
        areaSum += cell.area;
    }
    meanVoidArea_ = s.voidCells.empty() ? 0.0 : areaSum / double(s.voidCells.size());
}

void SceneRenderer::fitToCell(QSize viewport) {
    if (snapshot_) {
        const double border =
            options_.periodicImages ? options_.imageBorder * 2.0 * maxHalfWidth_ : 0.0;
        view_.fitCell(snapshot_->network.cell, QSizeF(viewport), 16.0, border);
    }
}

QColor SceneRenderer::grainColour(int g) const {
    const Snapshot& s = *snapshot_;
    switch (options_.colouring) {
    case GrainColouring::Size: {
        const double d = s.shapes[s.shape[g]].equivalentDiameter();
        const double span = maxDiameter_ - minDiameter_;
        const double t = span > 0.0 ? (d - minDiameter_) / span : 0.5;
        return sequentialColour(0.12 + 0.83 * t);
    }
    case GrainColouring::Rotation: {
        const double r = static_cast<std::size_t>(g) < s.rotation.size() ? s.rotation[g] : 0.0;
        return divergingColour(r / options_.rotationRange);
    }
    case GrainColouring::Coordination:
        return sequentialColour(std::min(coordination_[g], 8) / 8.0);
    case GrainColouring::LoadBearing: {
        return loadBearing_[g] != 0 ? QColor(70, 110, 170) : QColor(205, 205, 205);
    }
    case GrainColouring::Uniform:
        break;
    }
    return options_.uniformGrain;
}

int SceneRenderer::grainImages(int g, std::array<std::array<int, 2>, 9>& shifts) const {
    shifts[0] = {0, 0};
    if (!options_.periodicImages) {
        return 1;
    }
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    const auto widths = cellWidths(h);
    const double border = options_.imageBorder * 2.0 * maxHalfWidth_;
    const double m0 = border / widths[0], m1 = border / widths[1];
    const auto f = toFractional(h, s.x1[g], s.x2[g]);
    int count = 1;
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            if ((i != 0 || j != 0) && f[0] + i >= -m0 && f[0] + i <= 1.0 + m0 && f[1] + j >= -m1 &&
                f[1] + j <= 1.0 + m1) {
                shifts[count++] = {i, j};
            }
        }
    }
    return count;
}

bool SceneRenderer::grainContains(int g, double c1, double c2, double x1, double x2) const {
    const Snapshot& s = *snapshot_;
    const OvalShape& shape = s.shapes[s.shape[g]];
    const double d1 = x1 - c1, d2 = x2 - c2;
    if (d1 * d1 + d2 * d2 > shape.halfWidth * shape.halfWidth) {
        return false;
    }
    if (shape.isDisk) {
        return true;
    }
    // Body frame: theta rotates body x onto world x1.
    const double c = std::cos(s.theta[g]), sn = std::sin(s.theta[g]);
    const double bx = c * d1 + sn * d2, by = -sn * d1 + c * d2;
    const auto arcs = shape.arcs();
    auto inDisc = [&](const Arc& a) {
        return (bx - a.centreX) * (bx - a.centreX) + (by - a.centreY) * (by - a.centreY) <=
               a.radius * a.radius;
    };
    // The end discs are internally tangent to both side discs, so the oval is the union of the
    // end discs and the part of the side discs' intersection between the junctions.
    const double junctionX = arcs[kRightEnd].centreX + shape.endRadius * shape.cosJunction;
    if (std::fabs(bx) <= junctionX && inDisc(arcs[kTopSide]) && inDisc(arcs[kBottomSide])) {
        return true;
    }
    return inDisc(arcs[kRightEnd]) || inDisc(arcs[kLeftEnd]);
}

int SceneRenderer::grainAt(QPointF screenPoint) const {
    if (!snapshot_) {
        return -1;
    }
    const Snapshot& s = *snapshot_;
    const auto w = view_.toWorld(screenPoint);
    const CellMatrix& h = s.network.cell;
    std::array<std::array<int, 2>, 9> shifts;
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        const int count = grainImages(static_cast<int>(g), shifts);
        for (int k = 0; k < count; ++k) {
            const double c1 = s.x1[g] + h[0] * shifts[k][0] + h[2] * shifts[k][1];
            const double c2 = s.x2[g] + h[1] * shifts[k][0] + h[3] * shifts[k][1];
            if (grainContains(static_cast<int>(g), c1, c2, w[0], w[1])) {
                return static_cast<int>(g);
            }
        }
    }
    return -1;
}

int SceneRenderer::voidCellAt(QPointF screenPoint) const {
    if (!snapshot_) {
        return -1;
    }
    const auto w = view_.toWorld(screenPoint);
    const CellMatrix& h = snapshot_->network.cell;
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            // A polygon image shifted by +h k contains w iff the polygon contains w - h k.
            const double p1 = w[0] - h[0] * i - h[2] * j, p2 = w[1] - h[1] * i - h[3] * j;
            for (std::size_t v = 0; v < voidPolygons_.size(); ++v) {
                const auto& b = voidBoxes_[v];
                if (p1 < b[0] || p1 > b[1] || p2 < b[2] || p2 > b[3]) {
                    continue;
                }
                if (voidPolygons_[v].containsPoint(QPointF(p1, p2), Qt::OddEvenFill)) {
                    return static_cast<int>(v);
                }
            }
        }
    }
    return -1;
}

void SceneRenderer::render(QPainter& p, QSize viewport) const {
    renderBackground(p, viewport);
    if (snapshot_) {
        p.save();
        p.setRenderHint(QPainter::Antialiasing, true);
        drawGrains(p, view_.visibleBox(QSizeF(viewport)));
        p.restore();
    }
    renderOverlays(p, viewport, false);
}

void SceneRenderer::renderBackground(QPainter& p, QSize viewport) const {
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.fillRect(QRect(QPoint(0, 0), viewport), options_.background);
    if (snapshot_) {
        drawCell(p);
    }
    p.restore();
}

void SceneRenderer::renderOverlays(QPainter& p, QSize viewport, bool outlineSelectedGrain) const {
    if (!snapshot_) {
        return;
    }
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    const WorldBox box = view_.visibleBox(QSizeF(viewport));
    if (outlineSelectedGrain && options_.selectedGrain >= 0 &&
        options_.selectedGrain < static_cast<int>(snapshot_->x1.size())) {
        drawSelectedGrainOutline(p);
    }
    if (options_.voidCells != VoidCellShading::Off || options_.selectedVoidCell >= 0) {
        drawVoidCells(p, box);
    }
    if (options_.forceChains != ForceChains::Off) {
        drawForceChains(p, box);
    }
    if (options_.contactRose) {
        drawRose(p, viewport);
    }
    if (options_.scaleBar) {
        drawScaleBar(p, viewport);
    }
    if (options_.caption) {
        drawCaption(p);
    }
    p.restore();
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

void SceneRenderer::drawSelectedGrainOutline(QPainter& p) const {
    const Snapshot& s = *snapshot_;
    const int g = options_.selectedGrain;
    const QPolygonF& outline = outlines_[s.shape[g]][2];
    const double c = std::cos(s.theta[g]), sn = std::sin(s.theta[g]);
    QPolygonF screen(outline.size());
    for (int j = 0; j < outline.size(); ++j) {
        const double bx = outline[j].x(), by = outline[j].y();
        screen[j] = view_.toScreen(s.x1[g] + c * bx - sn * by, s.x2[g] + sn * bx + c * by);
    }
    const double radiusPixels = s.shapes[s.shape[g]].halfWidth * view_.pixelsPerMetre();
    p.setPen(QPen(QColor(255, 140, 0), std::max(2.0, 0.15 * radiusPixels)));
    p.setBrush(Qt::NoBrush);
    p.drawPolygon(screen);
}

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

void SceneRenderer::drawGrains(QPainter& p, const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    const double scale = view_.pixelsPerMetre();
    const QPointF origin = view_.toScreen(0.0, 0.0);
    std::array<std::array<int, 2>, 9> shifts;
    QPolygonF screen;
    for (std::size_t g = 0; g < s.x1.size(); ++g) {
        const OvalShape& shape = s.shapes[s.shape[g]];
        const double radiusPixels = shape.halfWidth * scale;
        const int level = radiusPixels < 3.0 ? 0 : (radiusPixels < 12.0 ? 1 : 2);
        const QPolygonF& outline = outlines_[s.shape[g]][level];
        const double c = std::cos(s.theta[g]), sn = std::sin(s.theta[g]);
        const QColor fill = grainColour(static_cast<int>(g));
        const bool selected = static_cast<int>(g) == options_.selectedGrain;
        const int count = grainImages(static_cast<int>(g), shifts);
        for (int k = 0; k < count; ++k) {
            const double c1 = s.x1[g] + h[0] * shifts[k][0] + h[2] * shifts[k][1];
            const double c2 = s.x2[g] + h[1] * shifts[k][0] + h[3] * shifts[k][1];
            if (!box.intersectsCircle(c1, c2, shape.halfWidth)) {
                continue;
            }
            screen.resize(outline.size());
            for (int j = 0; j < outline.size(); ++j) {
                const double bx = outline[j].x(), by = outline[j].y();
                const double w1 = c1 + c * bx - sn * by, w2 = c2 + sn * bx + c * by;
                screen[j] = QPointF(origin.x() + scale * w2, origin.y() - scale * w1);
            }
            const QColor colour = k == 0 ? fill : lighter(fill, 0.45);
            if (selected) {
                p.setPen(QPen(QColor(255, 140, 0), std::max(2.0, 0.15 * radiusPixels)));
            } else if (radiusPixels > 6.0) {
                p.setPen(QPen(colour.darker(160), 1.0));
            } else {
                p.setPen(Qt::NoPen);
            }
            p.setBrush(colour);
            p.drawPolygon(screen);
        }
    }
}

void SceneRenderer::drawVoidCells(QPainter& p, const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    const CellMatrix& h = s.network.cell;
    const int images = options_.periodicImages ? 1 : 0;
    QPolygonF screen;
    for (std::size_t v = 0; v < voidPolygons_.size(); ++v) {
        const bool selected = static_cast<int>(v) == options_.selectedVoidCell;
        if (options_.voidCells == VoidCellShading::Off && !selected) {
            continue;
        }
        const VoidCellView& cell = s.voidCells[v];
        QColor fill;
        if (options_.voidCells == VoidCellShading::Area && meanVoidArea_ > 0.0) {
            // Log scale: a tenth of the mean area to ten times it.
            fill = sequentialColour((std::log10(cell.area / meanVoidArea_) + 1.0) / 2.0);
        } else {
            fill = sequentialColour(std::clamp((cell.valence - 3) / 7.0, 0.0, 1.0));
        }
        fill.setAlpha(selected ? 200 : 120);
        QPen pen(selected ? QColor(255, 140, 0) : QColor(30, 30, 90, 160), selected ? 2.5 : 0.8);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.setBrush(fill);
        const auto& b = voidBoxes_[v];
        for (int i = -images; i <= images; ++i) {
            for (int j = -images; j <= images; ++j) {
                const double s1 = h[0] * i + h[2] * j, s2 = h[1] * i + h[3] * j;
                const WorldBox shifted{b[0] + s1, b[1] + s1, b[2] + s2, b[3] + s2};
                if (shifted.max1 < box.min1 || shifted.min1 > box.max1 || shifted.max2 < box.min2 ||
                    shifted.min2 > box.max2) {
                    continue;
                }
                const QPolygonF& polygon = voidPolygons_[v];
                screen.resize(polygon.size());
                for (int k = 0; k < polygon.size(); ++k) {
                    screen[k] = view_.toScreen(polygon[k].x() + s1, polygon[k].y() + s2);
                }
                p.drawPolygon(screen);
            }
        }
    }
}

void SceneRenderer::drawForceChains(QPainter& p, const WorldBox& box) const {
    const Snapshot& s = *snapshot_;
    if (maxForce_ <= 0.0) {
        return;
    }
    const double scale = view_.pixelsPerMetre();
    const double meanWidthPixels = minDiameter_ * scale;
    const double unitWidth = std::max(0.6, 0.07 * meanWidthPixels); // line width at f = f_a
    const auto& contacts = s.network.contacts;
    for (std::int32_t c : forceOrder_) {
        const double f = forceMagnitude_[c];
        if (options_.forceChains == ForceChains::Strong && f <= strongThreshold_) {
            continue;
        }
        const ContactRecord& r = contacts[c];
        const double ratio = f / strongThreshold_;
        const double width = std::clamp(unitWidth * ratio, 0.4, 4.0 * unitWidth);
        const QColor colour =
            QColor::fromRgbF(float(0.55 + 0.35 * std::min(1.0, f / maxForce_)),
                             float(0.35 * (1.0 - std::min(1.0, f / maxForce_))), 0.05f,
                             float(std::clamp(0.35 + 0.65 * ratio, 0.35, 1.0)));
        QPen pen(colour, width);
        pen.setCapStyle(Qt::RoundCap);
        p.setPen(pen);
        const double length = std::hypot(r.branch1, r.branch2);
        const double a1 = s.x1[r.first], a2 = s.x2[r.first];
        if (box.intersectsCircle(a1, a2, length)) {
            p.drawLine(view_.toScreen(a1, a2), view_.toScreen(a1 + r.branch1, a2 + r.branch2));
        }
        if (r.shift1 != 0 || r.shift2 != 0) {
            // The contact crosses the border: also draw it from B's side.
            const double b1 = s.x1[r.second], b2 = s.x2[r.second];
            if (box.intersectsCircle(b1, b2, length)) {
                p.drawLine(view_.toScreen(b1, b2), view_.toScreen(b1 - r.branch1, b2 - r.branch2));
            }
        }
    }
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
    const double width = kPi / kRoseBins;
    for (int k = 0; k < kRoseBins; ++k) {
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

} // namespace grainlab::ui
