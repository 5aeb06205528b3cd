#pragma once
// Measurements of a world, computed on demand (never inside the step).
#include <cstdint>

#include "physics/params.h"
#include "physics/world.h"

namespace physics {

struct Diagnostics {
    double kinetic = 0.0;     // J, sum 1/2 m |v|^2
    double potential = 0.0;   // J, -sum m g.p
    double total = 0.0;       // J, kinetic + potential
    double modified = 0.0;    // J, E~ = sum m (-g.p + 1/2 |v + (h/2) g|^2), exact for free flight
    glm::dvec3 momentum{0.0}; // kg m/s
    double momentumScale = 0.0;  // kg m/s, sum m |v|: what the momentum's rounding is relative to
    std::uint64_t sphereContacts = 0;  // overlapping pairs now
    std::uint64_t wallContacts = 0;    // spheres touching or crossing a plane now
    double maxPenetration = 0.0;       // deepest overlap divided by the smaller radius
    std::uint64_t hash = 0;            // FNV-1a over positions and velocities
};

Diagnostics measure(const World& world, const Params& params);

// The momentum as the readouts show it: a component within rounding of zero (1e-12 of
// sum m |v|, far below anything a readout or a property check can tell) reads 0, so that a
// symmetric answer's reads p (0, 0, 2), not (5.55e-17, 0, 2).
glm::dvec3 momentumShown(const Diagnostics& d);

// The energy semi-implicit Euler conserves exactly in free flight (physics.md), J.
double modifiedEnergy(const World& world, const Params& params);

// FNV-1a 64 over the bytes of every position and velocity: equal states, equal hashes.
std::uint64_t stateHash(const World& world);

// Spheres held in mid-air (slide 13's flaw with the velocity method): in static contact
// (green), touching no plane below them and carried by no chain of spheres, each lower
// than the one above it, down to such a plane. Only v <- mu v on their own velocity
// holds them there: friction on spheres that touch only each other.
std::size_t spheresHeldInMidAir(const World& world, const Params& params);

// Each sphere's deepest overlap: with another sphere over the smaller radius, with a plane
// over its own; 0 where it overlaps nothing. What "colour by penetration" shows.
std::vector<double> deepestOverlaps(const World& world);

// How far the state is from its mirror image in `mirror` (a point and a unit normal):
// each sphere's partner is the sphere nearest its reflected centre; the largest distance
// between partner and reflection (m), and between the partner's velocity and the
// reflected velocity (m/s). Both 0 for a mirror-symmetric state. O(N^2): worlds of at
// most kMostMirroredSpheres spheres, else both are -1 (not measured).
struct MirrorAsymmetry {
    double position = 0.0;  // m
    double velocity = 0.0;  // m/s
};
constexpr std::size_t kMostMirroredSpheres = 2000;
MirrorAsymmetry mirrorAsymmetry(const World& world, const Plane& mirror);

// Spheres whose centre lies on the wrong side of a box plane by more than `slack` (m).
std::size_t spheresOutsideBox(const World& world, double slack);

}  // namespace physics
