#version 330 core
// The distance to the dot's centre in pixels gives its coverage (line.frag's for a
// zero-length segment).
flat in float vHalfWidth;  // px
flat in vec4 vColor;

out vec4 fragColor;

void main() {
    float reach = vHalfWidth + 1.0;                             // px, the point's half size
    float offCentre = 2.0 * reach * length(gl_PointCoord - 0.5);  // px
    float coverage = clamp(vHalfWidth - offCentre + 0.5, 0.0, 1.0);
    if (coverage <= 0.0) discard;
    fragColor = vec4(vColor.rgb, vColor.a * coverage);
}
