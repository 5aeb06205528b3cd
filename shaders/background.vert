#version 330 core
// One triangle that covers the viewport; no vertex buffer needed.
out vec2 vUv;  // 0..1 across the viewport, y up

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
