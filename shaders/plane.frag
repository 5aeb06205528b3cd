#version 330 core
// A wall, floor or extra plane: a flat tint, lit a little by its orientation,
// with an optional anti-aliased grid (floor) drawn in world units.
in vec3 vWorld;

uniform vec4 uColor;          // rgb and opacity of the face
uniform vec3 uNormal;         // unit, world
uniform vec3 uLightWorld;     // unit, world, towards the light
uniform bool uGrid;
uniform vec3 uAxisU;          // unit, world: the grid's two directions
uniform vec3 uAxisV;
uniform float uGridSpacing;   // m between minor lines
uniform int uMajorEvery;      // minor lines per major line
uniform vec4 uGridColor;      // rgb and strength of minor lines (major: twice)

out vec4 fragColor;

// 1 on a line of the grid with unit spacing in `coord`, 0 between; about 1 px wide.
float gridLine(vec2 coord) {
    vec2 width = fwidth(coord);
    vec2 offLine = abs(fract(coord - 0.5) - 0.5) / max(width, 1e-6);  // px
    float line = 1.0 - min(min(offLine.x, offLine.y), 1.0);
    // Fade where lines get denser than ~3 px apart (grazing angles) to avoid moire.
    return line * clamp(1.5 - 3.0 * max(width.x, width.y), 0.0, 1.0);
}

void main() {
    float light = 0.78 + 0.22 * abs(dot(uNormal, uLightWorld));
    vec3 color = uColor.rgb * light;
    if (uGrid) {
        vec2 coord = vec2(dot(vWorld, uAxisU), dot(vWorld, uAxisV)) / uGridSpacing;
        float minor = gridLine(coord);
        float major = gridLine(coord / float(uMajorEvery));
        float strength = max(minor * uGridColor.a, major * min(2.0 * uGridColor.a, 1.0));
        color = mix(color, uGridColor.rgb, strength);
    }
    fragColor = vec4(color, uColor.a);
}
