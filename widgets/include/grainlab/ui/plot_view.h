#pragma once
// A widget showing one PlotPainter (plot_painter.h), filling the widget, with hover and click on
// its points: the Study window's error-against-cost chart. It draws what it is given and reports
// which point is under the pointer; what a point means is the caller's business. GUI thread.

#include "grainlab/ui/plot_painter.h"
#include "grainlab/ui/pointer_view.h"

namespace grainlab::ui {

class PlotView : public ItemPointerView<int> {
    Q_OBJECT
public:
    explicit PlotView(QWidget* parent = nullptr);

    void setPlot(PlotPainter plot);
    const PlotPainter& plot() const { return plot_; }
    /// Where the plot is painted (the whole widget), for toPixel() and pointAt().
    QRectF plotRect() const { return QRectF(rect()); }
    /// The point under the pointer, or -1.
    int hoveredPoint() const { return hovered_; }

signals:
    /// The pointer moved onto point `index` of plot(), or off every point (-1).
    void pointHovered(int index);
    /// Point `index` of plot() was clicked with the left button.
    void pointClicked(int index);

protected:
    void paintInto(QPainter& painter) const override;
    int itemAt(QPointF position) const override { return plot_.pointAt(position, plotRect()); }
    void hoveredChanged(int index) override { emit pointHovered(index); }
    void itemClicked(int index) override { emit pointClicked(index); }

private:
    PlotPainter plot_;
};

} // namespace grainlab::ui
