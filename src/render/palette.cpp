#include "render/palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace render {
namespace {

glm::u8vec4 toBytes(const glm::vec3& rgb) {
    const glm::vec3 c = glm::clamp(rgb, 0.0f, 1.0f) * 255.0f + 0.5f;
    return {static_cast<std::uint8_t>(c.x), static_cast<std::uint8_t>(c.y),
            static_cast<std::uint8_t>(c.z), 255};
}

// hue, saturation, value in [0, 1].
glm::vec3 hsvToRgb(float h, float s, float v) {
    const glm::vec3 k = glm::mod(glm::vec3(5.0f, 3.0f, 1.0f) + h * 6.0f, 6.0f);
    const glm::vec3 ramp = glm::clamp(glm::min(k, 4.0f - k), 0.0f, 1.0f);
    return v * (1.0f - s * ramp);
}

}  // namespace

glm::u8vec4 idColor(std::uint32_t id) {
    // Golden-ratio hue steps never repeat and keep neighbouring ids far apart on
    // the wheel; three value/saturation levels add variety between similar hues.
    constexpr float kGoldenRatio = 0.6180339887f;
    const float hue = std::fmod(0.58f + kGoldenRatio * static_cast<float>(id), 1.0f);
    const float saturation = std::array<float, 3>{0.72f, 0.60f, 0.80f}[id % 3];
    const float value = std::array<float, 3>{0.95f, 0.85f, 0.78f}[(id / 3) % 3];
    return toBytes(hsvToRgb(hue, saturation, value));
}

glm::u8vec4 speedColor(float speed, float maxSpeed) {
    // Viridis sampled every tenth from 0.1 to 1; its darkest tenth is cut so that slow spheres
    // stay visible on a dark projector image.
    static constexpr std::array<glm::vec3, 10> kStops = {{
        {0.283f, 0.141f, 0.458f},
        {0.254f, 0.265f, 0.530f},
        {0.207f, 0.372f, 0.553f},
        {0.164f, 0.471f, 0.558f},
        {0.128f, 0.567f, 0.551f},
        {0.135f, 0.659f, 0.518f},
        {0.267f, 0.749f, 0.441f},
        {0.478f, 0.821f, 0.318f},
        {0.741f, 0.873f, 0.150f},
        {0.993f, 0.906f, 0.144f},
    }};
    const float t = maxSpeed > 0.0f ? std::clamp(speed / maxSpeed, 0.0f, 1.0f) : 0.0f;
    const float x = t * static_cast<float>(kStops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), kStops.size() - 2);
    return toBytes(glm::mix(kStops[i], kStops[i + 1], x - static_cast<float>(i)));
}

glm::u8vec4 penetrationColor(double overlapOverRadius) {
    if (!(overlapOverRadius > kPenetrationShown[0])) return speedColor(0.0f, 1.0f);
    const double decades = std::log10(kPenetrationShown[1] / kPenetrationShown[0]);
    return speedColor(float(std::log10(overlapOverRadius / kPenetrationShown[0]) / decades), 1.0f);
}

glm::u8vec4 contactColor(physics::ContactState state) {
    switch (state) {
        case physics::ContactState::Free:
            return {110, 160, 230, 255};
        case physics::ContactState::Colliding:
            return {240, 90, 40, 255};
        case physics::ContactState::Static:
            return {70, 190, 90, 255};
    }
    return {110, 160, 230, 255};
}

}  // namespace render
