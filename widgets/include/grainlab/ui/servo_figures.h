#pragma once
// The figures of a servo map (servo_map.h): for each confining pressure and shape, a heat map of
// the lateral servo's response over gain and interval (steady, lagging, oscillating, diverging,
// with the largest error after the transient written in each cell), and one line figure of the
// largest stable gain against the interval for every pressure and shape, with the experiment
// reader's bound on the gain drawn across it. For `grainlab stability collect` (headless) and a
// window. GUI thread, or any thread with a Qt application for fonts.

#include <vector>

#include <QSize>
#include <QStringList>

#include "grainlab/servo_map.h"
#include "grainlab/ui/heat_map_painter.h"
#include "grainlab/ui/plot_painter.h"

namespace grainlab::ui {

/// The response over gain (x) and interval (y) of the cells at `pressure` and `aspectRatio`:
/// value 0 steady, 1 lagging, 2 oscillating, 3 diverging; the note the largest |error| [%].
HeatMapPainter servoResponseMap(const ServoMapSpec& spec,
                                const std::vector<ServoCellResult>& results, double pressure,
                                double aspectRatio);

/// The largest stable gain against the interval (the bracket as error bars), one curve per
/// pressure and shape; `gainBound` the reader's bound, drawn as a line.
PlotPainter servoStableGainPlot(const std::vector<ServoCellResult>& results, double gainBound);

/// Writes response_eta<eta>_p<kPa>kPa for every pressure and shape, and stable_gain, in each
/// of `formats`, into `folder`; returns the files written, stops at the first failure.
QStringList writeServoFigures(const QString& folder, const ServoMapSpec& spec,
                              const std::vector<ServoCellResult>& results, double gainBound,
                              QString* error = nullptr, const QStringList& formats = {"png", "svg"},
                              QSize size = {1000, 700});

} // namespace grainlab::ui
