// Reflection, slide 7's second answer to a penetration found after the fact:
// "approximate the correct position". The position based method's stages, with the
// position response p <- p + (1 + beta) d n instead of the projection's d n (pairs:
// along u, (1 + beta) d split as the projection splits d).
// Where it puts the sphere: where it would be had it bounced at the instant of contact
// and gone on at beta times its normal speed. Exact for uniform motion with beta = 1;
// under gravity it is off by O(g h^2), since the sphere was accelerating meanwhile.
#include "physics/solver_stages.h"

namespace physics {

StepStats stepReflection(World& world, const Params& params, double h) {
    return stepWithPositionResponse(world, params, h, PositionResponse::Reflection);
}

}  // namespace physics
