// See stability_figures.h.
#include "grainlab/ui/stability_figures.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <QObject>
#include <QPainter>

#include "grainlab/time_step.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {
namespace {

/// The labels of an axis's values, and which value a result has on it.
QStringList labelsOf(const StabilityMapSpec& spec, StabilityAxis axis) {
    QStringList out;
    switch (axis) {
    case StabilityAxis::AspectRatio:
        for (double v : spec.aspectRatios) {
            out << QString::number(v, 'g', 4);
        }
        break;
    case StabilityAxis::StiffnessRatio:
        for (double v : spec.stiffnessRatios) {
            out << QString::number(v, 'g', 4);
        }
        break;
    case StabilityAxis::Damping:
        for (const DampingParameters& d : spec.dampings) {
            out << QString::fromStdString(dampingLabel(d));
        }
        break;
    case StabilityAxis::Packing:
        for (const PackingState& p : spec.packings) {
            out << QString::fromStdString(packingLabel(p));
        }
        break;
    }
    return out;
}

int indexOn(const StabilityMapSpec& spec, StabilityAxis axis, const StabilityCell& c) {
    const auto find = [](const auto& list, const auto& same) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (same(list[i])) {
                return int(i);
            }
        }
        return -1;
    };
    switch (axis) {
    case StabilityAxis::AspectRatio:
        return find(spec.aspectRatios, [&](double v) { return v == c.aspectRatio; });
    case StabilityAxis::StiffnessRatio:
        return find(spec.stiffnessRatios, [&](double v) { return v == c.stiffnessRatio; });
    case StabilityAxis::Damping:
        return find(spec.dampings, [&](const DampingParameters& d) {
            return d.kind == c.damping.kind && d.coefficient == c.damping.coefficient;
        });
    case StabilityAxis::Packing:
        return find(spec.packings, [&](const PackingState& p) {
            return p.kind == c.packing.kind && p.pressure == c.packing.pressure;
        });
    }
    return -1;
}

/// An axis's names, in StabilityAxis order: in file names, as a figure's title, and brief.
struct AxisNames {
    const char* name;
    const char* title;
    const char* brief;
};
constexpr AxisNames kAxisNames[] = {
    {"aspect_ratio", QT_TRANSLATE_NOOP("QObject", "aspect ratio η = H/W"),
     QT_TRANSLATE_NOOP("QObject", "aspect ratio η")},
    {"stiffness_ratio", QT_TRANSLATE_NOOP("QObject", "stiffness ratio k_t / k_n"),
     QT_TRANSLATE_NOOP("QObject", "stiffness ratio k_t/k_n")},
    {"damping", QT_TRANSLATE_NOOP("QObject", "damping"), QT_TRANSLATE_NOOP("QObject", "damping")},
    {"packing", QT_TRANSLATE_NOOP("QObject", "packing state"),
     QT_TRANSLATE_NOOP("QObject", "packing state")},
};
static_assert(std::size(kAxisNames) == std::size(kStabilityAxes),
              "a name row for every StabilityAxis, in its order");

} // namespace

QString stabilityAxisName(StabilityAxis axis) {
    return kAxisNames[int(axis)].name;
}

QString stabilityAxisTitle(StabilityAxis axis, bool brief) {
    const AxisNames& names = kAxisNames[int(axis)];
    return QObject::tr(brief ? names.brief : names.title);
}

HeatMapPainter stabilityHeatMap(const StabilityMapSpec& spec,
                                const std::vector<StabilityCellResult>& results, StabilityAxis x,
                                StabilityAxis y, StabilityValue value) {
    HeatMapPainter map;
    map.xLabels = labelsOf(spec, x);
    map.yLabels = labelsOf(spec, y);
    map.xTitle = stabilityAxisTitle(x);
    map.yTitle = stabilityAxisTitle(y);
    const bool limit = value == StabilityValue::Limit;
    map.title = limit ? QObject::tr("Largest stable Δt (smallest over the other axes); below: the "
                                    "engine's estimate and its guard")
                      : QObject::tr("Measured limit / the engine's estimate (smallest over the "
                                    "other axes); red: the guard");
    map.valueTitle = limit ? QObject::tr("Δt limit [√(m_min/k_n)]") : QObject::tr("ratio [-]");
    const std::size_t n = std::size_t(map.xLabels.size()) * std::size_t(map.yLabels.size());
    map.values.assign(n, std::nullopt);
    map.notes.resize(n);
    std::vector<std::optional<double>> estimate(n);
    // A square none of whose cells was bracketed is stable up to the bracket's top: a bound,
    // not a measured limit (grey, with the bound written).
    std::vector<std::optional<double>> stableTo(n);
    for (const StabilityCellResult& r : results) {
        const int ix = indexOn(spec, x, r.cell), iy = indexOn(spec, y, r.cell);
        if (ix < 0 || iy < 0 || !(r.estimate > 0)) {
            continue;
        }
        const std::size_t i = std::size_t(iy) * std::size_t(map.xLabels.size()) + std::size_t(ix);
        const double v = limit ? r.limit.limit : r.limit.limit / r.estimate;
        if (!r.limit.bracketed) {
            stableTo[i] = stableTo[i] ? std::min(*stableTo[i], v) : v;
            continue;
        }
        map.values[i] = map.values[i] ? std::min(*map.values[i], v) : v;
        estimate[i] = estimate[i] ? std::min(*estimate[i], r.estimate) : r.estimate;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!map.values[i] && stableTo[i]) {
            map.notes[i] = QObject::tr("stable to %1").arg(QString::number(*stableTo[i], 'g', 3));
        } else if (limit && estimate[i]) {
            // The engine's estimate and the largest step its guard accepts.
            map.notes[i] = QObject::tr("est. %1 · guard %2")
                               .arg(QString::number(*estimate[i], 'g', 3),
                                    QString::number(kTimeStepMargin * *estimate[i], 'g', 3));
        }
    }
    if (!limit) {
        map.mark = kTimeStepMargin; // in units of the estimate, the same in every square
        map.markLabel = QObject::tr("guard");
    }
    return map;
}

int stabilityAxisIndex(const StabilityMapSpec& spec, StabilityAxis axis,
                       const StabilityCell& cell) {
    return indexOn(spec, axis, cell);
}

QStringList writeStabilityFigures(const QString& folder, const StabilityMapSpec& spec,
                                  const std::vector<StabilityCellResult>& results, QString* error,
                                  const QStringList& formats, QSize size) {
    QStringList written;
    if (!makeFigureFolder(folder, error)) {
        return written;
    }
    const auto& axes = kStabilityAxes;
    for (int a = 0; a < 4; ++a) {
        for (int b = a + 1; b < 4; ++b) {
            if (labelsOf(spec, axes[a]).size() < 2 && labelsOf(spec, axes[b]).size() < 2) {
                continue;
            }
            for (StabilityValue value :
                 {StabilityValue::Limit, StabilityValue::LimitOverEstimate}) {
                const HeatMapPainter map = stabilityHeatMap(spec, results, axes[a], axes[b], value);
                const QString name =
                    QString("%1_%2_%3")
                        .arg(value == StabilityValue::Limit ? "limit" : "ratio",
                             stabilityAxisName(axes[a]), stabilityAxisName(axes[b]));
                if (!exportFigureFormats(
                        folder, name, formats, size,
                        [&](QPainter& p, const QRectF& r) { map.paint(p, r); }, written, error)) {
                    return written;
                }
            }
        }
    }
    return written;
}

} // namespace grainlab::ui
