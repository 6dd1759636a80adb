#version 330 core
// Grains: keeps the oval by its signed distance, antialiased, outlined when wide enough.
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
