// See gl_scene_layer.h.
#include "grainlab/ui/gl_scene_layer.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include <QElapsedTimer>
#include <QPainter>

#include "grainlab/ui/polygon_triangulation.h"
#include "grainlab/ui/scene_renderer.h"

// The shaders' resource file lives in this static library: nothing else references it, so it is
// registered by hand (Q_INIT_RESOURCE, outside any namespace) before the first shader is read.
static void initShaderResources() {
    Q_INIT_RESOURCE(shaders);
}

namespace grainlab::ui {
namespace {

// Per instance: centre and orientation, half sizes, arc parameters (end-arc centre offset, end
// radius, side-arc centre offset, side radius), junction x, colour.
struct Instance {
    float x1, x2, theta;
    float halfWidth, halfHeight;
    float endOffset, endRadius, sideOffset, sideRadius;
    float junctionX;
    std::uint8_t rgba[4];
};

// Force chains: one quad per segment, grown by half the width and a pixel around it; the
// fragment shader keeps what lies within half the width of the segment (round caps), with a
// one-pixel antialiased edge, as QPainter's round-capped pen.
struct ChainInstance {
    float a1, a2, b1, b2; ///< [m]
    float width;          ///< [pixel]
    std::uint8_t rgba[4];
};

void toBytes(QRgb c, std::uint8_t rgba[4]) {
    rgba[0] = std::uint8_t(qRed(c));
    rgba[1] = std::uint8_t(qGreen(c));
    rgba[2] = std::uint8_t(qBlue(c));
    rgba[3] = std::uint8_t(qAlpha(c));
}

const void* byteOffset(std::size_t bytes) {
    return reinterpret_cast<const void*>(bytes);
}

} // namespace

GlSceneLayer::GlSceneLayer(const SceneRenderer& renderer, QWidget* parent)
    : QOpenGLWidget(parent), renderer_(renderer) {
    initShaderResources();
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setSamples(0);
    setFormat(format);
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setFocusPolicy(Qt::NoFocus);
}

GlSceneLayer::~GlSceneLayer() {
    makeCurrent();
    for (QOpenGLBuffer* buffer :
         {&instances_, &quad_, &voidTriangles_, &voidColours_, &voidEdges_, &chains_}) {
        buffer->destroy();
    }
    for (QOpenGLVertexArrayObject* vao : {&vao_, &voidVao_, &voidEdgeVao_, &chainVao_}) {
        vao->destroy();
    }
    doneCurrent();
}

bool GlSceneLayer::buildProgram(QOpenGLShaderProgram& program, const char* vertex,
                                const char* fragment) {
    if (!program.addShaderFromSourceFile(QOpenGLShader::Vertex, QString::fromLatin1(vertex)) ||
        !program.addShaderFromSourceFile(QOpenGLShader::Fragment, QString::fromLatin1(fragment)) ||
        !program.link()) {
        failure_ =
            QStringLiteral("%1 + %2: %3")
                .arg(QString::fromLatin1(vertex), QString::fromLatin1(fragment), program.log());
        return false;
    }
    return true;
}

void GlSceneLayer::initializeGL() {
    initializeOpenGLFunctions();
    // The GLSL sources are resources/shaders/*.vert and *.frag, compiled into the library
    // (resources/shaders/shaders.qrc): the grains as instanced quads cut to the oval by its
    // signed distance; void cells as world-space triangles at a periodic-image shift; force
    // chains as round-capped segment quads.
    if (!buildProgram(program_, ":/shaders/grains.vert", ":/shaders/grains.frag") ||
        !buildProgram(flatProgram_, ":/shaders/void_cells.vert", ":/shaders/void_cells.frag") ||
        !buildProgram(chainProgram_, ":/shaders/force_chains.vert",
                      ":/shaders/force_chains.frag")) {
        return;
    }
    vao_.create();
    vao_.bind();
    const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    quad_.create();
    quad_.bind();
    quad_.allocate(corners, sizeof(corners));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    instances_.create();
    instances_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    instances_.bind();
    const auto offset = byteOffset;
    const GLsizei stride = sizeof(Instance);
    const struct {
        GLuint location;
        GLint size;
        GLenum type;
        GLboolean normalise;
        std::size_t at;
    } attributes[] = {{1, 3, GL_FLOAT, GL_FALSE, offsetof(Instance, x1)},
                      {2, 2, GL_FLOAT, GL_FALSE, offsetof(Instance, halfWidth)},
                      {3, 4, GL_FLOAT, GL_FALSE, offsetof(Instance, endOffset)},
                      {4, 1, GL_FLOAT, GL_FALSE, offsetof(Instance, junctionX)},
                      {5, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(Instance, rgba)}};
    for (const auto& a : attributes) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.size, a.type, a.normalise, stride, offset(a.at));
        glVertexAttribDivisor(a.location, 1);
    }
    vao_.release();

    // Void cells: triangles with per-vertex colours, and outline edges with one colour.
    voidVao_.create();
    voidVao_.bind();
    voidTriangles_.create();
    voidTriangles_.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    voidColours_.create();
    voidColours_.bind();
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, nullptr);
    voidVao_.release();
    voidEdgeVao_.create();
    voidEdgeVao_.bind();
    voidEdges_.create();
    voidEdges_.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    voidEdgeVao_.release();

    // Force chains: the unit quad per instance.
    chainVao_.create();
    chainVao_.bind();
    quad_.bind();
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    chains_.create();
    chains_.setUsagePattern(QOpenGLBuffer::StreamDraw);
    chains_.bind();
    const GLsizei chainStride = sizeof(ChainInstance);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, chainStride,
                          offset(offsetof(ChainInstance, a1)));
    glVertexAttribDivisor(1, 1);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, chainStride,
                          offset(offsetof(ChainInstance, width)));
    glVertexAttribDivisor(2, 1);
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, chainStride,
                          offset(offsetof(ChainInstance, rgba)));
    glVertexAttribDivisor(3, 1);
    chainVao_.release();
    ready_ = true;
}

void GlSceneLayer::paintGL() {
    QElapsedTimer clock;
    clock.start();
    paintFrame();
    emit painted(1e-9 * double(clock.nsecsElapsed()));
}

void GlSceneLayer::paintFrame() {
    QPainter painter(this);
    if (!ready_) {
        renderer_.render(painter, size());
        return;
    }
    renderer_.renderBackground(painter, size());
    painter.beginNativePainting();
    if (renderer_.snapshot()) {
        const qreal ratio = devicePixelRatioF();
        glViewport(0, 0, GLsizei(width() * ratio), GLsizei(height() * ratio));
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        drawGrains();
        drawVoidCells();
        drawForceChains();
    }
    painter.endNativePainting();
    renderer_.renderOverlays(painter, size(), Overlays::Annotations);
}

void GlSceneLayer::setView(QOpenGLShaderProgram& program) {
    const ViewTransform& view = renderer_.view();
    const QPointF origin = view.toScreen(0.0, 0.0);
    program.setUniformValue("origin", QVector2D(float(origin.x()), float(origin.y())));
    program.setUniformValue("scale", float(view.pixelsPerMetre()));
    program.setUniformValue("viewport", QVector2D(float(width()), float(height())));
}

template <class T>
void GlSceneLayer::drawInstances(QOpenGLShaderProgram& program, QOpenGLVertexArrayObject& vao,
                                 QOpenGLBuffer& buffer, const std::vector<T>& instances) {
    program.bind();
    setView(program);
    vao.bind();
    buffer.bind();
    buffer.allocate(instances.data(), int(instances.size() * sizeof(T)));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(instances.size()));
    vao.release();
    program.release();
}

void GlSceneLayer::updateVoidCellMesh() {
    const SnapshotPtr& snapshot = renderer_.snapshot();
    if (snapshot == meshSnapshot_) {
        return;
    }
    meshSnapshot_ = snapshot;
    colourKey_ = -1;
    std::vector<float> triangles, edges;
    firstVertex_.assign(1, 0);
    const int cells = static_cast<int>(snapshot->voidCells.size());
    for (int v = 0; v < cells; ++v) {
        const QPolygonF& polygon = renderer_.voidCellPolygon(v);
        for (const auto& t : triangulatePolygon(polygon)) {
            for (int corner : t) {
                triangles.push_back(float(polygon[corner].x()));
                triangles.push_back(float(polygon[corner].y()));
            }
        }
        firstVertex_.push_back(static_cast<std::int32_t>(triangles.size() / 2));
        for (qsizetype k = 0; k < polygon.size(); ++k) {
            const QPointF& a = polygon[k];
            const QPointF& b = polygon[(k + 1) % polygon.size()];
            edges.insert(edges.end(), {float(a.x()), float(a.y()), float(b.x()), float(b.y())});
        }
    }
    voidTriangles_.bind();
    voidTriangles_.allocate(triangles.data(), int(triangles.size() * sizeof(float)));
    voidEdges_.bind();
    voidEdges_.allocate(edges.data(), int(edges.size() * sizeof(float)));
    edgeVertices_ = static_cast<int>(edges.size() / 2);
}

void GlSceneLayer::drawVoidCells() {
    const SceneOptions& options = renderer_.options();
    if (options.voidCells == VoidCellShading::Off) {
        return; // a selected cell is an annotation, painted by the renderer
    }
    updateVoidCellMesh();
    const int cells = static_cast<int>(firstVertex_.size()) - 1;
    const int selected = options.selectedVoidCell;
    const std::int64_t key = std::int64_t(options.voidCells) * (std::int64_t(cells) + 2) +
                             (selected >= 0 && selected < cells ? selected + 1 : 0);
    if (key != colourKey_) {
        colourKey_ = key;
        std::vector<std::uint8_t> colours(std::size_t(firstVertex_.back()) * 4);
        for (int v = 0; v < cells; ++v) {
            // The selected cell is left out here: the renderer paints it on top, highlighted.
            std::uint8_t rgba[4] = {0, 0, 0, 0};
            if (v != selected) {
                toBytes(renderer_.voidCellColour(v).rgba(), rgba);
            }
            for (std::int32_t k = firstVertex_[v]; k < firstVertex_[v + 1]; ++k) {
                std::copy(rgba, rgba + 4, colours.begin() + 4 * std::size_t(k));
            }
        }
        voidColours_.bind();
        voidColours_.allocate(colours.data(), int(colours.size()));
    }
    const CellMatrix& h = renderer_.snapshot()->network.cell;
    const int images = options.periodicImages ? 1 : 0;
    flatProgram_.bind();
    setView(flatProgram_);
    // As the QPainter view's cosmetic 0.8 pixel pen of alpha 160: a one-pixel line of 0.8 x 160.
    const QVector4D edgeColour(30.0f / 255, 30.0f / 255, 90.0f / 255, 0.8f * 160.0f / 255);
    for (int pass = 0; pass < 2; ++pass) {
        (pass == 0 ? voidVao_ : voidEdgeVao_).bind();
        if (pass == 1) {
            glVertexAttrib4f(1, edgeColour.x(), edgeColour.y(), edgeColour.z(), edgeColour.w());
        }
        for (int i = -images; i <= images; ++i) {
            for (int j = -images; j <= images; ++j) {
                flatProgram_.setUniformValue(
                    "shift", QVector2D(float(h[0] * i + h[2] * j), float(h[1] * i + h[3] * j)));
                if (pass == 0) {
                    glDrawArrays(GL_TRIANGLES, 0, firstVertex_.back());
                } else {
                    glDrawArrays(GL_LINES, 0, edgeVertices_);
                }
            }
        }
    }
    voidEdgeVao_.release();
    flatProgram_.release();
}

void GlSceneLayer::drawForceChains() {
    const std::vector<ChainSegment> segments = renderer_.forceChainSegments(size());
    if (segments.empty()) {
        return;
    }
    std::vector<ChainInstance> data(segments.size());
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const ChainSegment& c = segments[k];
        data[k] = {float(c.a1), float(c.a2), float(c.b1), float(c.b2), float(c.width), {}};
        toBytes(c.colour, data[k].rgba);
    }
    // Instances are drawn in order: the strongest chains end up on top, as in the QPainter view.
    drawInstances(chainProgram_, chainVao_, chains_, data);
}

void GlSceneLayer::drawGrains() {
    const SnapshotPtr& snapshot = renderer_.snapshot();
    if (!snapshot) {
        return;
    }
    const std::vector<GrainInstance> grains = renderer_.grainInstances();
    std::vector<Instance> data(grains.size());
    for (std::size_t k = 0; k < grains.size(); ++k) {
        const GrainInstance& g = grains[k];
        const OvalShape& s = snapshot->shapes[g.shape];
        Instance& d = data[k];
        d.x1 = float(g.x1);
        d.x2 = float(g.x2);
        d.theta = float(g.theta);
        d.halfWidth = float(s.halfWidth);
        d.halfHeight = float(s.halfHeight);
        if (s.isDisk) {
            d.endOffset = d.sideOffset = 0.0f;
            d.endRadius = d.sideRadius = d.junctionX = float(s.halfWidth);
        } else {
            d.endOffset = float(s.halfWidth - s.endRadius);
            d.endRadius = float(s.endRadius);
            d.sideOffset = float(s.sideRadius - s.halfHeight);
            d.sideRadius = float(s.sideRadius);
            d.junctionX = float(s.halfWidth - s.endRadius + s.endRadius * s.cosJunction);
        }
        toBytes(g.colour, d.rgba);
    }
    drawInstances(program_, vao_, instances_, data);
}

} // namespace grainlab::ui
