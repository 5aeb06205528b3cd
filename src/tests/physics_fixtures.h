#pragma once
// Small worlds built by hand for the physics tests (no scene files involved).
#include <glm/geometric.hpp>

#include "physics/params.h"
#include "physics/random.h"
#include "physics/world.h"

namespace fixtures {

// The box x in [-sx/2, sx/2], y in [-sy/2, sy/2], z in [0, sz], normals inward.
inline void addBox(physics::World& world, glm::dvec3 size) {
    const glm::dvec3 lo(-size.x / 2, -size.y / 2, 0.0), hi(size.x / 2, size.y / 2, size.z);
    world.planes = {{lo, {0, 0, 1}}, {hi, {0, 0, -1}}, {lo, {1, 0, 0}},
                    {hi, {-1, 0, 0}}, {lo, {0, 1, 0}}, {hi, {0, -1, 0}}};
    world.boxPlaneCount = 6;
}

// Parameters for exact checks: one solver step per time step, no static contacts.
inline physics::Params exactParams(double h, glm::dvec3 gravity = {0, 0, -9.81}) {
    physics::Params params;
    params.timeStep = h;
    params.substeps = 1;
    params.alpha = 1.0;
    params.beta = 1.0;
    params.epsilon = 0.0;
    params.mu = 1.0;
    params.gravity = gravity;
    return params;
}

// n spheres with radii in [rMin, rMax] at random non-overlapping places in a cube
// of side `extent` centred at `centre`, velocities uniform in [-speed, speed]^3.
inline void addRandomSpheres(physics::World& world, std::size_t n, double rMin, double rMax,
                             double extent, glm::dvec3 centre, double speed, std::uint64_t seed) {
    physics::Random random(seed);
    while (world.size() < n) {
        const glm::dvec3 p = centre + glm::dvec3(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5),
                                                 random.uniform(-0.5, 0.5)) * extent;
        const double r = random.uniform(rMin, rMax);
        bool free = true;
        for (std::size_t k = 0; k < world.size() && free; ++k) {
            free = glm::distance(p, world.position[k]) > r + world.radius[k];
        }
        if (!free) continue;
        const glm::dvec3 v(random.uniform(-speed, speed), random.uniform(-speed, speed),
                           random.uniform(-speed, speed));
        world.addSphere(p, v, r, 1000.0 * r * r * r);  // mass grows with volume
    }
}

// Newton's cradle: five touching spheres of radius 0.125 m and 1 kg on the x axis
// (exactly representable centres, so they touch exactly); sphere 0 strikes at v0 (m/s).
inline physics::World cradle(double v0) {
    physics::World world;
    for (int k = 0; k < 5; ++k) world.addSphere({0.25 * k, 0, 0}, {k == 0 ? v0 : 0.0, 0, 0}, 0.125, 1.0);
    return world;
}

}  // namespace fixtures
