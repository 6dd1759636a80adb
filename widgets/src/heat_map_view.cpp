// See heat_map_view.h.
#include "grainlab/ui/heat_map_view.h"

#include <QPainter>

namespace grainlab::ui {
namespace {

const QPoint kNoCell(-1, -1);

} // namespace

HeatMapView::HeatMapView(QWidget* parent) : ItemPointerView(parent, kNoCell) {}

void HeatMapView::setMap(HeatMapPainter map) {
    map_ = std::move(map);
    // The grid may have changed shape: a cell outside it is no longer hovered or chosen.
    const auto inside = [this](QPoint c) {
        return c.x() >= 0 && c.y() >= 0 && c.x() < map_.xLabels.size() &&
               c.y() < map_.yLabels.size();
    };
    if (!inside(selected_)) {
        selected_ = kNoCell;
    }
    if (!inside(hovered_)) {
        setHovered(kNoCell);
    }
    update();
}

QPoint HeatMapView::cellAt(QPointF position) const {
    for (int y = 0; y < map_.yLabels.size(); ++y) {
        for (int x = 0; x < map_.xLabels.size(); ++x) {
            if (map_.cellRect(x, y, mapRect()).contains(position)) {
                return {x, y};
            }
        }
    }
    return kNoCell;
}

void HeatMapView::setSelectedCell(QPoint cell) {
    if (cell != selected_) {
        selected_ = cell;
        update();
    }
}

void HeatMapView::paintInto(QPainter& painter) const {
    map_.paint(painter, mapRect());
    if (selected_ != kNoCell) {
        // Inside the cell's white border, so that the fill stays visible around the text.
        const QRectF c =
            map_.cellRect(selected_.x(), selected_.y(), mapRect()).adjusted(2.5, 2.5, -2.5, -2.5);
        painter.setPen(QPen(Qt::black, 3));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(c);
    }
}

} // namespace grainlab::ui
