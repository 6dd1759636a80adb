// See figure_export.h.
#include "grainlab/ui/figure_export.h"

#include <QGuiApplication>

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSvgGenerator>

#include "grainlab/csv_series.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/scene_view.h"

namespace grainlab::ui {

std::unique_ptr<QGuiApplication> headlessApplicationIfNone() {
    if (QCoreApplication::instance()) {
        return nullptr;
    }
    qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "grainlab";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}
namespace {

bool fail(QString* error, const QString& message) {
    if (error) {
        *error = message;
    }
    return false;
}

/// Paints the figure on `device` (an SVG or PDF file): false, with `cannotWrite` in `error`,
/// when the painter cannot begin on it.
bool paintOnto(QPaintDevice& device, QSize size, const std::function<void(QPainter&, QSize)>& paint,
               const QString& cannotWrite, QString* error) {
    QPainter painter;
    if (!painter.begin(&device)) {
        return fail(error, cannotWrite);
    }
    paint(painter, size);
    painter.end();
    return true;
}

} // namespace

bool exportFigure(const QString& path, QSize size,
                  const std::function<void(QPainter&, QSize)>& paint, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (size.isEmpty()) {
        return fail(error, QObject::tr("%1: empty figure size").arg(path));
    }
    if (suffix == QLatin1String("png")) {
        QImage image(size, QImage::Format_ARGB32);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            paint(painter, size);
        }
        if (!image.save(path, "PNG")) {
            return fail(error, QObject::tr("%1: cannot write the PNG file").arg(path));
        }
        return true;
    }
    if (suffix == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(QFileInfo(path).baseName());
        svg.setDescription(QStringLiteral("GrainLab figure"));
        if (!paintOnto(svg, size, paint, QObject::tr("%1: cannot write the SVG file").arg(path),
                       error)) {
            return false;
        }
        return QFileInfo(path).size() > 0 ||
               fail(error, QObject::tr("%1: the SVG file is empty").arg(path));
    }
    if (suffix == QLatin1String("pdf")) {
        // One device pixel per point: the page is `size` points.
        QPdfWriter pdf(path);
        pdf.setResolution(72);
        pdf.setPageSize(
            QPageSize(QSizeF(size), QPageSize::Point, QString(), QPageSize::ExactMatch));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setTitle(QFileInfo(path).baseName());
        pdf.setCreator(QStringLiteral("GrainLab"));
        return paintOnto(pdf, size, paint, QObject::tr("%1: cannot write the PDF file").arg(path),
                         error);
    }
    return fail(
        error,
        QObject::tr("%1: unknown figure format '%2' (use png, svg or pdf)").arg(path, suffix));
}

bool exportFigureFormats(const QString& folder, const QString& name, const QStringList& formats,
                         QSize size, const std::function<void(QPainter&, const QRectF&)>& paint,
                         QStringList& written, QString* error) {
    for (const QString& format : formats) {
        const QString path = QDir(folder).filePath(name + "." + format);
        if (!exportFigure(
                path, size, [&](QPainter& p, QSize s) { paint(p, QRectF(QPointF(0, 0), s)); },
                error)) {
            return false;
        }
        written << path;
    }
    return true;
}

bool makeFigureFolder(const QString& folder, QString* error) {
    return QDir().mkpath(folder) ||
           fail(error, QObject::tr("%1: cannot create the folder").arg(folder));
}

bool exportScene(const SceneView& view, const QString& path, QSize size, QString* error) {
    // A copy of the renderer, so that the view on screen is not disturbed.
    SceneRenderer renderer = view.renderer();
    if (view.size().width() > 0) {
        renderer.view().zoomAt(QPointF(0, 0), double(size.width()) / view.size().width());
    }
    return exportFigure(
        path, size,
        [&renderer](QPainter& painter, QSize target) { renderer.render(painter, target); }, error);
}

QStringList exportFigureSet(const QString& folder, const SceneView* scene,
                            const ChartsPanel* charts, const std::vector<SeriesTable>& series,
                            const FigureSetOptions& options, QString* error) {
    QStringList written;
    if (!makeFigureFolder(folder, error)) {
        return written;
    }
    const QDir dir(folder);
    for (const QString& format : options.formats) {
        if (scene) {
            const QString path = dir.filePath(QStringLiteral("scene.") + format);
            if (!exportScene(*scene, path, options.sceneSize, error)) {
                return written;
            }
            written << path;
        }
        for (int k = 0; charts && k < charts->chartCount(); ++k) {
            if (charts->definition(k).derived != ChartDefinition::Derived::None &&
                !charts->hasCurves(k)) {
                continue; // the cycles' or the probes' chart of a run without such a test
            }
            const QString path =
                dir.filePath(charts->definition(k).name + QLatin1Char('.') + format);
            if (!charts->exportChart(k, path, options.chartSize, error)) {
                return written;
            }
            written << path;
        }
    }
    if (options.csv) {
        for (const SeriesTable& table : series) {
            const QString path = dir.filePath(QString::fromStdString(table.test) + ".csv");
            try {
                writeSeriesCsv(table, path.toStdString());
            } catch (const std::exception& e) {
                fail(error, QString::fromStdString(e.what()));
                return written;
            }
            written << path;
        }
    }
    return written;
}

} // namespace grainlab::ui
