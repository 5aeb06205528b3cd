#version 330 core
// A dot as one point of its width in pixels: one vertex and one primitive, where a
// zero-length segment (line.vert) takes four and two triangles. A software GL sets up
// a point for about half of what a quad costs, and a pile's contacts are thousands of
// dots. A point whose centre leaves the view is clipped whole.
layout(location = 1) in vec3 aPosition;  // m, world, per instance
layout(location = 2) in vec4 aColor;     // per instance
layout(location = 3) in float aSize;     // px, diameter, per instance

uniform mat4 uViewProjection;
uniform float uWidthScale;  // HiDPI factor on every width
uniform float uDepthBias;   // NDC depth pulled towards the eye, as line.vert's

flat out float vHalfWidth;  // px
flat out vec4 vColor;

void main() {
    vec4 clip = uViewProjection * vec4(aPosition, 1.0);
    gl_Position = vec4(clip.xy, clip.z - uDepthBias * clip.w, clip.w);
    float halfWidth = 0.5 * aSize * uWidthScale;
    gl_PointSize = 2.0 * (halfWidth + 1.0);  // one more pixel each side for the anti-aliased rim
    vHalfWidth = halfWidth;
    vColor = aColor;
}
