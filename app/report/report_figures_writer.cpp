#include "report/report_figures_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include <QDir>
#include <QGuiApplication>
#include <QPainter>

#include <fmt/format.h>

#include "common/atomic_file.h"
#include "common/run_file_view.h"
#include "grainlab/run_file.h"
#include "grainlab/shear_metrics.h"
#include "grainlab/ui/colour_maps.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/plot_painter.h"
#include "grainlab/ui/scene_renderer.h"
#include "report/report_page.h"

namespace grainlab {
namespace fs = std::filesystem;
namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

/// A copy of `v` with every value times `scale`.
std::vector<double> scaled(std::vector<double> v, double scale) {
    for (double& x : v) {
        x *= scale;
    }
    return v;
}

} // namespace

/// The figure drawn in its axes' units (ReportFigure::xScale, yScale: ε1 in percent, q in kPa).
ui::PlotPainter reportPlot(const ReportFigure& f) {
    ui::PlotPainter plot;
    plot.title = q(f.title);
    plot.xAxis.title = q(f.xLabel);
    plot.yAxis.title = q(f.yLabel);
    int colour = 0;
    double lo = 0, hi = 0;
    bool any = false;
    for (const ReportLine& line : f.lines) {
        const QColor c = ui::categoryColour(colour++);
        for (double x : line.x) { // the fit spans the points and the curves alike
            lo = any ? std::min(lo, x) : x;
            hi = any ? std::max(hi, x) : x;
            any = true;
        }
        if (line.points) {
            for (std::size_t k = 0; k < line.x.size(); ++k) {
                ui::PlotPoint p;
                p.x = line.x[k] * f.xScale;
                p.y = line.y[k] * f.yScale;
                p.yError = line.sd[k] * f.yScale;
                p.label = QString::number(p.x, 'g', 3);
                p.colour = c;
                plot.points.push_back(p);
            }
            continue;
        }
        ui::PlotCurve curve;
        curve.x = scaled(line.x, f.xScale);
        curve.y = scaled(line.y, f.yScale);
        if (f.bands) {
            curve.band = scaled(line.sd, f.yScale);
        }
        curve.label = q(line.label);
        curve.colour = c;
        plot.curves.push_back(std::move(curve));
    }
    if (f.fit && any) {
        ui::PlotCurve fit;
        fit.x = {lo * f.xScale, hi * f.xScale};
        fit.y = {(f.fit->slope * lo + f.fit->intercept) * f.yScale,
                 (f.fit->slope * hi + f.fit->intercept) * f.yScale};
        fit.label = q(f.fitLabel.empty() ? fitEquation(*f.fit) : f.fitLabel);
        fit.colour = QColor(30, 30, 30);
        fit.width = 2.0;
        plot.curves.push_back(std::move(fit));
    }
    return plot;
}

namespace {

bool save(const QString& folder, const QString& name, QSize size,
          const std::function<void(QPainter&, QSize)>& paint, QString* error) {
    for (const char* format : {"png", "svg", "pdf"}) {
        if (!ui::exportFigure(QDir(folder).filePath(name + "." + format), size, paint, error)) {
            return false;
        }
    }
    return true;
}

/// Figure 5 from the first run's checkpoints: the shear checkpoint nearest eps1 = 0, the one at
/// the peak of q/p (nearest to it when the file has no peak checkpoint) and the one nearest
/// eps1 = 10 %, for the lowest and highest pressure. Writes `<stem>.csv` beside each picture:
/// the cells drawn (valence, area, centroid).
bool writeVoidCellPictures(const QString& folder, const std::vector<ReportFigure>& figures,
                           const std::vector<ReportSource>& sources, QString* error) {
    if (sources.empty() || figures.empty()) {
        return true;
    }
    std::vector<std::string> tests;
    for (const ReportLine& l : figures.front().lines) {
        tests.push_back(l.test);
    }
    const std::vector<std::string> stems = voidCellPictureNames(tests);
    const std::string runFile = (fs::path(sources.front().folder) / "run.h5").string();
    const ui::RunFileView file = ui::openRunFile(runFile);
    const std::string prefix = fs::path(runFile).filename().string() + ": ";
    for (const std::string& stem : stems) {
        // stem: 05_<test>_<start|peak|10pc>
        const std::size_t cut = stem.rfind('_');
        const std::string test = stem.substr(3, cut - 3), at = stem.substr(cut + 1);
        double eps1 = 0;
        if (at == "10pc") {
            eps1 = 0.10;
        } else if (at == "peak") {
            for (const SeriesTable& t : file.series) {
                if (t.test == prefix + test) {
                    eps1 = shearMetrics(t, 0).peakAxialStrain.value_or(0);
                }
            }
        }
        const int index = ui::nearestCheckpoint(file, prefix + test, eps1);
        if (index < 0) {
            continue; // the run holds no checkpoint of this test
        }
        const SnapshotPtr snapshot = ui::runFileSnapshot(file, std::size_t(index));
        ui::SceneRenderer renderer;
        renderer.options().voidCells = ui::VoidCellShading::Valence;
        renderer.options().colouring = ui::GrainColouring::Uniform;
        renderer.setSnapshot(snapshot);
        const QSize size(1000, 1000);
        renderer.fitToCell(size);
        if (!save(
                folder, q(stem), size, [&](QPainter& p, QSize s) { renderer.render(p, s); },
                error)) {
            return false;
        }
        std::string csv = "valence [-],area [m^2],centroid1 [m],centroid2 [m]\n";
        for (const VoidCellView& c : snapshot->voidCells) {
            csv += fmt::format("{},{:.9g},{:.9g},{:.9g}\n", c.valence, c.area, c.centroid1,
                               c.centroid2);
        }
        // Throws naming the file; the caller reports it.
        writeFileAtomically(QDir(folder).filePath(q(stem) + ".csv").toStdString(), csv);
    }
    return true;
}

} // namespace

std::string writeReportFiguresHeadless(const std::string& folder,
                                       const std::vector<ReportFigure>& figures,
                                       const std::vector<ReportSource>& sources) {
    const auto app = ui::headlessApplicationIfNone();
    QString error;
    const QString dir = q(folder);
    if (!QDir().mkpath(dir)) {
        return folder + ": cannot create the folder";
    }
    for (const ReportFigure& f : figures) {
        const ui::PlotPainter plot = reportPlot(f);
        if (!save(
                dir, q(f.name), QSize(1000, 700),
                [&](QPainter& p, QSize s) { plot.paint(p, QRectF(QPointF(0, 0), s)); }, &error)) {
            return error.toStdString();
        }
    }
    try {
        if (!writeVoidCellPictures(dir, figures, sources, &error)) {
            return error.toStdString();
        }
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

} // namespace grainlab
