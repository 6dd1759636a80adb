// See app.h.
#include "gui/app.h"

#include <QApplication>
#include <QGuiApplication>

#include <fmt/format.h>

#include "common/resources.h"
#include "gui/main_window.h"

namespace grainlab {

int runGui(int argc, char** argv, const std::string& experimentPath) {
    // Without a display (and no platform chosen) Qt would abort; say what to do instead.
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        fmt::print(stderr,
                   "grainlab: no display found for the window. Run an experiment headless with\n"
                   "  grainlab run {} --out DIR\n"
                   "or set QT_QPA_PLATFORM=offscreen to drive the window without a screen.\n",
                   experimentPath.empty() ? "EXPERIMENT.json" : experimentPath);
        return 2;
    }
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("GrainLab"));
    QApplication::setApplicationVersion(QStringLiteral(GRAINLAB_VERSION));
    // The scene is drawn with QPainter (SceneView) on every platform, so the offscreen platform
    // (no OpenGL) works as well as a desktop one.
    ui::MainWindow window;
    const std::string path =
        experimentPath.empty() ? resourcePath("experiments/quick.json") : experimentPath;
    QString error;
    if (!window.openExperiment(QString::fromStdString(path), &error)) {
        fmt::print(stderr, "grainlab: {}\n", error.toStdString());
        return 1;
    }
    window.resize(1500, 950);
    window.show();
    return QApplication::exec();
}

} // namespace grainlab
