// See plot_view.h.
#include "grainlab/ui/plot_view.h"

#include <QImage>
#include <QMouseEvent>
#include <QPainter>

namespace grainlab::ui {

PlotView::PlotView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(320, 240);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void PlotView::setPlot(PlotPainter plot) {
    plot_ = std::move(plot);
    // The same index may now be another point: hover is re-established by the next move.
    if (hovered_ >= int(plot_.points.size())) {
        setHovered(-1);
    }
    update();
}

QImage PlotView::render() const {
    QImage image(size(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    plot_.paint(painter, plotRect());
    return image;
}

void PlotView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::white);
    painter.setRenderHint(QPainter::Antialiasing);
    plot_.paint(painter, plotRect());
}

void PlotView::mouseMoveEvent(QMouseEvent* event) {
    setHovered(plot_.pointAt(event->position(), plotRect()));
    QWidget::mouseMoveEvent(event);
}

void PlotView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        const int k = plot_.pointAt(event->position(), plotRect());
        if (k >= 0) {
            emit pointClicked(k);
            return;
        }
    }
    QWidget::mousePressEvent(event);
}

void PlotView::leaveEvent(QEvent* event) {
    setHovered(-1);
    QWidget::leaveEvent(event);
}

void PlotView::setHovered(int index) {
    if (index != hovered_) {
        hovered_ = index;
        emit pointHovered(index);
    }
}

} // namespace grainlab::ui
