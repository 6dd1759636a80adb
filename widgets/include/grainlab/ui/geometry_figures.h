#pragma once
// The figure of a contact-geometry map (geometry_map.h): the largest departure of a kernel's
// overlap from the exact overlap against the overlap, both as fractions of the smaller width,
// one curve per aspect ratio and size ratio for the engine's pair loop and, lighter, for the
// engine without its 0.1 W hand-over to the 16 arc pairs; the departure tolerance and the engine's
// overlap guard drawn across it. For `grainlab stability` (headless) and a window. GUI thread, or
// any thread with a Qt application for fonts.

#include <vector>

#include <QSize>
#include <QStringList>

#include "grainlab/geometry_map.h"
#include "grainlab/ui/plot_painter.h"

namespace grainlab::ui {

/// Departures of exactly zero are drawn at this floor (the plot is logarithmic) [-].
inline constexpr double kGeometryDepartureFloor = 1e-17;

/// The departure plot; `guard` the engine's overlap guard (a fraction of the smaller width).
PlotPainter geometryDeparturePlot(const GeometryMapSpec& spec,
                                  const std::vector<GeometryLevel>& levels, double guard);

/// Writes departure.<format> into `folder`; returns the files written.
QStringList writeGeometryFigures(const QString& folder, const GeometryMapSpec& spec,
                                 const std::vector<GeometryLevel>& levels, double guard,
                                 QString* error = nullptr,
                                 const QStringList& formats = {"png", "svg"},
                                 QSize size = {1000, 700});

} // namespace grainlab::ui
