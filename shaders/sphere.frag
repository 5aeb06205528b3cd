#version 330 core
// Ray-cast sphere impostor: exact outline, normal and depth for a handful of
// instructions. The ray comes from the pixel position, so the same shader
// serves point sprites and squares.
flat in vec3 vCenter;   // m, view space
flat in float vRadius;  // m
flat in vec3 vColor;

uniform mat4 uProjection;
uniform vec4 uViewport;        // x, y, width, height in framebuffer pixels
uniform vec3 uLightDirection;  // view space, unit, towards the light
uniform vec3 uUpDirection;     // world +z in view space, for the sky/ground ambient
uniform bool uCoverageAlpha;   // alpha is the edge coverage (alpha to coverage, or blended)
uniform int uPart;             // 0: every fragment; 1: where the sphere covers the pixel whole;
                               // 2: its edge only (coverage below 1)

out vec4 fragColor;

void main() {
    vec2 ndc = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw * 2.0 - 1.0;
    vec3 ray = normalize(vec3(ndc.x / uProjection[0][0], ndc.y / uProjection[1][1], -1.0));
    float along = dot(ray, vCenter);                       // m, to the closest approach
    // Squared miss distance, m^2, as the offset's length: |c|^2 - along^2 would cancel
    // in single precision (an error of 1e-7 |c|^2, most of a pixel for small spheres).
    vec3 offset = vCenter - ray * along;
    float miss2 = dot(offset, offset);
    float miss = sqrt(max(miss2, 0.0));
    // Inside the outline > 0, in pixels: the anti-aliased edge.
    float edge = (vRadius - miss) / max(fwidth(miss), 1e-7);
    float coverage = clamp(edge + 0.5, 0.0, 1.0);
    if (uCoverageAlpha ? coverage <= 0.0 : edge < 0.0) discard;
    if ((uPart == 1 && coverage < 1.0) || (uPart == 2 && coverage >= 1.0)) discard;

    float t = along - sqrt(max(vRadius * vRadius - miss2, 0.0));
    vec3 hit = ray * t;
    vec3 normal = normalize(hit - vCenter);
    // Depth of the true surface: only z and w of the projection are needed.
    float clipZ = uProjection[2][2] * hit.z + uProjection[3][2];
    gl_FragDepth = 0.5 * clipZ / -hit.z + 0.5;

    float diffuse = max(dot(normal, uLightDirection), 0.0);
    float sky = 0.5 + 0.5 * dot(normal, uUpDirection);
    vec3 ambient = mix(vec3(0.22, 0.21, 0.24), vec3(0.48, 0.50, 0.55), sky);
    vec3 halfway = normalize(uLightDirection - ray);
    float specular = 0.35 * pow(max(dot(normal, halfway), 0.0), 40.0);
    vec3 color = vColor * (ambient + 0.72 * diffuse) + specular;
    fragColor = vec4(color, uCoverageAlpha ? coverage : 1.0);
}
