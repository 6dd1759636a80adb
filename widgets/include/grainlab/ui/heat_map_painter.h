#pragma once
// A heat map drawn with QPainter: a grid of cells over two categorical axes, each cell coloured
// by its value on the sequential colour map (colour_maps.h) and labelled with its value and an
// optional second line (e.g. the estimate it is compared with), with a colour bar. A plot kind
// beside plot_painter.h; the same painting serves a widget and exportFigure(). A value type:
// build it, then paint() it, on the GUI thread or any thread that owns its painter.

#include <optional>
#include <vector>

#include <QColor>
#include <QRectF>
#include <QString>
#include <QStringList>

class QPainter;

namespace grainlab::ui {

class HeatMapPainter {
public:
    QString title;
    QString xTitle, yTitle; ///< axis titles
    QString valueTitle;     ///< the colour bar's title
    QStringList xLabels, yLabels;
    /// Row-major values, yLabels.size() rows of xLabels.size(); unset: no data (drawn grey).
    std::vector<std::optional<double>> values;
    std::vector<QString> notes;     ///< a second line per cell (empty: none); same layout
    std::optional<double> min, max; ///< the colour scale; unset: from the values
    /// A value marked on the colour bar (a red line and its label), e.g. a guard; the scale
    /// reaches down or up to it, and squares whose value is below it are outlined in red.
    std::optional<double> mark;
    QString markLabel;

    /// Draws the map filling `rect`.
    void paint(QPainter& painter, const QRectF& rect) const;
    /// The rectangle of cell (column x, row y) as paint() draws it in `rect` (row 0 at the
    /// bottom, as on a y axis).
    QRectF cellRect(int x, int y, const QRectF& rect) const;
    /// The colour paint() fills a cell of value `v` with.
    QColor colourOf(double v) const;

private:
    QRectF gridArea(const QRectF& rect) const;
    std::pair<double, double> scale() const;
};

} // namespace grainlab::ui
