#pragma once
// An orbit camera around a target point, z up. Pure math: the app turns mouse
// and keys into orbit / zoom / pan calls; picking and tests use project() and
// rayThroughPixel(). Pixel coordinates have their origin at the top-left of
// the viewport, like mouse positions and the rows of render::readPixelsRGBA.
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace render {

struct Ray {
    glm::vec3 origin{0.0f};     // m
    glm::vec3 direction{0.0f};  // unit
};

class Camera {
  public:
    glm::vec3 target{0.0f, 0.0f, 0.5f};  // m, the point orbited around
    float azimuth = -1.05f;              // rad, around +z, measured from +x
    float elevation = 0.42f;             // rad, above the xy plane, in (-pi/2, pi/2)
    float distance = 4.0f;               // m, from the target
    float fovY = 0.70f;                  // rad, vertical field of view

    glm::vec3 position() const;  // m
    glm::vec3 forward() const;   // unit, from the camera towards the target
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;  // aspect = width / height
    float nearPlane() const;                   // m
    float farPlane() const;                    // m

    // Mouse drag in pixels: right turns the scene right, down raises the eye.
    void orbit(float dxPixels, float dyPixels);
    // Mouse wheel steps: positive moves closer (10 % per step).
    void zoom(float scrollSteps);
    // Mouse drag in pixels: the point under the cursor follows it.
    void pan(float dxPixels, float dyPixels, float viewportHeightPixels);
    // Keeps the angles; moves the target to the box centre and the eye back until
    // the whole box is in view (with a small margin).
    void fitBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect);
    // The distance fitBox would choose for these angles, without moving (m).
    float fitDistance(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect) const;
    // The view changed shape from aspect `before` to `after` (a window resized, a phone
    // turned): keeps the angles, the target and the zoom relative to the box, so that the
    // box still fits as it did.
    void followAspect(const glm::vec3& boxMin, const glm::vec3& boxMax, float before, float after);
    // The default three-quarter view of the box, then fitBox.
    void reset(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect);

    // Pixel position (x right, y down, from the viewport's top-left; pixel i spans
    // [i, i + 1)) and window depth in [0, 1] (outside it: behind the eye or beyond far).
    glm::vec3 project(const glm::vec3& worldPoint, const glm::vec2& viewportSize) const;
    // The ray from the eye through a pixel position (same convention: i + 0.5 is a centre).
    Ray rayThroughPixel(const glm::vec2& pixel, const glm::vec2& viewportSize) const;
};

}  // namespace render
