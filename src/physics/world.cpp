#include "physics/world.h"

namespace physics {

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
