#pragma once
// Internal to spheres_render: what every pass needs to know about the frame.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace render {

struct RenderStyle;

// Largest point sprite drawn (spheres, dots), px: below every implementation's limit.
// Larger ones are few enough for quads.
constexpr float kMaxPointPixels = 64.0f;

struct FrameContext {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
    glm::vec3 cameraPosition{0.0f};  // m, world
    glm::vec4 viewport{0.0f};        // x, y, width, height in framebuffer pixels
    glm::vec2 viewportSize{1.0f};    // px
    float nearPlane = 0.0f;          // m
    float farPlane = 0.0f;           // m
    float pixelSize = 0.0f;          // view-space size of a pixel at 1 m: 2 tan(fovY/2) / height
    glm::vec3 lightView{0.0f};       // unit, towards the key light, view space
    glm::vec3 lightWorld{0.0f};      // the same, world space
    glm::vec3 upView{0.0f};          // world +z in view space
    const RenderStyle* style = nullptr;
};

}  // namespace render
