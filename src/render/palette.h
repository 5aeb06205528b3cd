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
// The same colormap over the decades of a sphere's deepest overlap / r, kPenetrationShown[0]
// (and none) the darkest, kPenetrationShown[1] and deeper the brightest: 22's pyramids, 0.76,
// 0.11, 0 and 0.02 % of r deep, look alike in any other colouring.
constexpr double kPenetrationShown[2] = {1e-4, 1e-1};  // 0.01 % and 10 % of r
glm::u8vec4 penetrationColor(double overlapOverRadius);
// Free: soft blue; colliding: orange-red; static contact: green.
glm::u8vec4 contactColor(physics::ContactState state);

}  // namespace render
