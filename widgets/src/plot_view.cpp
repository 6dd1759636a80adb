// See plot_view.h.
#include "grainlab/ui/plot_view.h"

#include <QPainter>

namespace grainlab::ui {

PlotView::PlotView(QWidget* parent) : ItemPointerView(parent, -1) {}

void PlotView::setPlot(PlotPainter plot) {
    plot_ = std::move(plot);
    // The same index may now be another point: hover is re-established by the next move.
    if (hovered_ >= int(plot_.points.size())) {
        setHovered(-1);
    }
    update();
}

void PlotView::paintInto(QPainter& painter) const {
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    plot_.paint(painter, plotRect());
}

} // namespace grainlab::ui
