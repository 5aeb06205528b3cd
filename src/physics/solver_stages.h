#pragma once
// The stages the two methods are made of (second deck, "Summary with multiple
// particles"). Internal to the physics library.
#include <cstdint>

#include "physics/collision_response.h"
#include "physics/step.h"

namespace physics {

// Field forces, semi-implicit Euler (slide 2): v <- v + h g, then p <- p + h v.
void integrateVelocity(World& world, const glm::dvec3& gravity, double h);
void integratePosition(World& world, double h);

// Fills world.workspace.pairs with the candidate pairs in the order the passes
// visit them (index, reversed, or shuffled with the world's seed and step count).
void findOrderedPairs(World& world, const Params& params, StepStats& stats);

// Narrow phase, slide 9: the pair touches when |p1 - p2| <= r1 + r2.
struct SphereContact {
    glm::dvec3 u{0.0, 0.0, 1.0};  // (p1 - p2) / |p1 - p2|, from 2 to 1
    double depth = 0.0;           // m, d = r1 + r2 - |p1 - p2| (>= 0 when touching)
};
bool touching(const World& world, const SpherePair& pair, SphereContact& contact);

// Slide 3: the sphere touches the plane when (p - a).n <= r.
bool touching(const World& world, std::uint32_t i, const Plane& plane);

// The velocity response to one contact (collision_response.h), recorded in the
// spheres' contact state, counted in the stats (contacts on pass 0 only) and, when
// world.recordContacts is on, logged as a ContactEvent.
void respondToContact(World& world, const SpherePair& pair, const SphereContact& contact,
                      const Params& params, StepStats& stats, int pass);
// `face` is faceFor(world.planes[planeIndex], the sphere's centre).
void respondToContact(World& world, std::uint32_t i, std::size_t planeIndex, const Plane& face,
                      const Params& params, StepStats& stats, int pass);

// Velocity response to every touching pair (in pass order), then every wall contact.
void respondToAllContacts(World& world, const Params& params, StepStats& stats, int pass);

}  // namespace physics
