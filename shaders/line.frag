#version 330 core
// Distance to the segment in pixels gives the coverage of a round-capped line.
noperspective in vec2 vLocal;
flat in float vLength;
flat in float vHalfWidth;
flat in vec4 vColor;

out vec4 fragColor;

void main() {
    float beyond = max(max(-vLocal.x, vLocal.x - vLength), 0.0);
    float offAxis = length(vec2(beyond, vLocal.y));  // px
    float coverage = clamp(vHalfWidth - offAxis + 0.5, 0.0, 1.0);
    if (coverage <= 0.0) discard;
    fragColor = vec4(vColor.rgb, vColor.a * coverage);
}
