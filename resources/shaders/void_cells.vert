#version 330 core
// Void cells: world-space vertices with a colour, drawn at a periodic-image shift.
layout(location = 0) in vec2 world; // x1, x2 [m]
layout(location = 1) in vec4 colour;
uniform vec2 origin;
uniform float scale;
uniform vec2 viewport;
uniform vec2 shift; // periodic image [m]
flat out vec4 fill;
void main() {
    vec2 w = world + shift;
    vec2 screen = vec2(origin.x + scale * w.y, origin.y - scale * w.x);
    gl_Position = vec4(screen.x / viewport.x * 2.0 - 1.0, 1.0 - screen.y / viewport.y * 2.0, 0.0, 1.0);
    fill = colour;
}
