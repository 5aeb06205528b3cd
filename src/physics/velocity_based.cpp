// Velocity based ("velocity correction"), second deck, "Summary with multiple particles":
//   A. update velocity from field forces;
//   B. handle collisions (with velocity) between particles, and walls;
//   C. cancel the velocity component contributing to penetration;
//   D. update position from the current velocity.
// B is repeated for K passes; C runs once after them, as the safety net for what
// B left approaching. Inside every pass it would turn each multi-contact bounce
// partly inelastic (an elastic gas lost 16 % of its kinetic energy in 10^4 steps).
// (+) smooth and stable motion; (-) an existing overlap persists.
// With shock propagation on, the contact graph's levels are swept between B and C, on
// velocities only (shock_propagation.cpp).
#include "physics/solver_stages.h"

namespace physics {
namespace {

// The contacts are those findContacts found: positions have not moved since.
void cancelPenetratingVelocity(World& world, const Params& params) {
    const Workspace& ws = world.workspace;
    StepStats none;
    forEachPairInPassOrder(world, params, none, [&](const SpherePair* pairs, std::uint32_t first,
                                                    std::uint32_t last, StepStats&) {
        for (std::uint32_t k = first; k < last; ++k) {
            if (!ws.pairTouches[k]) continue;
            const SpherePair& pair = pairs[k];
            cancelApproachBetween(world.velocity[pair.i], world.velocity[pair.j], world.mass[pair.i],
                                  world.mass[pair.j], ws.pairContacts[k].u);
        }
    });
    forEachSphere(world, params, none, [&](std::uint32_t i, StepStats&) {
        for (std::uint32_t w = ws.wallStart[i]; w < ws.wallStart[i + 1]; ++w) {
            cancelApproachToPlane(world.velocity[i], ws.wallContacts[w].face.normal);
        }
    });
}

}  // namespace

StepStats stepVelocityBased(World& world, const Params& params, double h) {
    StepStats stats;
    integrateVelocity(world, params, h);  // A
    findOrderedPairs(world, params, stats);
    {
        const StageTimer timer(stats.passesSeconds);
        findContacts(world, params);  // positions stay put until D
        beginMeasuringImpacts(world, params);
        runPasses(world, params, stats, [&](int pass) { respondWithSolver(world, params, stats, pass); });  // B
        propagateShock(world, params, stats, false);
        endWithPositivity(world, params, stats, false);
        cancelPenetratingVelocity(world, params);  // C
        endMeasuringImpacts(world, stats);
    }
    integratePosition(world, params, h);  // D
    return stats;
}

}  // namespace physics
