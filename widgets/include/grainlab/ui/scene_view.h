#pragma once
// The live scene as a QWidget painted with SceneRenderer (QPainter): works on every platform,
// including the offscreen one used by tests and CI, where there is no OpenGL. Mouse wheel zooms
// about the cursor, a drag pans, + / - / arrows / 0 (fit) on the keyboard; a click (a press and
// release without a drag) selects the void cell or grain under the cursor. Optionally the grains
// are drawn by an OpenGL child layer (gl_scene_layer.h); interaction stays here. GUI thread only.

#include <cstdint>

#include <QWidget>

#include "grainlab/snapshot.h"
#include "grainlab/ui/scene_renderer.h"

namespace grainlab::ui {

class GlSceneLayer;

class SceneView : public QWidget {
    Q_OBJECT
public:
    explicit SceneView(QWidget* parent = nullptr);

    /// Shows a new snapshot. Keeps the user's zoom and pan; fits the cell until the user has
    /// zoomed or panned (so a deforming cell stays in view).
    void setSnapshot(SnapshotPtr snapshot);
    const SnapshotPtr& snapshot() const { return renderer_.snapshot(); }
    SceneRenderer& renderer() { return renderer_; }
    const SceneRenderer& renderer() const { return renderer_; }
    /// Changes what is drawn and repaints.
    void setOptions(const SceneOptions& options);
    /// Fits the cell into the widget and resumes following it.
    void fitToCell();
    /// Selects a grain or a void cell (-1 clears) without emitting a signal.
    void selectGrain(int grain);
    void selectVoidCell(int voidCell);
    /// Screen point of a world point, in widget coordinates.
    QPoint toWidget(double x1, double x2) const;
    /// The scene rendered (QPainter) into an image of the widget's size.
    QImage renderImage() const;

    /// True when this platform can draw the scene with OpenGL 3.3 (never on the offscreen,
    /// minimal, vnc or linuxfb platforms, which have no OpenGL).
    static bool openGLAvailable();
    /// The OpenGL renderer (GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"), "" when
    /// OpenGL is not available. Asked once.
    static QString openGLRenderer();
    /// True when OpenGL is drawn by the processor (Mesa's llvmpipe, softpipe or swrast, e.g.
    /// under Xvfb or in a virtual machine without a graphics card).
    static bool openGLIsSoftware();
    /// Draws the grains with the OpenGL layer (instanced, shader-drawn ovals) instead of
    /// QPainter. Returns whether OpenGL is now in use (false when unavailable).
    bool setUseOpenGL(bool use);
    bool usesOpenGL() const { return gl_ != nullptr; }
    /// The OpenGL layer, or null.
    GlSceneLayer* glLayer() const { return gl_; }

    /// What drawing the scene costs the GUI thread, wall clock (which also counts what a paint
    /// waits for on other threads, e.g. software OpenGL's): the main window spaces its running
    /// pictures by it (picture_budget.h), `grainlab bench --gui` prints it.
    struct DrawingTime {
        double prepareMs = 0;        ///< the last setSnapshot() with a snapshot
        double paintMs = 0;          ///< the last paint of the whole view
        std::uint64_t snapshots = 0; ///< setSnapshot() calls with a snapshot
        double prepareSeconds = 0;   ///< their total
        std::uint64_t paints = 0;    ///< paints of the whole view (QPainter or OpenGL)
        double paintSeconds = 0;     ///< their total
    };
    const DrawingTime& drawingTime() const { return drawing_; }
    /// One new picture at the current view and options [ms]: the last preparation and the last
    /// whole paint.
    double pictureMs() const { return drawing_.prepareMs + drawing_.paintMs; }

signals:
    void grainClicked(int grain);
    void voidCellClicked(int voidCell);
    /// The world point under the cursor [m] (for a status bar).
    void cursorMoved(double x1, double x2);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    void handleClick(QPointF point, Qt::KeyboardModifiers modifiers);
    void repaintScene();
    void notePaint(double seconds);

    SceneRenderer renderer_;
    GlSceneLayer* gl_ = nullptr; ///< child covering the widget when OpenGL draws the grains
    bool following_ = true;      ///< fit the cell on each snapshot until the user moves the view
    QPointF pressPoint_, lastPoint_;
    bool dragging_ = false;
    bool pressed_ = false;
    DrawingTime drawing_;
};

} // namespace grainlab::ui
