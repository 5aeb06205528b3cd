#version 330 core
// A vertical gradient with a soft darkening towards the corners, so that the
// eye goes to the centre of the image where the spheres are.
in vec2 vUv;
uniform vec3 uTop;     // colour at the top edge
uniform vec3 uBottom;  // colour at the bottom edge
out vec4 fragColor;

void main() {
    vec3 color = mix(uBottom, uTop, smoothstep(0.0, 1.0, vUv.y));
    vec2 offset = vUv - 0.5;
    color *= 1.0 - 0.25 * dot(offset, offset);
    fragColor = vec4(color, 1.0);
}
