#version 330 core
// Spheres too large or too close to the viewport's edge for a point sprite:
// one camera-facing square per sphere, just large enough to cover its outline.
// sphere.frag ray-casts the exact sphere inside it.
layout(location = 0) in vec2 aCorner;   // (-1..1, -1..1)
layout(location = 1) in vec3 aCenter;   // m, world, per instance
layout(location = 2) in float aRadius;  // m, per instance
layout(location = 3) in vec4 aColor;    // per instance

uniform mat4 uView;
uniform mat4 uProjection;
uniform float uPixelSize;     // view-space size of one pixel at 1 m: 2 tan(fovY/2) / height
uniform float uMarginPixels;  // room around the outline for the anti-aliased rim, px

flat out vec3 vCenter;   // m, view space
flat out float vRadius;  // m
flat out vec3 vColor;

void main() {
    vec3 center = (uView * vec4(aCenter, 1.0)).xyz;
    float distance2 = dot(center, center);
    float radius2 = aRadius * aRadius;
    vCenter = center;
    vRadius = aRadius;
    vColor = aColor.rgb;
    if (distance2 <= radius2 * 1.0001) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // eye inside the sphere: drop it
        return;
    }
    // The cone of rays grazing the sphere cuts the plane through its centre
    // (facing the eye) in a circle of radius r d / sqrt(d^2 - r^2).
    float halfSize = aRadius * inversesqrt(1.0 - radius2 / distance2) +
                     uMarginPixels * uPixelSize * max(-center.z, 0.0);
    vec3 toCenter = center * inversesqrt(distance2);
    vec3 right = normalize(cross(toCenter, vec3(0.0, 1.0, 0.0)));
    vec3 up = cross(right, toCenter);
    vec3 corner = center + (aCorner.x * right + aCorner.y * up) * halfSize;
    gl_Position = uProjection * vec4(corner, 1.0);
}
