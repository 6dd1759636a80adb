#pragma once
// The OpenGL layer of the scene view: draws every grain as one instanced quad whose fragment
// shader fills the exact four-arc outline (union of the end discs and the lens of the side
// discs between the junctions, antialiased by the signed distance), so 8450 ovals cost one draw
// call. The background, the cell and the overlays (force chains, void cells, rose, scale bar,
// caption, selection) are painted with the shared SceneRenderer through QPainter on the same
// widget, so both views show the same picture. A child of SceneView that ignores the mouse:
// SceneView keeps all interaction. GUI thread only. Not used on the offscreen platform (no
// OpenGL there): SceneView::openGLAvailable() decides.

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

namespace grainlab::ui {

class SceneRenderer;

class GlSceneLayer : public QOpenGLWidget, protected QOpenGLExtraFunctions {
    Q_OBJECT
public:
    GlSceneLayer(const SceneRenderer& renderer, QWidget* parent);
    ~GlSceneLayer() override;

    /// False when the shaders could not be built: the layer then paints with QPainter only.
    bool shadersReady() const { return ready_; }
    /// Why the shaders failed, if they did.
    const QString& failure() const { return failure_; }

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void drawGrains();

    const SceneRenderer& renderer_;
    QOpenGLShaderProgram program_;
    QOpenGLVertexArrayObject vao_;
    QOpenGLBuffer quad_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer instances_{QOpenGLBuffer::VertexBuffer};
    bool ready_ = false;
    QString failure_;
};

} // namespace grainlab::ui
