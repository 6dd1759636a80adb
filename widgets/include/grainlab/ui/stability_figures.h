#pragma once
// The figures of a stability map (stability_map.h) as heat maps (heat_map_painter.h): over each
// pair of the map's axes, the measured limit of the time step in units of sqrt(m_min / k_n),
// with the engine's estimate written in each cell, and the ratio of the two. Each cell of a
// pair shows the smallest value over the other two axes (the step that is safe for all of
// them). For `grainlab stability collect` (headless) and a window. GUI thread, or any thread
// with a Qt application for fonts.

#include <vector>

#include <QSize>
#include <QStringList>

#include "grainlab/stability_map.h"
#include "grainlab/ui/heat_map_painter.h"

namespace grainlab::ui {

enum class StabilityAxis { AspectRatio, StiffnessRatio, Damping, Packing };
/// The four axes, in that order.
inline constexpr StabilityAxis kStabilityAxes[] = {StabilityAxis::AspectRatio,
                                                   StabilityAxis::StiffnessRatio,
                                                   StabilityAxis::Damping, StabilityAxis::Packing};
/// "aspect_ratio", "stiffness_ratio", "damping", "packing".
QString stabilityAxisName(StabilityAxis axis);
/// The axis's title in the figures ("aspect ratio η = H/W"), or, `brief`, as the Stability view
/// names it ("aspect ratio η").
QString stabilityAxisTitle(StabilityAxis axis, bool brief = false);

enum class StabilityValue {
    Limit,            ///< measured limit [sqrt(m_min / k_n)], the estimate as a note
    LimitOverEstimate ///< measured limit / the engine's estimate [-]
};

/// The heat map of `value` over axes `x` and `y`: the minimum over the other axes.
HeatMapPainter stabilityHeatMap(const StabilityMapSpec& spec,
                                const std::vector<StabilityCellResult>& results, StabilityAxis x,
                                StabilityAxis y, StabilityValue value);
/// The index of `cell`'s value among the spec's values on `axis`: its column (or row) in
/// stabilityHeatMap() over that axis; -1 when the spec has no such value.
int stabilityAxisIndex(const StabilityMapSpec& spec, StabilityAxis axis, const StabilityCell& cell);

/// Writes limit_<x>_<y> and ratio_<x>_<y> for every pair of axes with more than one value on
/// either, in each of `formats`, into `folder`; returns the files written, stops at the first
/// failure setting `error`.
QStringList writeStabilityFigures(const QString& folder, const StabilityMapSpec& spec,
                                  const std::vector<StabilityCellResult>& results,
                                  QString* error = nullptr,
                                  const QStringList& formats = {"png", "svg"},
                                  QSize size = {1000, 700});

} // namespace grainlab::ui
