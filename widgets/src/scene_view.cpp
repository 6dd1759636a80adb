// See scene_view.h.
#include "grainlab/ui/scene_view.h"

#include <cmath>

#include <QElapsedTimer>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPaintEvent>
#include <QPainter>
#include <QWheelEvent>

#include "grainlab/ui/gl_scene_layer.h"

namespace grainlab::ui {

SceneView::SceneView(QWidget* parent) : QWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumSize(200, 200);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void SceneView::setSnapshot(SnapshotPtr snapshot) {
    const bool first = !renderer_.snapshot();
    const bool some = snapshot != nullptr;
    QElapsedTimer clock;
    clock.start();
    renderer_.setSnapshot(std::move(snapshot));
    if (some) {
        const double seconds = 1e-9 * double(clock.nsecsElapsed());
        drawing_.prepareMs = 1e3 * seconds;
        drawing_.prepareSeconds += seconds;
        ++drawing_.snapshots;
    }
    if (following_ || first) {
        renderer_.fitToCell(size());
    }
    repaintScene();
}

void SceneView::setOptions(const SceneOptions& options) {
    renderer_.options() = options;
    repaintScene();
}

void SceneView::fitToCell() {
    following_ = true;
    renderer_.fitToCell(size());
    repaintScene();
}

void SceneView::selectGrain(int grain) {
    renderer_.options().selectedGrain = grain;
    repaintScene();
}

void SceneView::selectVoidCell(int voidCell) {
    renderer_.options().selectedVoidCell = voidCell;
    repaintScene();
}

QPoint SceneView::toWidget(double x1, double x2) const {
    return renderer_.view().toScreen(x1, x2).toPoint();
}

QImage SceneView::renderImage() const {
    QImage image(size(), QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    renderer_.render(painter, size());
    return image;
}

void SceneView::paintEvent(QPaintEvent* event) {
    if (gl_) {
        return; // the OpenGL layer covers the widget
    }
    QElapsedTimer clock;
    clock.start();
    {
        QPainter painter(this);
        renderer_.render(painter, size());
    }
    // A paint of part of the view (uncovered by another window) is clipped and cheaper: it says
    // nothing about the next picture.
    if (QRegion(rect()).subtracted(event->region()).isEmpty()) {
        notePaint(1e-9 * double(clock.nsecsElapsed()));
    }
}

void SceneView::notePaint(double seconds) {
    drawing_.paintMs = 1e3 * seconds;
    drawing_.paintSeconds += seconds;
    ++drawing_.paints;
}

void SceneView::resizeEvent(QResizeEvent*) {
    if (following_) {
        renderer_.fitToCell(size());
    }
    if (gl_) {
        gl_->setGeometry(rect());
    }
}

void SceneView::repaintScene() {
    if (gl_) {
        gl_->update();
    } else {
        update();
    }
}

bool SceneView::openGLAvailable() {
    const QString platform = QGuiApplication::platformName();
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal") ||
        platform == QLatin1String("vnc") || platform == QLatin1String("linuxfb")) {
        return false;
    }
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    QOpenGLContext context;
    context.setFormat(format);
    return context.create() && context.format().version() >= qMakePair(3, 3);
}

QString SceneView::openGLRenderer() {
    static const QString renderer = [] {
        if (!openGLAvailable()) {
            return QString();
        }
        QOpenGLContext context;
        QOffscreenSurface surface;
        surface.setFormat(context.format());
        surface.create();
        if (!context.create() || !context.makeCurrent(&surface)) {
            return QString();
        }
        const auto* name = context.functions()->glGetString(GL_RENDERER);
        const QString text =
            name ? QString::fromLatin1(reinterpret_cast<const char*>(name)) : QString();
        context.doneCurrent();
        return text;
    }();
    return renderer;
}

bool SceneView::openGLIsSoftware() {
    const QString renderer = openGLRenderer();
    for (const char* software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"}) {
        if (renderer.contains(QLatin1String(software), Qt::CaseInsensitive)) {
            return true;
        }
    }
    return false;
}

bool SceneView::setUseOpenGL(bool use) {
    if (use == (gl_ != nullptr)) {
        return use;
    }
    if (!use) {
        delete gl_;
        gl_ = nullptr;
        update();
        return false;
    }
    if (!openGLAvailable()) {
        return false;
    }
    gl_ = new GlSceneLayer(renderer_, this);
    connect(gl_, &GlSceneLayer::painted, this, &SceneView::notePaint);
    gl_->setGeometry(rect());
    gl_->show();
    return true;
}

void SceneView::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0.0) {
        following_ = false;
        renderer_.view().zoomAt(event->position(), std::pow(1.25, steps));
        repaintScene();
    }
    event->accept();
}

void SceneView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        pressed_ = true;
        dragging_ = false;
        pressPoint_ = lastPoint_ = event->position();
    }
}

void SceneView::mouseMoveEvent(QMouseEvent* event) {
    const auto w = renderer_.view().toWorld(event->position());
    emit cursorMoved(w[0], w[1]);
    if (!pressed_) {
        return;
    }
    if (!dragging_ && (event->position() - pressPoint_).manhattanLength() > 4.0) {
        dragging_ = true;
        following_ = false;
    }
    if (dragging_) {
        renderer_.view().panBy(event->position() - lastPoint_);
        lastPoint_ = event->position();
        repaintScene();
    }
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || !pressed_) {
        return;
    }
    pressed_ = false;
    if (!dragging_) {
        handleClick(event->position(), event->modifiers());
    }
    dragging_ = false;
}

void SceneView::handleClick(QPointF point, Qt::KeyboardModifiers modifiers) {
    // With void cells shown a click picks the void cell under the cursor (its polygon runs
    // through grain centres, so it overlaps grains); Shift picks the grain. Otherwise grains
    // come first and a click between grains picks the void cell there.
    const bool voidsFirst =
        renderer_.options().voidCells != VoidCellShading::Off && !(modifiers & Qt::ShiftModifier);
    int grain = -1, cell = -1;
    if (voidsFirst) {
        cell = renderer_.voidCellAt(point);
        if (cell < 0) {
            grain = renderer_.grainAt(point);
        }
    } else {
        grain = renderer_.grainAt(point);
        if (grain < 0) {
            cell = renderer_.voidCellAt(point);
        }
    }
    renderer_.options().selectedGrain = grain;
    renderer_.options().selectedVoidCell = cell;
    repaintScene();
    if (cell >= 0) {
        emit voidCellClicked(cell);
    } else {
        emit grainClicked(grain);
    }
}

void SceneView::keyPressEvent(QKeyEvent* event) {
    const QPointF centre(width() / 2.0, height() / 2.0);
    const double step = 0.1 * std::min(width(), height());
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        renderer_.view().zoomAt(centre, 1.25);
        break;
    case Qt::Key_Minus:
        renderer_.view().zoomAt(centre, 0.8);
        break;
    case Qt::Key_Left:
        renderer_.view().panBy(QPointF(step, 0));
        break;
    case Qt::Key_Right:
        renderer_.view().panBy(QPointF(-step, 0));
        break;
    case Qt::Key_Up:
        renderer_.view().panBy(QPointF(0, step));
        break;
    case Qt::Key_Down:
        renderer_.view().panBy(QPointF(0, -step));
        break;
    case Qt::Key_0:
    case Qt::Key_Home:
        fitToCell();
        return;
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    following_ = false;
    repaintScene();
}

} // namespace grainlab::ui
