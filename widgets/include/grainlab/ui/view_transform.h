#pragma once
// The map between world coordinates of the periodic cell and screen pixels. x1 (axial) points up
// on screen, x2 (lateral) to the right; one uniform scale, so grains keep their true shape. Plain
// value type used by SceneRenderer and SceneView on the GUI thread (or any thread that renders).

#include <array>

#include <QPointF>
#include <QSizeF>

#include "grainlab/periodic_cell.h"

namespace grainlab::ui {

/// An axis-aligned box in world coordinates [m].
struct WorldBox {
    double min1 = 0, max1 = 0; ///< along x1
    double min2 = 0, max2 = 0; ///< along x2

    bool intersectsCircle(double c1, double c2, double radius) const {
        return c1 + radius >= min1 && c1 - radius <= max1 && c2 + radius >= min2 &&
               c2 - radius <= max2;
    }
};

class ViewTransform {
public:
    /// Scales and centres the view so that the whole cell, grown by `worldMargin` [m] on every
    /// side, fits the viewport with a margin of `marginPixels`.
    void fitCell(const CellMatrix& cell, QSizeF viewport, double marginPixels = 16.0,
                 double worldMargin = 0.0);

    QPointF toScreen(double x1, double x2) const {
        return {originX_ + scale_ * x2, originY_ - scale_ * x1};
    }
    /// World point (x1, x2) [m] under a screen point.
    std::array<double, 2> toWorld(QPointF p) const {
        return {(originY_ - p.y()) / scale_, (p.x() - originX_) / scale_};
    }
    /// Multiplies the scale by `factor`, keeping the world point under `screenPoint` fixed.
    void zoomAt(QPointF screenPoint, double factor);
    void panBy(QPointF deltaPixels) {
        originX_ += deltaPixels.x();
        originY_ += deltaPixels.y();
    }
    double pixelsPerMetre() const { return scale_; }
    /// The world box seen through a viewport of this size.
    WorldBox visibleBox(QSizeF viewport) const;

private:
    double scale_ = 1e4;   ///< [pixel/m]
    double originX_ = 0.0; ///< screen position of the world origin [pixel]
    double originY_ = 0.0;
};

} // namespace grainlab::ui
