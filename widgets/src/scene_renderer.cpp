// See scene_renderer.h. This file holds what the snapshot implies (coordination, forces, void-cell
// polygons), the colours, the hit tests and the order of the layers; the layers themselves are
// drawn in scene_renderer_grains.cpp, scene_renderer_overlays.cpp and
// scene_renderer_decorations.cpp.
#include "grainlab/ui/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QPaintEngine>
#include <QPainter>

#include "grainlab/measures.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/pixel_canvas.h"

namespace grainlab::ui {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRoseBins = 18;
constexpr int kChainBins = 64;         ///< force bins between 0 and the largest force
constexpr int kAreaColourSteps = 128;  ///< colours of void cells by area
constexpr double kRotationSteps = 128; ///< colours of grains per sign of rotation

} // namespace

SceneRenderer::SceneRenderer() = default;

void SceneRenderer::setSnapshot(SnapshotPtr snapshot) {
    snapshot_ = std::move(snapshot);
    coordination_.clear();
    forceMagnitude_.clear();
    forceOrder_.clear();
    chainBins_.clear();
    outlines_.clear();
    voidPolygons_.clear();
    voidBoxes_.clear();
    voidOrder_.clear();
    voidEdges_.clear();
    voidEdgesReady_ = false;
    chainLines_.clear();
    chainLinesFrom_ = 0;
    voidFills_.clear();
    voidFillPoints_.clear();
    voidFillsShading_ = VoidCellShading::Off;
    roseCounts_.fill(0.0);
    maxForce_ = strongThreshold_ = meanVoidArea_ = 0.0;
    if (!snapshot_) {
        return;
    }
    const Snapshot& s = *snapshot_;
    const std::size_t n = s.x1.size();

    // Shapes: size range. Their outlines are built when first drawn (outline()).
    minDiameter_ = 1e300;
    maxDiameter_ = maxHalfWidth_ = 0.0;
    outlines_.assign(s.shapes.size(), {});
    for (const OvalShape& shape : s.shapes) {
        minDiameter_ = std::min(minDiameter_, shape.equivalentDiameter());
        maxDiameter_ = std::max(maxDiameter_, shape.equivalentDiameter());
        maxHalfWidth_ = std::max(maxHalfWidth_, shape.halfWidth);
    }

    // Contacts: coordination, force magnitudes and order, normal rose.
    const auto& contacts = s.network.contacts;
    coordination_.assign(n, 0);
    forceMagnitude_.resize(contacts.size());
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
        maxForce_ = std::max(maxForce_, forceMagnitude_[c]);
        double alpha = std::atan2(r.normal2, r.normal1);
        if (alpha < 0.0) {
            alpha += kPi;
        }
        roseCounts_[std::min(kRoseBins - 1, static_cast<int>(alpha / kPi * kRoseBins))] += 1.0;
    }
    // The engine's rules (measures.h): the load-bearing graph when the snapshot was taken without
    // its measures, and the strong-force threshold f_a.
    if (s.loadBearing.size() == n) {
        loadBearing_ = s.loadBearing;
    } else {
        loadBearing_ = loadBearingGraph(s.network).grainInGraph;
        loadBearing_.resize(n, 0);
    }
    strongThreshold_ = grainlab::strongForceThreshold(s.network, StrongForceThreshold::RmsForce);
    forceOrder_.resize(contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        forceOrder_[c] = static_cast<std::int32_t>(c);
    }
    std::sort(forceOrder_.begin(), forceOrder_.end(),
              [this](int a, int b) { return forceMagnitude_[a] < forceMagnitude_[b]; });
    chainLinesFrom_ = static_cast<std::int32_t>(forceOrder_.size()); // none gathered yet
    // Force bins: runs of forceOrder_ with one pen each, split at the strong threshold so that
    // "strong" draws exactly the contacts above it. The key grows with the force.
    chainBins_.clear();
    auto binKey = [this](std::size_t i) {
        const double f = forceMagnitude_[forceOrder_[i]];
        const int bin =
            maxForce_ > 0.0 ? std::min(kChainBins - 1, int(f / maxForce_ * kChainBins)) : 0;
        return 2 * bin + (f > strongThreshold_ ? 1 : 0);
    };
    for (std::size_t i = 0; i < forceOrder_.size();) {
        const int key = binKey(i);
        double sum = 0.0;
        std::size_t j = i;
        for (; j < forceOrder_.size() && binKey(j) == key; ++j) {
            sum += forceMagnitude_[forceOrder_[j]];
        }
        chainBins_.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j),
                              sum / double(j - i), (key & 1) != 0});
        i = j;
    }

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
    voidOrder_.resize(voidPolygons_.size());
    for (std::size_t v = 0; v < voidOrder_.size(); ++v) {
        voidOrder_[v] = static_cast<std::int32_t>(v);
    }
    std::sort(voidOrder_.begin(), voidOrder_.end(), [this](std::int32_t a, std::int32_t b) {
        return voidBoxes_[a][0] < voidBoxes_[b][0];
    });
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
        // In steps, so that grains of nearly equal rotation share one brush (drawGrains).
        const double r = static_cast<std::size_t>(g) < s.rotation.size() ? s.rotation[g] : 0.0;
        const double t = std::clamp(r / options_.rotationRange, -1.0, 1.0);
        return divergingColour(std::isfinite(t) ? std::round(t * kRotationSteps) / kRotationSteps
                                                : 0.0);
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

QColor SceneRenderer::voidCellColour(int v) const {
    return voidCellShade(v, v == options_.selectedVoidCell ? 200 : kVoidCellAlpha);
}

double SceneRenderer::voidCellScalePosition(double valence, double areaOverMean) const {
    if (options_.voidCells == VoidCellShading::Area) {
        // Log scale: a tenth of the mean area to ten times it, in steps, so that cells of
        // nearly equal area share one brush.
        const double t = std::clamp((std::log10(areaOverMean) + 1.0) / 2.0, 0.0, 1.0);
        return std::isfinite(t) ? std::round(t * (kAreaColourSteps - 1)) / (kAreaColourSteps - 1)
                                : 0.0;
    }
    return std::clamp((valence - 3) / 7.0, 0.0, 1.0);
}

QColor SceneRenderer::voidCellShade(int v, int alpha) const {
    const VoidCellView& cell = snapshot_->voidCells[v];
    const double areaOverMean = meanVoidArea_ > 0.0 ? cell.area / meanVoidArea_ : 1.0;
    QColor fill = sequentialColour(voidCellScalePosition(cell.valence, areaOverMean));
    fill.setAlpha(alpha);
    return fill;
}

QColor SceneRenderer::forceChainColour(double force) const {
    const double relative = maxForce_ > 0.0 ? std::min(1.0, force / maxForce_) : 0.0;
    const double ratio = strongThreshold_ > 0.0 ? force / strongThreshold_ : 0.0;
    return QColor::fromRgbF(float(0.55 + 0.35 * relative), float(0.35 * (1.0 - relative)), 0.05f,
                            float(std::clamp(0.35 + 0.65 * ratio, 0.35, 1.0)));
}

double SceneRenderer::forceChainWidth(double force) const {
    const double meanWidthPixels = minDiameter_ * view_.pixelsPerMetre();
    const double unitWidth = std::max(0.6, 0.07 * meanWidthPixels); // line width at f = f_a
    const double ratio = strongThreshold_ > 0.0 ? force / strongThreshold_ : 0.0;
    return std::clamp(unitWidth * ratio, 0.4, 4.0 * unitWidth);
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
    if (snapshot_ && drawsOverview(p)) {
        const WorldBox box = view_.visibleBox(QSizeF(viewport));
        drawOverview(p, viewport, box);
        drawOverlays(p, viewport, false, true, true);
        return;
    }
    renderBackground(p, viewport);
    if (snapshot_) {
        p.save();
        drawGrains(p, view_.visibleBox(QSizeF(viewport)));
        p.restore();
    }
    renderOverlays(p, viewport, Overlays::All);
}

bool SceneRenderer::drawsOverview(const QPainter& p) const {
    const QPaintEngine* engine = p.paintEngine();
    return engine && engine->type() == QPaintEngine::Raster && p.worldTransform().isIdentity() &&
           maxHalfWidth_ * view_.pixelsPerMetre() <= options_.overviewHalfWidth;
}

void SceneRenderer::drawOverview(QPainter& p, QSize viewport, const WorldBox& box) const {
    // In device pixels: the layer is copied onto the device pixel for pixel. An opaque
    // background makes an opaque layer (RGB32), which Qt copies without blending.
    const double ratio = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    const QSize pixels(static_cast<int>(std::ceil(viewport.width() * ratio)),
                       static_cast<int>(std::ceil(viewport.height() * ratio)));
    const QImage::Format format = options_.background.alpha() == 255
                                      ? QImage::Format_RGB32
                                      : QImage::Format_ARGB32_Premultiplied;
    if (layer_.size() != pixels || layer_.format() != format || !layer_.isDetached()) {
        layer_ = QImage(pixels, format);
    }
    layer_.setDevicePixelRatio(ratio);
    if (format != QImage::Format_RGB32) {
        layer_.fill(Qt::transparent); // the background is blended over what is there
    }
    {
        QPainter lp(&layer_);
        renderBackground(lp, viewport);
    }
    PixelCanvas canvas(layer_, ratio);
    drawGrains(canvas, box);
    drawVoidCellShading(canvas, box);
    p.drawImage(QPointF(0.0, 0.0), layer_);
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

void SceneRenderer::renderOverlays(QPainter& p, QSize viewport, Overlays overlays) const {
    // render() draws the selected grain's outline with the grains.
    drawOverlays(p, viewport, overlays == Overlays::All, overlays == Overlays::All,
                 overlays == Overlays::Annotations);
}

void SceneRenderer::drawOverlays(QPainter& p, QSize viewport, bool voidShading, bool chains,
                                 bool selectedGrain) const {
    if (!snapshot_) {
        return;
    }
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    const WorldBox box = view_.visibleBox(QSizeF(viewport));
    if (selectedGrain) {
        drawSelectedGrainOutline(p, box);
    }
    if (options_.voidCells != VoidCellShading::Off || options_.selectedVoidCell >= 0) {
        drawVoidCells(p, box, voidShading);
    }
    p.setRenderHint(QPainter::Antialiasing, true);
    if (chains && options_.forceChains != ForceChains::Off) {
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
    if (options_.colourKey && options_.voidCells != VoidCellShading::Off) {
        drawColourKey(p, viewport);
    }
    p.restore();
}

} // namespace grainlab::ui
