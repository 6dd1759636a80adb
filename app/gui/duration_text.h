#pragma once
// A duration for people: "42 s", "3 min 5 s", "2 h 10 min"; "–" when unknown (negative or not
// finite). Used by the window's and the Study window's ETA. Any thread.

#include <cmath>

#include <QString>

namespace grainlab::ui {

inline QString formatDuration(double seconds) {
    if (seconds < 0.0 || !std::isfinite(seconds)) {
        return QStringLiteral("–");
    }
    const auto s = static_cast<qint64>(seconds + 0.5);
    if (s >= 3600) {
        return QStringLiteral("%1 h %2 min").arg(s / 3600).arg((s % 3600) / 60);
    }
    if (s >= 60) {
        return QStringLiteral("%1 min %2 s").arg(s / 60).arg(s % 60);
    }
    return QStringLiteral("%1 s").arg(s);
}

} // namespace grainlab::ui
