#pragma once
// The OpenGL layer of the scene view: draws every grain as one instanced quad whose fragment
// shader fills the exact four-arc outline (union of the end discs and the lens of the side
// discs between the junctions, antialiased by the signed distance), so 8450 ovals cost one draw
// call. The void cells are triangles (ear clipping, kept per snapshot) and their outlines
// lines; each force-chain segment is an instanced quad whose shader draws a round-capped,
// antialiased line with the QPainter view's width and colour. The background, the cell and
// the annotations (selection, rose, scale bar, caption) are painted with the shared
// SceneRenderer through QPainter on the same widget, so both views show the same picture:
// painting thousands of polygons and lines through QPainter's OpenGL engine was what made this
// view slow. A child of SceneView that ignores the mouse:
// SceneView keeps all interaction. GUI thread only. Not used on the offscreen platform (no
// OpenGL there): SceneView::openGLAvailable() decides.

#include <cstdint>
#include <vector>

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QOpenGLWidget>

#include "grainlab/snapshot.h"

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

signals:
    /// A frame was drawn in `seconds` (wall clock of paintGL, for the scene view's picture
    /// cost).
    void painted(double seconds);

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    /// What paintGL draws (paintGL times it).
    void paintFrame();
    bool buildProgram(QOpenGLShaderProgram& program, const char* vertex, const char* fragment);
    /// Sets the world-to-screen uniforms of `program`.
    void setView(QOpenGLShaderProgram& program);
    /// Uploads `instances` into `buffer` and draws them, a four-vertex strip each, in order, with
    /// `program` (its view set) and `vao`.
    template <class T>
    void drawInstances(QOpenGLShaderProgram& program, QOpenGLVertexArrayObject& vao,
                       QOpenGLBuffer& buffer, const std::vector<T>& instances);
    void drawGrains();
    void drawVoidCells();
    void drawForceChains();
    /// Triangulates the snapshot's void cells into the mesh buffers when the snapshot changed.
    void updateVoidCellMesh();

    const SceneRenderer& renderer_;
    QOpenGLShaderProgram program_;      ///< grains
    QOpenGLShaderProgram flatProgram_;  ///< void-cell triangles and outlines
    QOpenGLShaderProgram chainProgram_; ///< force-chain segments
    QOpenGLVertexArrayObject vao_, voidVao_, voidEdgeVao_, chainVao_;
    QOpenGLBuffer quad_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer instances_{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer voidTriangles_{QOpenGLBuffer::VertexBuffer}; ///< x1, x2 [m] per vertex
    QOpenGLBuffer voidColours_{QOpenGLBuffer::VertexBuffer};   ///< RGBA per vertex
    QOpenGLBuffer voidEdges_{QOpenGLBuffer::VertexBuffer};     ///< x1, x2 [m], two per edge
    QOpenGLBuffer chains_{QOpenGLBuffer::VertexBuffer};
    SnapshotPtr meshSnapshot_;              ///< the snapshot the void-cell buffers hold
    std::vector<std::int32_t> firstVertex_; ///< per void cell, its first triangle vertex
    int edgeVertices_ = 0;
    /// Shading and selection the colour buffer holds (-1: none yet).
    std::int64_t colourKey_ = -1;
    bool ready_ = false;
    QString failure_;
};

} // namespace grainlab::ui
