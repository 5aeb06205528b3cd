// Simultaneous pairwise, slide 14's "multiple collisions" solved as a Jacobi iteration:
// in a pass every touching contact computes its response (the lecture's, slides 4 and
// 11-13) from the velocities at the start of the pass, and all are applied together,
// each sphere's changes summed. No contact sees another's result within a pass, so the
// pair order does not matter and a symmetric input stays symmetric; but a sphere hit
// from several sides gets every change at once, and can leave faster than it came.
#include "physics/solver_stages.h"

namespace physics {

void respondSimultaneously(World& world, const Params& params, StepStats& stats, int pass) {
    Workspace& ws = world.workspace;
    ws.passStart = world.velocity;  // m/s
    ws.velocityChange.assign(world.size(), glm::dvec3(0.0));
    // Each contact from the pass's starting velocities: its change kept, the velocities put back.
    const auto answer = [&](std::uint32_t i, std::int64_t j, const auto& respond) {
        respond();
        ws.velocityChange[i] += world.velocity[i] - ws.passStart[i];
        world.velocity[i] = ws.passStart[i];
        if (j < 0) return;
        ws.velocityChange[std::size_t(j)] += world.velocity[std::size_t(j)] - ws.passStart[std::size_t(j)];
        world.velocity[std::size_t(j)] = ws.passStart[std::size_t(j)];
    };
    const std::vector<SpherePair>& pairs = pairsAsVisited(world, params);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (!ws.pairTouches[k]) continue;
        answer(pairs[k].i, pairs[k].j, [&] { respondToContact(world, pairs[k], ws.pairContacts[k], params, stats, pass); });
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        for (std::uint32_t w = ws.wallStart[i]; w < ws.wallStart[i + 1]; ++w) {
            const WallContact& wall = ws.wallContacts[w];
            answer(i, -1, [&] { respondToContact(world, i, wall.plane, wall.face, params, stats, pass); });
        }
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) world.velocity[i] += ws.velocityChange[i];
}

}  // namespace physics
