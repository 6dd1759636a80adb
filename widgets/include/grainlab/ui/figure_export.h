#pragma once
// Figure files: anything that paints with QPainter written as PNG, SVG or PDF (chosen by the file
// extension), and the one-click figure set (the scene and every chart in every format, plus the
// series as CSV) into a folder. GUI thread (it paints widgets' content).

#include <functional>
#include <memory>
#include <vector>

#include <QSize>
#include <QString>
#include <QStringList>

#include "grainlab/series.h"

class QGuiApplication;
class QPainter;
class QRectF;

namespace grainlab::ui {

class ChartsPanel;
class SceneView;

/// For headless commands that write figures (study, report, stability): a Qt application on
/// the offscreen platform when none runs yet (figures need fonts, not a screen), else null. Keep
/// it alive while painting. Main thread.
std::unique_ptr<QGuiApplication> headlessApplicationIfNone();

/// Paints `paint(painter, size)` into `path`: .png (white background), .svg or .pdf, at `size`
/// pixels (points for PDF). Returns false and sets `error` on an unknown extension or a write
/// failure.
bool exportFigure(const QString& path, QSize size,
                  const std::function<void(QPainter&, QSize)>& paint, QString* error = nullptr);

/// Writes `paint(painter, rect)` as <folder>/<name>.<format> for each of `formats`, at `size`,
/// adding each file written to `written`. Returns false and sets `error` at the first failure.
bool exportFigureFormats(const QString& folder, const QString& name, const QStringList& formats,
                         QSize size, const std::function<void(QPainter&, const QRectF&)>& paint,
                         QStringList& written, QString* error = nullptr);

/// Creates `folder` (and its parents) for figures. Returns false and sets `error` when it cannot.
bool makeFigureFolder(const QString& folder, QString* error = nullptr);

/// The scene as shown (same zoom, scaled to `size`; the whole cell when the view follows it).
bool exportScene(const SceneView& view, const QString& path, QSize size, QString* error = nullptr);

struct FigureSetOptions {
    QSize sceneSize{1200, 1200};
    QSize chartSize{1200, 800};
    QStringList formats{QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")};
    bool csv = true; ///< also write each test's series as <test>.csv
};

/// Writes scene.<fmt>, <chart name>.<fmt> for every chart (but the charts of cycles and of probes
/// when the run has no such test), and <test>.csv into `folder`
/// (created if needed). Returns the files written; sets `error` and stops at the first failure.
QStringList exportFigureSet(const QString& folder, const SceneView* scene,
                            const ChartsPanel* charts, const std::vector<SeriesTable>& series,
                            const FigureSetOptions& options = {}, QString* error = nullptr);

} // namespace grainlab::ui
