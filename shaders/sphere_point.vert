#version 330 core
// Most spheres: one point sprite each, sized to the exact screen-space bounding
// square of the sphere's outline. A single vertex per sphere is what keeps
// 100 000 spheres interactive on a software rasteriser. The CPU sends here only
// spheres wholly beyond the near plane whose centre stays inside the viewport.
layout(location = 1) in vec3 aCenter;   // m, world
layout(location = 2) in float aRadius;  // m
layout(location = 3) in vec4 aColor;

uniform mat4 uView;
uniform mat4 uProjection;
uniform vec2 uViewportSize;   // px
uniform float uMarginPixels;  // room around the outline for the anti-aliased rim, px

flat out vec3 vCenter;   // m, view space
flat out float vRadius;  // m
flat out vec3 vColor;

// Tangents (x / depth) of the two rays that graze the sphere in the plane of
// one screen axis, for the centre at (offset along that axis, depth > 0).
vec2 grazingTangents(float offset, float depth, float radius) {
    float length2 = offset * offset + depth * depth;
    float sine = radius * inversesqrt(length2);
    float cosine = sqrt(max(1.0 - sine * sine, 0.0));
    vec2 low = vec2(offset * cosine - depth * sine, depth * cosine + offset * sine);
    vec2 high = vec2(offset * cosine + depth * sine, depth * cosine - offset * sine);
    return vec2(low.x / low.y, high.x / high.y);
}

void main() {
    vec3 center = (uView * vec4(aCenter, 1.0)).xyz;
    vCenter = center;
    vRadius = aRadius;
    vColor = aColor.rgb;
    float depth = -center.z;
    // NDC bounds of the outline: tangent times the projection's focal terms.
    vec2 boundsX = grazingTangents(center.x, depth, aRadius) * uProjection[0][0];
    vec2 boundsY = grazingTangents(center.y, depth, aRadius) * uProjection[1][1];
    vec2 middle = vec2(boundsX.x + boundsX.y, boundsY.x + boundsY.y) * 0.5;
    vec2 sizePixels = vec2(boundsX.y - boundsX.x, boundsY.y - boundsY.x) * 0.5 * uViewportSize;
    gl_PointSize = max(sizePixels.x, sizePixels.y) + 2.0 * uMarginPixels;
    vec4 clip = uProjection * vec4(center, 1.0);
    gl_Position = vec4(middle, clip.z / clip.w, 1.0);
}
