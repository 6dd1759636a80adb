#version 330 core
// Grains (widgets/src/gl_scene_layer.cpp): one instanced quad per oval, its body-frame box.
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
