#pragma once
// What the window tests share: the small experiment (120 ovals, one confining pressure, shear to
// 0.5 %) read from experiment text as a window run records it, an emptied folder for its runs,
// a run of the tiny experiment by the grainlab executable, waiting on the event loop, and
// clicking a toolbar action like a user.
#include <chrono>
#include <string>

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QProcess>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grainlab/experiment_file.h"
#include "gui/main_window.h"

namespace grainlab::ui::window_tests {

/// The quick run's experiment made small, read back from its text; `test`, when given, is its
/// `test` key (a loading path).
inline ExperimentConfig smallExperiment(double shearTarget = 0.005,
                                        const nlohmann::ordered_json& test = nullptr) {
    const std::string path = GRAINLAB_SOURCE_DIR "/resources/experiments/quick.json";
    auto j = nlohmann::ordered_json::parse(readExperimentFile(path).sourceText);
    j["threads"] = 1;
    j["grains"]["count"] = 120;
    j["compaction"]["pressures"] = {15e3};
    j["shear"]["pressures"] = {15e3};
    j["shear"]["target_axial_strain"] = shearTarget;
    if (!test.is_null()) {
        j["test"] = test;
    }
    return parseExperimentText(j.dump(2), path);
}

/// An empty folder test-runs/<name> in the working folder.
inline QString freshFolder(const QString& name) {
    QDir dir(QDir::current().filePath(QStringLiteral("test-runs/") + name));
    dir.removeRecursively();
    return dir.path();
}

/// An empty folder test-runs/<name>, where the window's runs are then written
/// (GRAINLAB_RUNS_DIR).
inline QString freshRunsFolder(const QString& name) {
    const QString runs = freshFolder(name);
    qputenv("GRAINLAB_RUNS_DIR", runs.toUtf8());
    return runs;
}

/// An empty folder grainlab-test-<name>-<pid> in the temporary folder (made: it exists unless
/// it could not be).
inline QDir freshTempFolder(const QString& name) {
    QDir dir(QDir::temp().filePath(
        QStringLiteral("grainlab-test-%1-%2").arg(name).arg(QCoreApplication::applicationPid())));
    dir.removeRecursively();
    dir.mkpath(QStringLiteral("."));
    return dir;
}

/// `grainlab run` of the tiny experiment (resources/experiments/tiny.json) into `out`, quietly:
/// its exit code (negative when it crashed or did not start).
inline int runTinyExperiment(const QString& out) {
    return QProcess::execute(
        QStringLiteral(GRAINLAB_EXE),
        {QStringLiteral("run"),
         QStringLiteral(GRAINLAB_SOURCE_DIR "/resources/experiments/tiny.json"),
         QStringLiteral("--out"), out, QStringLiteral("--quiet")});
}

template <class Predicate>
bool waitFor(Predicate done, int timeoutMs = 60000) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) {
            return false;
        }
        QTest::qWait(10);
    }
    return true;
}

/// Gives the window `experiment` and shows it at 1400 x 900, the size the window tests see it at.
inline void showWith(MainWindow& w, const ExperimentConfig& experiment) {
    w.setExperiment(experiment);
    w.resize(1400, 900);
    w.show();
}

/// Clicks the toolbar button of an action, like a user.
inline void click(MainWindow& w, QAction* action) {
    QToolBar* bar = w.findChild<QToolBar*>(QStringLiteral("runToolBar"));
    ASSERT_NE(bar, nullptr);
    QWidget* button = bar->widgetForAction(action);
    ASSERT_NE(button, nullptr);
    ASSERT_TRUE(button->isEnabled()) << action->text().toStdString();
    QTest::mouseClick(button, Qt::LeftButton);
}

} // namespace grainlab::ui::window_tests
