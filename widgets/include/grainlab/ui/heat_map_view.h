#pragma once
// A widget showing one HeatMapPainter (heat_map_painter.h), filling the widget, with hover and
// click on its cells and an outline on a chosen cell: the Stability view's map. It draws what it
// is given and reports which cell is under the pointer; what a cell means is the caller's
// business. GUI thread.

#include <QPoint>

#include "grainlab/ui/heat_map_painter.h"
#include "grainlab/ui/pointer_view.h"

namespace grainlab::ui {

class HeatMapView : public ItemPointerView<QPoint> {
    Q_OBJECT
public:
    explicit HeatMapView(QWidget* parent = nullptr);

    void setMap(HeatMapPainter map);
    const HeatMapPainter& map() const { return map_; }
    /// Where the map is painted (the whole widget), for HeatMapPainter::cellRect().
    QRectF mapRect() const { return QRectF(rect()); }
    /// The cell (column, row) at `position`, or (-1, -1) outside the grid.
    QPoint cellAt(QPointF position) const;
    /// The cell under the pointer, or (-1, -1).
    QPoint hoveredCell() const { return hovered_; }
    /// Outlines cell (column, row); (-1, -1): none.
    void setSelectedCell(QPoint cell);
    QPoint selectedCell() const { return selected_; }

signals:
    /// The pointer moved onto cell (column, row), or off the grid ((-1, -1)).
    void cellHovered(QPoint cell);
    /// Cell (column, row) was clicked with the left button.
    void cellClicked(QPoint cell);

protected:
    void paintInto(QPainter& painter) const override;
    QPoint itemAt(QPointF position) const override { return cellAt(position); }
    void hoveredChanged(QPoint cell) override { emit cellHovered(cell); }
    void itemClicked(QPoint cell) override { emit cellClicked(cell); }

private:
    HeatMapPainter map_;
    QPoint selected_{-1, -1};
};

} // namespace grainlab::ui
