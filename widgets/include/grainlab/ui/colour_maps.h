#pragma once
// Colour scales for the scene and the charts: a perceptually ordered sequential map, a diverging
// map for signed quantities, a qualitative palette for categories and for overlaid tests. Pure
// functions, any thread.

#include <QColor>

namespace grainlab::ui {

/// Sequential map (dark blue -> green -> yellow) at t in [0, 1] (clamped).
QColor sequentialColour(double t);
/// Diverging map (blue -> near white -> red) at t in [-1, 1] (clamped).
QColor divergingColour(double t);
/// Qualitative palette, cycling; distinct colours for categories and for tests in a chart.
QColor categoryColour(int index);
/// `colour` mixed with white by `amount` in [0, 1].
QColor lighter(const QColor& colour, double amount);

} // namespace grainlab::ui
