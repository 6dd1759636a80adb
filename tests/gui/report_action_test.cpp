// File > Report… writes the report of the window's run into its run folder's report/ through a
// `grainlab report` process and opens report.html (caught here by a URL handler, as the system's
// browser would be); it refuses while the run is still going.
#include <QDesktopServices>
#include <QDir>
#include <QSignalSpy>
#include <QUrl>

#include <gtest/gtest.h>

#include "common/atomic_file.h"
#include "gui/main_window.h"
#include "window_test_support.h"

namespace grainlab::ui {
namespace {

using namespace window_tests;

class UrlCatcher : public QObject {
    Q_OBJECT
public:
    QList<QUrl> opened;
public slots:
    void open(const QUrl& url) { opened << url; }
};

TEST(ReportAction, WritesTheRunsReportAndOpensIt) {
    QDir runs(QDir::current().filePath(QStringLiteral("test-runs/report-action")));
    runs.removeRecursively();
    qputenv("GRAINLAB_RUNS_DIR", runs.path().toUtf8());
    UrlCatcher catcher;
    QDesktopServices::setUrlHandler(QStringLiteral("file"), &catcher, "open");

    MainWindow w;
    w.setGrainlabExecutable(QStringLiteral(GRAINLAB_EXE));
    showWith(w, smallExperiment(0.01));
    w.writeReport(); // no run yet
    EXPECT_TRUE(catcher.opened.isEmpty());

    click(w, w.startAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state == RunState::Running; }));
    click(w, w.pauseAction());
    ASSERT_TRUE(waitFor([&] { return w.controller().status().state == RunState::Paused; }));
    QSignalSpy written(&w, &MainWindow::reportWritten);
    w.reportAction()->trigger(); // the run file is still being written: refused
    QTest::qWait(200);
    EXPECT_EQ(written.count(), 0);
    EXPECT_TRUE(w.reportAction()->isEnabled());

    click(w, w.startAction());
    ASSERT_TRUE(
        waitFor([&] { return w.controller().status().state == RunState::Finished; }, 180000))
        << w.controller().status().error;
    w.reportAction()->trigger();
    ASSERT_TRUE(waitFor([&] { return written.count() == 1; }, 120000));
    const QString html = written.front().front().toString();
    EXPECT_EQ(html, QDir(w.runFolder()).filePath(QStringLiteral("report/report.html")));
    const std::string page = readWholeFile(html.toStdString());
    EXPECT_NE(page.find("Headline numbers"), std::string::npos);
    EXPECT_NE(page.find("had not finished"), std::string::npos); // a window run has no cost.json
    EXPECT_NE(page.find("data:image/png;base64,"), std::string::npos);
    ASSERT_EQ(catcher.opened.size(), 1);
    EXPECT_EQ(catcher.opened.front(), QUrl::fromLocalFile(html));

    QDir(w.runFolder()).removeRecursively();
    QDesktopServices::unsetUrlHandler(QStringLiteral("file"));
}

} // namespace
} // namespace grainlab::ui

#include "report_action_test.moc"
