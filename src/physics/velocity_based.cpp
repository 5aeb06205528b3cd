// Velocity based ("velocity correction"), second deck, "Summary with multiple particles":
//   A. update velocity from field forces;
//   B. handle collisions (with velocity) between particles, and walls;
//   C. cancel the velocity component contributing to penetration;
//   D. update position from the current velocity.
// B is repeated for K passes; C runs once after them, as the safety net for what
// B left approaching. Inside every pass it would turn each multi-contact bounce
// partly inelastic (an elastic gas lost 16 % of its kinetic energy in 10^4 steps).
// (+) smooth and stable motion; (-) an existing overlap persists.
#include "physics/solver_stages.h"

namespace physics {
namespace {

void cancelPenetratingVelocity(World& world, const Params& params) {
    StepStats none;
    forEachPairInPassOrder(world, params, none, [&](const SpherePair* first, const SpherePair* last, StepStats&) {
        for (const SpherePair* pair = first; pair != last; ++pair) {
            SphereContact contact;
            if (!touching(world, *pair, contact)) continue;
            cancelApproachBetween(world.velocity[pair->i], world.velocity[pair->j], world.mass[pair->i],
                                  world.mass[pair->j], contact.u);
        }
    });
    forEachSphere(world, params, none, [&](std::uint32_t i, StepStats&) {
        forEachTouchedPlane(world, i, [&](std::size_t, const Plane& face) {
            cancelApproachToPlane(world.velocity[i], face.normal);
        });
    });
}

}  // namespace

StepStats stepVelocityBased(World& world, const Params& params, double h) {
    StepStats stats;
    integrateVelocity(world, params, h);  // A
    findOrderedPairs(world, params, stats);
    for (int pass = 0; pass < params.passes; ++pass) {
        respondToAllContacts(world, params, stats, pass);  // B
    }
    cancelPenetratingVelocity(world, params);  // C
    integratePosition(world, params, h);  // D
    return stats;
}

}  // namespace physics
