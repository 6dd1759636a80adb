// `grainlab export picture` draws a run file's checkpoint as the window's scene renderer draws
// it: the picture of the command equals, pixel for pixel, the one drawn here from the same
// checkpoint with the same options; a picture that exists and a test the run does not have are
// refused, naming them, and nothing is written.
#include <set>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QProcess>

#include <gtest/gtest.h>

#include "common/run_file_view.h"
#include "grainlab/ui/figure_export.h"
#include "grainlab/ui/scene_renderer.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

struct Result {
    int status = -1;
    QString output;
};

Result grainlab(const QStringList& arguments) {
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(QStringLiteral(GRAINLAB_EXE), arguments);
    p.waitForFinished(120000);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
            QString::fromUtf8(p.readAll())};
}

TEST(CheckpointPicture, DrawsTheCheckpointAsTheWindowsRendererDoes) {
    QDir work = window_tests::freshTempFolder(QStringLiteral("picture"));
    ASSERT_TRUE(work.exists());
    const QString run = work.filePath(QStringLiteral("run"));
    ASSERT_EQ(window_tests::runTinyExperiment(run), 0);
    const QString picture = work.filePath(QStringLiteral("p015.png"));
    const Result drawn = grainlab(
        {QStringLiteral("export"), QStringLiteral("picture"), run, QStringLiteral("--test"),
         QStringLiteral("p015kPa"), QStringLiteral("--strain"), QStringLiteral("0.01"),
         QStringLiteral("--out"), picture, QStringLiteral("--size"), QStringLiteral("400"),
         QStringLiteral("--void-cells"), QStringLiteral("valence")});
    ASSERT_EQ(drawn.status, 0) << drawn.output.toStdString();
    const QImage fromCommand(picture);
    ASSERT_EQ(fromCommand.size(), QSize(400, 400));

    // The same checkpoint drawn here, with the same options.
    const RunFileView file =
        openRunFile(QDir(run).filePath(QStringLiteral("run.h5")).toStdString());
    const int index = nearestCheckpoint(file, "run.h5: p015kPa", 0.01);
    ASSERT_GE(index, 0);
    EXPECT_TRUE(drawn.output.contains(QString::fromStdString(file.checkpoints[std::size_t(index)])))
        << drawn.output.toStdString();
    SceneRenderer renderer;
    renderer.options().colouring = GrainColouring::Rotation;
    renderer.options().forceChains = ForceChains::Strong;
    renderer.options().voidCells = VoidCellShading::Valence;
    renderer.options().rotationRange = 0.2;
    renderer.setSnapshot(runFileSnapshot(file, std::size_t(index)));
    renderer.fitToCell(QSize(400, 400));
    const QString here = work.filePath(QStringLiteral("here.png"));
    QString error;
    ASSERT_TRUE(exportFigure(
        here, QSize(400, 400), [&](QPainter& p, QSize s) { renderer.render(p, s); }, &error))
        << error.toStdString();
    const QImage drawnHere(here);
    ASSERT_EQ(drawnHere.size(), fromCommand.size());
    EXPECT_TRUE(drawnHere.convertToFormat(QImage::Format_ARGB32) ==
                fromCommand.convertToFormat(QImage::Format_ARGB32));
    // Not a blank picture: the rotation colours and the cell are there.
    std::set<QRgb> colours;
    for (int y = 0; y < 400; y += 4) {
        for (int x = 0; x < 400; x += 4) {
            colours.insert(fromCommand.pixel(x, y));
        }
    }
    EXPECT_GT(colours.size(), 50u);

    // Refused: an existing picture (untouched), a test the run does not have.
    QFile existing(picture);
    ASSERT_TRUE(existing.open(QIODevice::ReadOnly));
    const QByteArray before = existing.readAll();
    existing.close();
    const Result again = grainlab({QStringLiteral("export"), QStringLiteral("picture"), run,
                                   QStringLiteral("--test"), QStringLiteral("p015kPa"),
                                   QStringLiteral("--out"), picture});
    EXPECT_EQ(again.status, 2);
    EXPECT_TRUE(again.output.contains(picture)) << again.output.toStdString();
    ASSERT_TRUE(existing.open(QIODevice::ReadOnly));
    EXPECT_EQ(existing.readAll(), before);
    const QString other = work.filePath(QStringLiteral("other.png"));
    const Result unknown = grainlab({QStringLiteral("export"), QStringLiteral("picture"), run,
                                     QStringLiteral("--test"), QStringLiteral("p999kPa"),
                                     QStringLiteral("--out"), other});
    EXPECT_EQ(unknown.status, 2);
    EXPECT_TRUE(unknown.output.contains(QStringLiteral("p999kPa")) &&
                unknown.output.contains(QStringLiteral("p015kPa")))
        << unknown.output.toStdString();
    EXPECT_FALSE(QFile::exists(other));
    work.removeRecursively();
}

} // namespace
} // namespace grainlab::ui
