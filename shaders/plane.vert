#version 330 core
// A clipped plane polygon, already in world coordinates.
layout(location = 0) in vec3 aPosition;  // m, world

uniform mat4 uViewProjection;

out vec3 vWorld;  // m

void main() {
    vWorld = aPosition;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
