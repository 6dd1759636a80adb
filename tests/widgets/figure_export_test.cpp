// Figures: every chart and the scene written as PNG, SVG and PDF; the figure set into a folder
// with valid files of the requested size, and the series as CSV readable back.
#include <QDir>
#include <QFile>
#include <QImageReader>
#include <QSvgRenderer>

#include <gtest/gtest.h>

#include "grainlab/csv_series.h"
#include "grainlab/ui/charts_panel.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/scene_view.h"
#include "test_scenes.h"

namespace grainlab::ui {
namespace {

TEST(FigureExport, FigureSetWritesValidFilesOfTheRightSize) {
    // In the build folder, for a look by hand: test-images/figure-set/.
    QDir dir(QStringLiteral("test-images/figure-set"));
    dir.removeRecursively();
    SceneView scene;
    scene.resize(500, 500);
    scene.setSnapshot(testing::makeCompactedSnapshot());
    ChartsPanel charts;
    charts.resize(800, 800);
    std::vector<SeriesTable> series{testing::makeSeries("p15kPa", 100, 0.5),
                                    testing::makeSeries("p100kPa", 100, 0.4)};
    series[0].columns.insert(series[0].columns.begin(), {"step", "-"});
    for (auto& r : series[0].rows) {
        r.insert(r.begin(), 1.0);
    }
    series.push_back(testing::makeCompactionSeries(60)); // for the compaction charts
    charts.setSeries(series);
    FigureSetOptions options;
    options.sceneSize = QSize(640, 640);
    options.chartSize = QSize(900, 600);
    QString error;
    const QStringList files = exportFigureSet(dir.path(), &scene, &charts, series, options, &error);
    EXPECT_TRUE(error.isEmpty()) << error.toStdString();
    // Every chart but the two of cyclic tests and probes, which these series have none of.
    const int drawn = charts.chartCount() - 2;
    ASSERT_EQ(files.size(), 3 * (1 + drawn) + 3);
    EXPECT_FALSE(files.contains(dir.filePath(QStringLiteral("p_per_cycle.png"))));
    EXPECT_TRUE(files.contains(dir.filePath(QStringLiteral("q_vs_p.png"))));
    for (const QString& file : files) {
        ASSERT_TRUE(QFile::exists(file)) << file.toStdString();
        EXPECT_GT(QFileInfo(file).size(), 200) << file.toStdString();
        const QString suffix = QFileInfo(file).suffix();
        const QSize expected =
            QFileInfo(file).baseName() == "scene" ? options.sceneSize : options.chartSize;
        if (suffix == "png") {
            QImageReader reader(file);
            EXPECT_EQ(reader.size(), expected) << file.toStdString();
            const QImage image = reader.read();
            ASSERT_FALSE(image.isNull());
            // Not blank: a good share of the pixels is not white.
            int ink = 0;
            for (int y = 0; y < image.height(); y += 3) {
                for (int x = 0; x < image.width(); x += 3) {
                    ink += qGray(image.pixel(x, y)) < 240;
                }
            }
            EXPECT_GT(ink, image.width() * image.height() / 9 / 100) << file.toStdString();
        } else if (suffix == "svg") {
            QSvgRenderer svg(file);
            EXPECT_TRUE(svg.isValid()) << file.toStdString();
            EXPECT_EQ(svg.viewBox(), QRect(QPoint(0, 0), expected)) << file.toStdString();
        } else if (suffix == "pdf") {
            QFile pdf(file);
            ASSERT_TRUE(pdf.open(QIODevice::ReadOnly));
            const QByteArray bytes = pdf.readAll();
            EXPECT_TRUE(bytes.startsWith("%PDF-"));
            const QByteArray box = QStringLiteral("/MediaBox [0 0 %1.000000 %2.000000]")
                                       .arg(expected.width())
                                       .arg(expected.height())
                                       .toLatin1();
            EXPECT_TRUE(bytes.contains(box)) << file.toStdString();
        } else {
            EXPECT_EQ(suffix, "csv");
        }
    }
    const SeriesTable back = readSeriesCsv(QDir(dir.path()).filePath("p100kPa.csv").toStdString());
    EXPECT_EQ(back.rows.size(), 100u);
}

TEST(FigureExport, UnknownFormatIsAnError) {
    QString error;
    EXPECT_FALSE(exportFigure(
        QStringLiteral("/tmp/x.bmpx"), QSize(10, 10), [](QPainter&, QSize) {}, &error));
    EXPECT_TRUE(error.contains("bmpx"));
}

} // namespace
} // namespace grainlab::ui
