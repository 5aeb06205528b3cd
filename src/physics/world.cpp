#include "physics/world.h"

#include <glm/geometric.hpp>

namespace physics {

Plane faceFor(const Plane& plane, const glm::dvec3& p) {
    if (plane.thickness <= 0.0) return plane;
    const double side = glm::dot(p - plane.point, plane.normal) >= 0.0 ? 1.0 : -1.0;
    return {plane.point + (0.5 * plane.thickness * side) * plane.normal, side * plane.normal, 0.0};
}

void World::addSphere(const glm::dvec3& p, const glm::dvec3& v, double r, double m) {
    position.push_back(p);
    velocity.push_back(v);
    radius.push_back(r);
    mass.push_back(m);
    contactState.push_back(ContactState::Free);
}

void World::removeSphere(std::size_t index) {
    position.erase(position.begin() + static_cast<std::ptrdiff_t>(index));
    velocity.erase(velocity.begin() + static_cast<std::ptrdiff_t>(index));
    radius.erase(radius.begin() + static_cast<std::ptrdiff_t>(index));
    mass.erase(mass.begin() + static_cast<std::ptrdiff_t>(index));
    contactState.erase(contactState.begin() + static_cast<std::ptrdiff_t>(index));
}

}  // namespace physics
