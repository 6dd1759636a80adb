// Export > ParaView files… writes, by a `grainlab export vtk` process the window does not wait
// for, the same files as the command line for the run file the window shows; it refuses with
// no run, and an existing folder is refused with the command's own message, untouched.
#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using window_tests::freshTempFolder;
using window_tests::runTinyExperiment;
using window_tests::waitFor;

/// Every file under `folder` (relative path) with its bytes.
std::map<QString, QByteArray> files(const QString& folder) {
    std::map<QString, QByteArray> out;
    QDirIterator it(folder, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        QFile f(path);
        f.open(QIODevice::ReadOnly);
        out[QDir(folder).relativeFilePath(path)] = f.readAll();
    }
    return out;
}

TEST(ParaViewExport, WritesTheCommandLinesFilesOfTheOpenRunFileWithoutWaiting) {
    QDir work = freshTempFolder(QStringLiteral("paraview"));
    ASSERT_TRUE(work.exists());
    const QString run = work.filePath(QStringLiteral("run"));
    ASSERT_EQ(runTinyExperiment(run), 0);

    MainWindow w;
    w.setGrainlabExecutable(QStringLiteral(GRAINLAB_EXE));
    w.resize(1200, 800);
    w.show();
    // In the Export menu.
    bool inMenu = false;
    for (QAction* menu : w.menuBar()->actions()) {
        if (menu->menu() && menu->text() == QStringLiteral("&Export")) {
            inMenu = menu->menu()->actions().contains(w.paraviewAction());
        }
    }
    EXPECT_TRUE(inMenu);
    QSignalSpy written(&w, &MainWindow::paraviewFilesWritten);

    // No run yet: refused at once.
    w.writeParaViewFiles(work.filePath(QStringLiteral("none")));
    ASSERT_EQ(written.count(), 1);
    EXPECT_TRUE(written.takeFirst().at(1).toString().contains(QStringLiteral("no run")));
    EXPECT_FALSE(QFileInfo::exists(work.filePath(QStringLiteral("none"))));

    QString error;
    ASSERT_TRUE(w.openRunFile(QDir(run).filePath(QStringLiteral("run.h5")), &error))
        << error.toStdString();
    const QString out = work.filePath(QStringLiteral("window"));
    QElapsedTimer clock;
    clock.start();
    w.writeParaViewFiles(out);
    EXPECT_LT(clock.elapsed(), 500); // the process writes; the window goes on
    EXPECT_FALSE(w.paraviewAction()->isEnabled());
    ASSERT_TRUE(waitFor([&] { return written.count() == 1; }, 120000));
    EXPECT_EQ(written.front().at(0).toString(), out);
    EXPECT_EQ(written.takeFirst().at(1).toString(), QString());
    EXPECT_TRUE(w.paraviewAction()->isEnabled());

    // The same bytes as the command line's export of that run folder.
    const QString cli = work.filePath(QStringLiteral("cli"));
    ASSERT_EQ(QProcess::execute(QStringLiteral(GRAINLAB_EXE),
                                {QStringLiteral("export"), QStringLiteral("vtk"),
                                 QFileInfo(run).absoluteFilePath(), QStringLiteral("--out"), cli,
                                 QStringLiteral("--quiet")}),
              0);
    const auto mine = files(out);
    EXPECT_EQ(mine.size(), 51u); // 3 tests: 12 frames of 4 files, 3 .pvd
    EXPECT_TRUE(mine.count(QStringLiteral("p015kPa.pvd")));
    EXPECT_TRUE(mine == files(cli));

    // Again into the same folder: the command's refusal, naming it; the files untouched.
    w.writeParaViewFiles(out);
    ASSERT_TRUE(waitFor([&] { return written.count() == 1; }, 60000));
    const QString refusal = written.takeFirst().at(1).toString();
    EXPECT_TRUE(refusal.contains(out)) << refusal.toStdString();
    EXPECT_TRUE(refusal.contains(QStringLiteral("exists already"))) << refusal.toStdString();
    EXPECT_TRUE(files(out) == mine);
    work.removeRecursively();
}

} // namespace
} // namespace grainlab::ui
