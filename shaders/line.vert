#version 330 core
// A segment as a screen-space quad of constant width in pixels with round caps
// (core profile has no wide lines); a zero-length segment draws a dot.
layout(location = 0) in vec2 aCorner;  // x: 0 at a, 1 at b; y: -1 or +1 across
layout(location = 1) in vec3 aA;       // m, world, per instance
layout(location = 2) in vec3 aB;       // m, world, per instance
layout(location = 3) in vec4 aColor;   // per instance
layout(location = 4) in float aWidth;  // px, per instance

uniform mat4 uViewProjection;
uniform vec2 uViewportSize;  // px
uniform float uWidthScale;   // HiDPI factor on every width
uniform float uDepthBias;    // NDC depth pulled towards the eye, so lines on a face win

noperspective out vec2 vLocal;   // px: along the segment from a, across from its axis
flat out float vLength;          // px
flat out float vHalfWidth;       // px
flat out vec4 vColor;

// Moves the endpoint behind the eye onto the plane w = epsilon along the segment.
vec4 clipToFront(vec4 p, vec4 other) {
    const float kEpsilon = 1e-4;
    if (p.w >= kEpsilon) return p;
    return mix(p, other, (kEpsilon - p.w) / (other.w - p.w));
}

void main() {
    vec4 clipA = uViewProjection * vec4(aA, 1.0);
    vec4 clipB = uViewProjection * vec4(aB, 1.0);
    if (clipA.w < 1e-4 && clipB.w < 1e-4) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // wholly behind the eye
        return;
    }
    vec4 a = clipToFront(clipA, clipB);
    vec4 b = clipToFront(clipB, clipA);
    vec2 screenA = (a.xy / a.w * 0.5 + 0.5) * uViewportSize;
    vec2 screenB = (b.xy / b.w * 0.5 + 0.5) * uViewportSize;
    vec2 delta = screenB - screenA;
    float pixels = length(delta);
    vec2 along = pixels > 1e-3 ? delta / pixels : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);

    float halfWidth = 0.5 * aWidth * uWidthScale;
    float reach = halfWidth + 1.0;  // px, one more for the anti-aliased rim
    float s = aCorner.x < 0.5 ? -reach : pixels + reach;
    vec2 screen = screenA + along * s + across * aCorner.y * reach;
    vec4 end = aCorner.x < 0.5 ? a : b;
    gl_Position = vec4((screen / uViewportSize * 2.0 - 1.0) * end.w,
                       end.z - uDepthBias * end.w, end.w);
    vLocal = vec2(s, aCorner.y * reach);
    vLength = pixels;
    vHalfWidth = halfWidth;
    vColor = aColor;
}
