#pragma once
// What the plot-like views (HeatMapView, PlotView) share: a widget that a painter fills, at least
// 320 × 240 px, rendered to an image as on screen, with the pointer's moves, its leaving and the
// left button's clicks handed to the view, which says what lies under the pointer (a cell, a
// point). GUI thread.

#include <optional>

#include <QImage>
#include <QPointF>
#include <QWidget>

class QPainter;

namespace grainlab::ui {

class PointerView : public QWidget {
public:
    explicit PointerView(QWidget* parent = nullptr);

    /// What is drawn, at the widget's size, on white.
    QImage render() const;

protected:
    /// Draws the view onto `painter` (the widget's, or render()'s image).
    virtual void paintInto(QPainter& painter) const = 0;
    /// The pointer moved to `position` in the widget, or left it (nullopt).
    virtual void pointerAt(std::optional<QPointF> position) = 0;
    /// The left button was clicked at `position`: true when it was on something (the click is
    /// the view's, not passed on).
    virtual bool clickedAt(QPointF position) = 0;

    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
};

/// A PointerView whose pointer is on an `Item` (a cell, a point's index) or on none (`none`):
/// the item under the pointer is kept, and a change of it and a left click on an item are
/// handed to the view (which emits its signals).
template <class Item>
class ItemPointerView : public PointerView {
protected:
    ItemPointerView(QWidget* parent, Item none)
        : PointerView(parent), none_(none), hovered_(none) {}

    /// The item at `position`, or none.
    virtual Item itemAt(QPointF position) const = 0;
    /// The pointer moved onto `item` (or off every item: none).
    virtual void hoveredChanged(Item item) = 0;
    /// `item` was clicked with the left button.
    virtual void itemClicked(Item item) = 0;

    void pointerAt(std::optional<QPointF> position) final {
        setHovered(position ? itemAt(*position) : none_);
    }
    bool clickedAt(QPointF position) final {
        const Item item = itemAt(position);
        if (item == none_) {
            return false;
        }
        itemClicked(item);
        return true;
    }
    void setHovered(Item item) {
        if (item != hovered_) {
            hovered_ = item;
            hoveredChanged(item);
        }
    }

    const Item none_;
    Item hovered_;
};

} // namespace grainlab::ui
