#pragma once
// A widget showing one PlotPainter (plot_painter.h), filling the widget, with hover and click on
// its points: the Study window's error-against-cost chart. It draws what it is given and reports
// which point is under the pointer; what a point means is the caller's business. GUI thread.

#include <QWidget>

#include "grainlab/ui/plot_painter.h"

namespace grainlab::ui {

class PlotView : public QWidget {
    Q_OBJECT
public:
    explicit PlotView(QWidget* parent = nullptr);

    void setPlot(PlotPainter plot);
    const PlotPainter& plot() const { return plot_; }
    /// Where the plot is painted (the whole widget), for toPixel() and pointAt().
    QRectF plotRect() const { return QRectF(rect()); }
    /// The point under the pointer, or -1.
    int hoveredPoint() const { return hovered_; }
    /// The plot as drawn at the widget's size.
    QImage render() const;

signals:
    /// The pointer moved onto point `index` of plot(), or off every point (-1).
    void pointHovered(int index);
    /// Point `index` of plot() was clicked with the left button.
    void pointClicked(int index);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void setHovered(int index);

    PlotPainter plot_;
    int hovered_ = -1;
};

} // namespace grainlab::ui
