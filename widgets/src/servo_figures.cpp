// See servo_figures.h.
#include "grainlab/ui/servo_figures.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <QObject>
#include <QPainter>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {
namespace {

QString kPa(double pressure) {
    return QString::number(pressure / 1e3, 'g', 6);
}

} // namespace

HeatMapPainter servoResponseMap(const ServoMapSpec& spec,
                                const std::vector<ServoCellResult>& results, double pressure,
                                double aspectRatio) {
    HeatMapPainter map;
    for (double g : spec.gains) {
        map.xLabels << QString::number(g, 'g', 4);
    }
    for (int n : spec.intervals) {
        map.yLabels << QString::number(n);
    }
    map.xTitle = QObject::tr("servo gain g");
    map.yTitle = QObject::tr("servo interval [steps]");
    map.valueTitle =
        QObject::tr("0 steady, 1 lagging, 2 oscillating, 3 diverging (below: max |error|)");
    map.title = QObject::tr("Lateral stress control in shear at %1 kPa, η = %2")
                    .arg(kPa(pressure), QString::number(aspectRatio, 'g', 3));
    map.min = 0;
    map.max = 3;
    const std::size_t columns = std::size_t(map.xLabels.size());
    const std::size_t n = columns * std::size_t(map.yLabels.size());
    map.values.assign(n, std::nullopt);
    map.notes.resize(n);
    for (const ServoCellResult& r : results) {
        if (r.cell.pressure != pressure || r.cell.aspectRatio != aspectRatio) {
            continue;
        }
        const auto row = std::find(spec.intervals.begin(), spec.intervals.end(), r.cell.interval);
        if (row == spec.intervals.end()) {
            continue;
        }
        for (const ServoRun& run : r.runs) {
            const auto column = std::find(spec.gains.begin(), spec.gains.end(), run.gain);
            if (!run.grid || column == spec.gains.end()) {
                continue;
            }
            const std::size_t i = std::size_t(row - spec.intervals.begin()) * columns +
                                  std::size_t(column - spec.gains.begin());
            map.values[i] = double(int(run.response));
            map.notes[i] = QString("%1 %").arg(QString::number(100 * run.stats.maxError, 'g', 2));
        }
    }
    return map;
}

PlotPainter servoStableGainPlot(const std::vector<ServoCellResult>& results, double gainBound) {
    PlotPainter plot;
    plot.title = QObject::tr("Largest stable gain of the lateral servo (bars: the bracket; open "
                             "at the top: stable up to the largest gain tried)");
    plot.xAxis = {QObject::tr("servo interval [steps]"), true, {}, {}};
    plot.yAxis = {QObject::tr("largest stable gain g"), true, {}, {}};
    std::map<std::pair<double, double>, std::vector<const ServoCellResult*>> curves;
    double largestInterval = 1;
    for (const ServoCellResult& r : results) {
        curves[{r.cell.pressure, r.cell.aspectRatio}].push_back(&r);
        largestInterval = std::max(largestInterval, double(r.cell.interval));
    }
    int index = 0;
    for (auto& [key, cells] : curves) {
        std::sort(cells.begin(), cells.end(),
                  [](const ServoCellResult* a, const ServoCellResult* b) {
                      return a->cell.interval < b->cell.interval;
                  });
        PlotCurve curve;
        curve.colour = categoryColour(index++);
        curve.label =
            QObject::tr("%1 kPa, η = %2").arg(kPa(key.first), QString::number(key.second, 'g', 3));
        for (const ServoCellResult* r : cells) {
            curve.x.push_back(r->cell.interval);
            curve.y.push_back(r->limit.limit);
            PlotPoint p;
            p.x = r->cell.interval;
            p.y = 0.5 * (r->limit.low + r->limit.high);
            p.yError = 0.5 * (r->limit.high - r->limit.low);
            p.colour = curve.colour;
            p.highlighted = !r->limit.bracketed;
            plot.points.push_back(p);
        }
        plot.curves.push_back(std::move(curve));
    }
    plot.curves.push_back(plotLine({1, gainBound}, {largestInterval, gainBound},
                                   QObject::tr("the experiment file's bound, servo.gain ≤ %1")
                                       .arg(QString::number(gainBound, 'g', 3)),
                                   QColor(0, 0, 0), 2.5));
    return plot;
}

QStringList writeServoFigures(const QString& folder, const ServoMapSpec& spec,
                              const std::vector<ServoCellResult>& results, double gainBound,
                              QString* error, const QStringList& formats, QSize size) {
    QStringList written;
    if (!makeFigureFolder(folder, error)) {
        return written;
    }
    for (double p : spec.pressures) {
        for (double eta : spec.aspectRatios) {
            const HeatMapPainter map = servoResponseMap(spec, results, p, eta);
            const QString name =
                QString("response_eta%1_p%2kPa").arg(QString::number(eta, 'g', 6), kPa(p));
            if (!exportFigureFormats(
                    folder, name, formats, size,
                    [&](QPainter& painter, const QRectF& r) { map.paint(painter, r); }, written,
                    error)) {
                return written;
            }
        }
    }
    const PlotPainter plot = servoStableGainPlot(results, gainBound);
    exportFigureFormats(
        folder, "stable_gain", formats, size,
        [&](QPainter& painter, const QRectF& r) { plot.paint(painter, r); }, written, error);
    return written;
}

} // namespace grainlab::ui
