#version 330 core
// Force chains: one quad per segment, grown by half the width and a pixel around it.
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 ends;  // a1, a2, b1, b2 [m]
layout(location = 2) in float width; // [px]
layout(location = 3) in vec4 colour;
uniform vec2 origin;
uniform float scale;
uniform vec2 viewport;
out vec2 pixel;
flat out vec2 a;
flat out vec2 b;
flat out float halfWidth;
flat out vec4 fill;
void main() {
    a = vec2(origin.x + scale * ends.y, origin.y - scale * ends.x);
    b = vec2(origin.x + scale * ends.w, origin.y - scale * ends.z);
    halfWidth = 0.5 * width;
    float len = length(b - a);
    vec2 u = len > 1e-6 ? (b - a) / len : vec2(1.0, 0.0);
    vec2 n = vec2(-u.y, u.x);
    float reach = halfWidth + 1.0;
    pixel = 0.5 * (a + b) + u * corner.x * (0.5 * len + reach) + n * corner.y * reach;
    gl_Position = vec4(pixel.x / viewport.x * 2.0 - 1.0, 1.0 - pixel.y / viewport.y * 2.0, 0.0, 1.0);
    fill = colour;
}
