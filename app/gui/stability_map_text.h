#pragma once
// The words of the Stability view (stability_view.h): a map cell's numbers as the HTML of its
// side panel, and what a `grainlab stability` process wrote to its log: its summary and errors
// (with the last line of a failed cell's own log) and its last progress line. Plain functions
// of a result or a log file. GUI thread (the logs are small files).

#include <QString>

#include "grainlab/stability_map.h"

namespace grainlab::ui {

/// The cell's id, axes, limit (and in seconds), bracket, detector, estimate and its parts, the
/// ratio, the accuracy runs' residuals, whether compaction calmed, its wall time; HTML.
QString stabilityCellNumbers(const StabilityCellResult& r);
/// What the map said in `logPath` (its summary line, an error, the failed cells each with the
/// last line of its log), not its opening or progress lines; the last 8 such lines.
QString stabilityLogSummary(const QString& logPath);
/// The map's last progress line in `logPath` in words ("" when there is none yet).
QString stabilityLogProgress(const QString& logPath);

} // namespace grainlab::ui
