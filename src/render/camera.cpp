#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace render {
namespace {

constexpr float kOrbitRate = 0.006f;     // rad per pixel of drag
constexpr float kZoomPerStep = 0.9f;     // distance factor per wheel step
constexpr float kMaxElevation = 1.55f;   // rad, just short of the pole (view() needs it)
constexpr float kMinDistance = 0.02f;    // m
constexpr float kMaxDistance = 1000.0f;  // m
constexpr float kFitMargin = 1.08f;      // room around a fitted box
constexpr glm::vec3 kUp{0.0f, 0.0f, 1.0f};

}  // namespace

glm::vec3 Camera::forward() const {
    const float c = std::cos(elevation);
    return -glm::vec3(c * std::cos(azimuth), c * std::sin(azimuth), std::sin(elevation));
}

glm::vec3 Camera::position() const { return target - distance * forward(); }

glm::mat4 Camera::view() const { return glm::lookAt(position(), target, kUp); }

// Near and far follow the distance, so that zooming in on one sphere and
// looking at the whole box both keep depth precision (ratio 2500 for 24 bits).
float Camera::nearPlane() const { return distance * 0.02f; }
float Camera::farPlane() const { return distance * 50.0f; }

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(fovY, aspect > 0.0f ? aspect : 1.0f, nearPlane(), farPlane());
}

void Camera::orbit(float dxPixels, float dyPixels) {
    azimuth -= dxPixels * kOrbitRate;
    azimuth = std::remainder(azimuth, 2.0f * glm::pi<float>());
    elevation = std::clamp(elevation + dyPixels * kOrbitRate, -kMaxElevation, kMaxElevation);
}

void Camera::zoom(float scrollSteps) {
    distance =
        std::clamp(distance * std::pow(kZoomPerStep, scrollSteps), kMinDistance, kMaxDistance);
}

void Camera::pan(float dxPixels, float dyPixels, float viewportHeightPixels) {
    if (viewportHeightPixels <= 0.0f) return;
    // m per pixel in the plane through the target, facing the camera.
    const float metresPerPixel = 2.0f * distance * std::tan(0.5f * fovY) / viewportHeightPixels;
    const glm::vec3 right = glm::normalize(glm::cross(forward(), kUp));
    const glm::vec3 up = glm::cross(right, forward());
    target += metresPerPixel * (-dxPixels * right + dyPixels * up);
}

void Camera::fitBox(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect) {
    target = 0.5f * (boxMin + boxMax);
    distance = fitDistance(boxMin, boxMax, aspect);
}

void Camera::followAspect(const glm::vec3& boxMin, const glm::vec3& boxMax, float before, float after) {
    if (before <= 0.0f || after == before) return;
    distance *= fitDistance(boxMin, boxMax, after) / fitDistance(boxMin, boxMax, before);
}

float Camera::fitDistance(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect) const {
    const glm::vec3 centre = 0.5f * (boxMin + boxMax);
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, kUp));
    const glm::vec3 up = glm::cross(right, f);
    const float tanY = std::tan(0.5f * fovY);
    const float tanX = tanY * (aspect > 0.0f ? aspect : 1.0f);
    // The eye must be far enough that every corner lies inside both half-angles:
    // a corner at depth z (towards the scene) and offset x needs d >= |x|/tan + z.
    float needed = kMinDistance;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{corner & 1 ? boxMax.x : boxMin.x, corner & 2 ? boxMax.y : boxMin.y,
                          corner & 4 ? boxMax.z : boxMin.z};
        const glm::vec3 o = p - centre;
        const float z = glm::dot(o, f);
        needed = std::max(needed, std::abs(glm::dot(o, right)) * kFitMargin / tanX - z);
        needed = std::max(needed, std::abs(glm::dot(o, up)) * kFitMargin / tanY - z);
    }
    return std::min(needed, kMaxDistance);
}

void Camera::reset(const glm::vec3& boxMin, const glm::vec3& boxMax, float aspect) {
    *this = Camera{};
    fitBox(boxMin, boxMax, aspect);
}

glm::vec3 Camera::project(const glm::vec3& worldPoint, const glm::vec2& viewportSize) const {
    const glm::vec4 clip =
        projection(viewportSize.x / viewportSize.y) * view() * glm::vec4(worldPoint, 1.0f);
    if (clip.w <= 0.0f) return {-1.0f, -1.0f, -1.0f};  // behind the eye
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * viewportSize.x, (0.5f - ndc.y * 0.5f) * viewportSize.y,
            ndc.z * 0.5f + 0.5f};
}

Ray Camera::rayThroughPixel(const glm::vec2& pixel, const glm::vec2& viewportSize) const {
    const glm::vec2 ndc{pixel.x / viewportSize.x * 2.0f - 1.0f,
                        1.0f - pixel.y / viewportSize.y * 2.0f};
    const float tanY = std::tan(0.5f * fovY);
    const float tanX = tanY * viewportSize.x / viewportSize.y;
    const glm::vec3 f = forward();
    const glm::vec3 right = glm::normalize(glm::cross(f, kUp));
    const glm::vec3 up = glm::cross(right, f);
    return {position(), glm::normalize(f + ndc.x * tanX * right + ndc.y * tanY * up)};
}

}  // namespace render
