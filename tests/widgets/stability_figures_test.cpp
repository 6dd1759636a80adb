// The time-step map's heat maps show the guard placed on them: the ratio map marks the guard's
// 0.9 of the estimate on its colour bar in red and outlines in red a square measured below it;
// the limit map writes the estimate and the guard's step in each square; a square whose cells
// all held up to the bracket's top is a bound, not a limit (grey, "stable to").
#include <QImage>
#include <QPainter>

#include <gtest/gtest.h>

#include "grainlab/time_step.h"
#include "grainlab/ui/stability_figures.h"

namespace grainlab::ui {
namespace {

StabilityMapSpec twoByTwo() {
    StabilityMapSpec spec;
    spec.aspectRatios = {1.0, 0.6};
    spec.stiffnessRatios = {1.0};
    spec.dampings = {{DampingKind::GlobalViscous, 0.05}};
    spec.packings = {{PackingKind::Gas, 0}, {PackingKind::Dense, 15e3}};
    return spec;
}

StabilityCellResult resultOf(const StabilityCell& cell, double limit, double estimate,
                             bool bracketed) {
    StabilityCellResult r;
    r.cell = cell;
    r.estimate = estimate;
    r.limit.bracketed = bracketed;
    r.limit.limit = r.limit.low = limit;
    r.limit.high = 1.01 * limit;
    return r;
}

QImage render(const HeatMapPainter& map, QSize size) {
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    map.paint(painter, QRectF(QPointF(0, 0), size));
    return image;
}

bool isRed(QColor c) {
    return c.red() > 150 && c.green() < 60 && c.blue() < 60;
}

/// Red pixels along the inside of a square's border, 3 px in.
int redOnTheOutline(const QImage& image, const QRectF& square) {
    int red = 0;
    const QRect r = square.adjusted(3, 3, -3, -3).toRect();
    for (int x = r.left() + 4; x < r.right() - 4; x += 2) {
        red += isRed(image.pixelColor(x, r.top())) + isRed(image.pixelColor(x, r.bottom()));
    }
    return red;
}

TEST(StabilityFigures, TheRatioMapMarksTheGuardAndOutlinesASquareBelowIt) {
    const StabilityMapSpec spec = twoByTwo();
    const std::vector<StabilityCell> cells = stabilityCells(spec);
    ASSERT_EQ(cells.size(), 4u); // eta 1 gas, eta 1 dense, eta 0.6 gas, eta 0.6 dense
    const std::vector<StabilityCellResult> results = {
        resultOf(cells[0], 4.0, 0.58, false), // stable to the bracket's top
        resultOf(cells[1], 0.46, 0.58, true), // 0.79 of the estimate: below the guard
        resultOf(cells[2], 1.2, 0.48, true), resultOf(cells[3], 0.6, 0.48, true), // 1.25
    };
    const HeatMapPainter map =
        stabilityHeatMap(spec, results, StabilityAxis::AspectRatio, StabilityAxis::Packing,
                         StabilityValue::LimitOverEstimate);
    ASSERT_TRUE(map.mark.has_value());
    EXPECT_EQ(*map.mark, kTimeStepMargin);
    // Columns: eta 1, 0.6; rows: gas, dense.
    EXPECT_FALSE(map.values[0].has_value());
    EXPECT_TRUE(map.notes[0].startsWith("stable to 6.9")) << map.notes[0].toStdString();
    EXPECT_NEAR(*map.values[2], 0.46 / 0.58, 1e-12);
    EXPECT_NEAR(*map.values[3], 0.6 / 0.48, 1e-12);

    const QSize size(900, 600);
    const QImage image = render(map, size);
    const QRectF rect(QPointF(0, 0), size);
    EXPECT_GT(redOnTheOutline(image, map.cellRect(0, 1, rect)), 20); // 0.79: outlined
    EXPECT_EQ(redOnTheOutline(image, map.cellRect(1, 1, rect)), 0);  // 1.25: not
    EXPECT_EQ(redOnTheOutline(image, map.cellRect(1, 0, rect)), 0);  // 2.5: not
    // The unbracketed square is grey.
    const QColor grey =
        image.pixelColor(map.cellRect(0, 0, rect).center().toPoint() + QPoint(0, 20));
    EXPECT_EQ(grey, QColor(220, 220, 220));
    // A red line crosses the colour bar (to the right of the grid) somewhere.
    const QRectF lastSquare = map.cellRect(1, 1, rect);
    int redInTheBar = 0;
    for (int y = 0; y < size.height(); ++y) {
        for (int x = int(lastSquare.right()) + 14; x < int(lastSquare.right()) + 36; ++x) {
            redInTheBar += isRed(image.pixelColor(x, y));
        }
    }
    EXPECT_GT(redInTheBar, 15);

    // The limit map writes the estimate and the guard's step.
    const HeatMapPainter limits = stabilityHeatMap(spec, results, StabilityAxis::AspectRatio,
                                                   StabilityAxis::Packing, StabilityValue::Limit);
    EXPECT_FALSE(limits.mark.has_value());
    EXPECT_EQ(limits.notes[3],
              QString("est. 0.48 · guard %1").arg(kTimeStepMargin * 0.48, 0, 'g', 3));
    EXPECT_TRUE(limits.notes[0].startsWith("stable to 4")) << limits.notes[0].toStdString();
}

} // namespace
} // namespace grainlab::ui
