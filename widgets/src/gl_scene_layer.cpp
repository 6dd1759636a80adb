// See gl_scene_layer.h.
#include "grainlab/ui/gl_scene_layer.h"

#include <vector>

#include <QPainter>

#include "grainlab/ui/scene_renderer.h"

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

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec3 pose;
layout(location = 2) in vec2 halfSize;
layout(location = 3) in vec4 arcs;
layout(location = 4) in float junctionX;
layout(location = 5) in vec4 colour;
uniform vec2 origin;   // screen position of the world origin [px]
uniform float scale;   // [px/m]
uniform vec2 viewport; // [px]
out vec2 body;
flat out vec4 fill;
flat out vec4 arcParameters;
flat out float junction;
flat out float radiusPixels;
void main() {
    // The body-frame bounding box, grown by 1.5 px for the antialiased edge.
    body = corner * (halfSize + vec2(1.5 / scale));
    float c = cos(pose.z), s = sin(pose.z);
    vec2 w = pose.xy + vec2(c * body.x - s * body.y, s * body.x + c * body.y);
    vec2 screen = vec2(origin.x + scale * w.y, origin.y - scale * w.x); // x1 up, x2 right
    gl_Position = vec4(screen.x / viewport.x * 2.0 - 1.0, 1.0 - screen.y / viewport.y * 2.0, 0.0, 1.0);
    fill = colour;
    arcParameters = arcs;
    junction = junctionX;
    radiusPixels = halfSize.x * scale;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec2 body;
flat in vec4 fill;
flat in vec4 arcParameters;
flat in float junction;
flat in float radiusPixels;
uniform float scale;
out vec4 colour;
void main() {
    float endOffset = arcParameters.x, r = arcParameters.y;
    float sideOffset = arcParameters.z, R = arcParameters.w;
    // Signed distance to the oval: union of the end discs with the part of the side discs'
    // intersection between the junctions (the end discs are internally tangent to both).
    float right = length(body - vec2(endOffset, 0.0)) - r;
    float left = length(body + vec2(endOffset, 0.0)) - r;
    float top = length(body - vec2(0.0, -sideOffset)) - R;
    float bottom = length(body - vec2(0.0, sideOffset)) - R;
    float slab = abs(body.x) - junction;
    float d = min(min(right, left), max(max(top, bottom), slab)) * scale; // [px]
    // Grains wider than a few pixels get a one-pixel darker outline centred on the boundary,
    // like the QPainter view's pen (which reaches half a pixel outside).
    bool outlined = radiusPixels > 6.0;
    float alpha = clamp((outlined ? 1.0 : 0.5) - d, 0.0, 1.0);
    if (alpha <= 0.0) {
        discard;
    }
    vec3 rgb = fill.rgb;
    if (outlined) {
        rgb = mix(rgb, rgb * 0.625, clamp(2.0 * (d + 1.0), 0.0, 1.0));
    }
    colour = vec4(rgb, fill.a * alpha);
}
)";

} // namespace

GlSceneLayer::GlSceneLayer(const SceneRenderer& renderer, QWidget* parent)
    : QOpenGLWidget(parent), renderer_(renderer) {
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
    instances_.destroy();
    quad_.destroy();
    vao_.destroy();
    doneCurrent();
}

void GlSceneLayer::initializeGL() {
    initializeOpenGLFunctions();
    if (!program_.addShaderFromSourceCode(QOpenGLShader::Vertex, kVertexShader) ||
        !program_.addShaderFromSourceCode(QOpenGLShader::Fragment, kFragmentShader) ||
        !program_.link()) {
        failure_ = program_.log();
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
    const auto offset = [](std::size_t bytes) { return reinterpret_cast<const void*>(bytes); };
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
    ready_ = true;
}

void GlSceneLayer::paintGL() {
    QPainter painter(this);
    if (!ready_) {
        renderer_.render(painter, size());
        return;
    }
    renderer_.renderBackground(painter, size());
    painter.beginNativePainting();
    drawGrains();
    painter.endNativePainting();
    renderer_.renderOverlays(painter, size(), true);
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
        d.rgba[0] = std::uint8_t(qRed(g.colour));
        d.rgba[1] = std::uint8_t(qGreen(g.colour));
        d.rgba[2] = std::uint8_t(qBlue(g.colour));
        d.rgba[3] = std::uint8_t(qAlpha(g.colour));
    }
    const qreal ratio = devicePixelRatioF();
    glViewport(0, 0, GLsizei(width() * ratio), GLsizei(height() * ratio));
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program_.bind();
    const ViewTransform& view = renderer_.view();
    const QPointF origin = view.toScreen(0.0, 0.0);
    program_.setUniformValue("origin", QVector2D(float(origin.x()), float(origin.y())));
    program_.setUniformValue("scale", float(view.pixelsPerMetre()));
    program_.setUniformValue("viewport", QVector2D(float(width()), float(height())));
    vao_.bind();
    instances_.bind();
    instances_.allocate(data.data(), int(data.size() * sizeof(Instance)));
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(data.size()));
    vao_.release();
    program_.release();
}

} // namespace grainlab::ui
