#version 330 core
// Force chains: keeps what lies within half the width of the segment (round caps).
in vec2 pixel;
flat in vec2 a;
flat in vec2 b;
flat in float halfWidth;
flat in vec4 fill;
out vec4 colour;
void main() {
    vec2 pa = pixel - a, ba = b - a;
    float t = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
    float alpha = clamp(halfWidth + 0.5 - length(pa - ba * t), 0.0, 1.0);
    if (alpha <= 0.0) {
        discard;
    }
    colour = vec4(fill.rgb, fill.a * alpha);
}
