// Velocity response only, first deck, slides 5-6 ("applying collision response on
// speed only"): the flow of the position-based method without its projection.
//   A. update position and velocity from field forces;
//   B. handle collisions with velocity only, K passes.
// The lesson of slide 6: in discrete time the contact is detected once the sphere is
// already inside the wall, and its weight still acts. It bounces back from below the
// contact, so it "doesn't bounce high enough", and a resting sphere sinks step by step.
#include "physics/solver_stages.h"

namespace physics {

StepStats stepResponseOnly(World& world, const Params& params, double h) {
    StepStats stats;
    integrateVelocity(world, params, h);  // A
    integratePosition(world, params, h);
    findOrderedPairs(world, params, stats);
    {
        const StageTimer timer(stats.passesSeconds);
        findContacts(world, params);  // positions stay put during B
        beginMeasuringImpacts(world, params);
        runPasses(world, params, stats, [&](int pass) { respondWithSolver(world, params, stats, pass); });  // B
        endMeasuringImpacts(world, stats);
    }
    return stats;
}

}  // namespace physics
