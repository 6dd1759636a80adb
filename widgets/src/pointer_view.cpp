// See pointer_view.h.
#include "grainlab/ui/pointer_view.h"

#include <QMouseEvent>
#include <QPainter>

namespace grainlab::ui {

PointerView::PointerView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setMinimumSize(320, 240);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

QImage PointerView::render() const {
    QImage image(size(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    paintInto(painter);
    return image;
}

void PointerView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    paintInto(painter);
}

void PointerView::mouseMoveEvent(QMouseEvent* event) {
    pointerAt(event->position());
    QWidget::mouseMoveEvent(event);
}

void PointerView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && clickedAt(event->position())) {
        return;
    }
    QWidget::mousePressEvent(event);
}

void PointerView::leaveEvent(QEvent* event) {
    pointerAt(std::nullopt);
    QWidget::leaveEvent(event);
}

} // namespace grainlab::ui
