#pragma once
// The colours of spheres, chosen to read well on a projector: saturated hues
// that stay distinct under shading, against the renderer's grey-blue background.
#include <cstdint>
#include <glm/gtc/type_precision.hpp>

#include "physics/world.h"

namespace render {

// A varied palette of saturated hues (golden-angle steps), stable per id.
glm::u8vec4 idColor(std::uint32_t id);
// A perceptual colormap (viridis, without its darkest tenth) of speed / maxSpeed, m/s.
glm::u8vec4 speedColor(float speed, float maxSpeed);
// Free: soft blue; colliding: orange-red; static contact: green.
glm::u8vec4 contactColor(physics::ContactState state);

}  // namespace render
