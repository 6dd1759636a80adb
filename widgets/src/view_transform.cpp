// See view_transform.h.
#include "grainlab/ui/view_transform.h"

#include <algorithm>
#include <cmath>

namespace grainlab::ui {

void ViewTransform::fitCell(const CellMatrix& h, QSizeF viewport, double margin,
                            double worldMargin) {
    // Corners of the cell: 0, first column, second column and their sum.
    const double c1[4] = {0.0, h[0], h[2], h[0] + h[2]};
    const double c2[4] = {0.0, h[1], h[3], h[1] + h[3]};
    const double min1 = *std::min_element(c1, c1 + 4) - worldMargin;
    const double max1 = *std::max_element(c1, c1 + 4) + worldMargin;
    const double min2 = *std::min_element(c2, c2 + 4) - worldMargin;
    const double max2 = *std::max_element(c2, c2 + 4) + worldMargin;
    const double width = std::max(1.0, viewport.width() - 2.0 * margin);
    const double height = std::max(1.0, viewport.height() - 2.0 * margin);
    const double span1 = std::max(max1 - min1, 1e-12), span2 = std::max(max2 - min2, 1e-12);
    scale_ = std::min(width / span2, height / span1);
    originX_ = 0.5 * viewport.width() - scale_ * 0.5 * (min2 + max2);
    originY_ = 0.5 * viewport.height() + scale_ * 0.5 * (min1 + max1);
}

void ViewTransform::zoomAt(QPointF p, double factor) {
    const auto w = toWorld(p);
    scale_ = std::clamp(scale_ * factor, 1.0, 1e9);
    originX_ = p.x() - scale_ * w[1];
    originY_ = p.y() + scale_ * w[0];
}

WorldBox ViewTransform::visibleBox(QSizeF viewport) const {
    const auto topLeft = toWorld(QPointF(0, 0));
    const auto bottomRight = toWorld(QPointF(viewport.width(), viewport.height()));
    return {bottomRight[0], topLeft[0], topLeft[1], bottomRight[1]};
}

} // namespace grainlab::ui
