// See geometry_figures.h.
#include "grainlab/ui/geometry_figures.h"

#include <algorithm>

#include <QObject>
#include <QPainter>

#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"

namespace grainlab::ui {

PlotPainter geometryDeparturePlot(const GeometryMapSpec& spec,
                                  const std::vector<GeometryLevel>& levels, double guard) {
    PlotPainter plot;
    plot.title = QObject::tr("Contact geometry: largest |overlap − exact| against the overlap "
                             "(0 drawn at %1)")
                     .arg(kGeometryDepartureFloor);
    plot.xAxis = {QObject::tr("exact overlap / smaller width"), true, {}, {}};
    plot.yAxis = {
        QObject::tr("largest departure / smaller width"), true, kGeometryDepartureFloor / 2, {}};
    int index = 0;
    double top = spec.tolerance;
    for (double eta : spec.aspectRatios) {
        for (double ratio : spec.sizeRatios) {
            const QColor colour = categoryColour(index++);
            for (GeometryKernel kernel : {GeometryKernel::Engine, GeometryKernel::FourPair}) {
                PlotCurve curve;
                const bool engine = kernel == GeometryKernel::Engine;
                curve.colour = engine ? colour : lighter(colour, 0.55);
                curve.width = engine ? 2.0 : 1.0;
                curve.label = QObject::tr("η = %1, W_B/W_A = %2, %3")
                                  .arg(QString::number(eta, 'g', 3), QString::number(ratio, 'g', 3),
                                       engine ? QObject::tr("engine")
                                              : QObject::tr("4 facing pairs at any overlap"));
                for (const GeometryLevel& l : levels) {
                    if (l.aspectRatio != eta || l.sizeRatio != ratio || l.pairs == 0) {
                        continue;
                    }
                    const double d = l.kernels[int(kernel)].maxDeparture;
                    curve.x.push_back(l.overlap);
                    curve.y.push_back(std::max(d, kGeometryDepartureFloor));
                    top = std::max(top, d);
                }
                plot.curves.push_back(std::move(curve));
            }
        }
    }
    const double left = spec.overlaps.front(), right = spec.overlaps.back();
    plot.curves.push_back(plotLine({left, spec.tolerance}, {right, spec.tolerance},
                                   QObject::tr("departure tolerance %1 W").arg(spec.tolerance),
                                   QColor(90, 90, 90)));
    plot.curves.push_back(
        plotLine({guard, kGeometryDepartureFloor}, {guard, top},
                 QObject::tr("overlap guard, stability.max_overlap_fraction = %1").arg(guard),
                 QColor(0, 0, 0), 2.5));
    return plot;
}

QStringList writeGeometryFigures(const QString& folder, const GeometryMapSpec& spec,
                                 const std::vector<GeometryLevel>& levels, double guard,
                                 QString* error, const QStringList& formats, QSize size) {
    QStringList written;
    if (!makeFigureFolder(folder, error)) {
        return written;
    }
    const PlotPainter plot = geometryDeparturePlot(spec, levels, guard);
    exportFigureFormats(
        folder, "departure", formats, size, [&](QPainter& p, const QRectF& r) { plot.paint(p, r); },
        written, error);
    return written;
}

} // namespace grainlab::ui
