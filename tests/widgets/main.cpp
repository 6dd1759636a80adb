// Test main of widget_tests and gui_tests: selects Qt's offscreen platform when there is no
// display (CI, servers), then runs GoogleTest inside a QApplication so that the tests can drive
// real widgets with QTest. Runs started in a window are written under test-runs/ in the working
// folder (GRAINLAB_RUNS_DIR), never into the user's runs folder.
#include <QApplication>
#include <QDir>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    if (qEnvironmentVariableIsEmpty("GRAINLAB_RUNS_DIR")) {
        qputenv("GRAINLAB_RUNS_DIR",
                QDir::current().filePath(QStringLiteral("test-runs")).toUtf8());
    }
    ::testing::InitGoogleTest(&argc, argv);
    QApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
