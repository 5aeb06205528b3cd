// Position based ("position projection"), second deck, "Summary with multiple particles":
//   A. update position and velocity from field forces;
//   B. handle collisions between particles: velocity + position;
//   C. handle collisions with the walls: velocity + position;
//   B and C repeated for K passes.
// (+) walls are never crossed, since they are handled last; (-) stacked spheres jitter.
// Reflection (slide 7's second answer, reflection.cpp) runs the same stages with its
// own position response. With slide 14's simultaneous and global solvers the velocities
// of a pass are answered together first (respondWithSolver), and B and C only move.
// With shock propagation on, the contact graph's levels are swept after the passes
// (shock_propagation.cpp).
#include "physics/solver_stages.h"

namespace physics {
namespace {

// Each move lowers the spheres' wall clearance by its length. `respond`: the velocity
// response too (else the velocities of this pass are answered already).
void particlesVelocityAndPosition(World& world, const Params& params, StepStats& stats,
                                  int pass, PositionResponse response, bool respond) {
    std::vector<double>& clearance = world.workspace.wallClearance;  // m
    const bool byWavefronts = passesByWavefronts(world, params);
    const bool inLanes = byWavefronts || (params.order == PairOrder::Colored && !world.answersOneAtATime());
    const auto visit = [&](const SpherePair* pairs, std::uint32_t first, std::uint32_t last, StepStats& s) {
        std::uint32_t k = first;
        if (inLanes) {  // a wavefront's or a colour's pairs, several side by side (colored_lanes.cpp)
            const double factor = positionResponseDistance(response, 1.0, params);
            k = byWavefronts ? separateSideBySide(world, params, pairs, first, last, s, pass, factor, respond)
                             : separateColorInLanes(world, params, pairs, first, last, s, pass, factor, respond);
        }
        for (; k < last; ++k) {
            const SpherePair& pair = pairs[k];
            SphereContact contact;
            if (!touching(world, pair, contact)) continue;
            if (respond) respondToContact(world, pair, contact, params, s, pass);
            const Separation moved =
                separateSpheres(world.position[pair.i], world.position[pair.j], world.mass[pair.i],
                                world.mass[pair.j], contact.u,
                                positionResponseDistance(response, contact.depth, params), params.split);
            clearance[pair.i] -= moved.first;
            clearance[pair.j] -= moved.second;
        }
    };
    if (byWavefronts) {
        forEachWavefront(world, params, stats, visit);
    } else {
        forEachPairInPassOrder(world, params, stats, visit);
    }
}

// A sphere whose wall clearance is above 0 touches no plane: passed by.
void wallsVelocityAndPosition(World& world, const Params& params, StepStats& stats,
                              int pass, PositionResponse response, bool respond) {
    std::vector<double>& clearance = world.workspace.wallClearance;  // m
    const double scale = planeScale(world);                          // m
    forEachSphere(world, params, stats, [&](std::uint32_t i, StepStats& s) {
        if (clearance[i] > 0.0) return;
        forEachTouchedPlane(world, i, [&](std::size_t k, const Plane& face) {
            if (respond) respondToContact(world, i, k, face, params, s, pass);
            if (response == PositionResponse::Projection) {
                projectOnPlane(world.position[i], world.radius[i], face);
            } else {
                reflectOnPlane(world.position[i], world.radius[i], face, params.beta);
            }
        });
        clearance[i] = wallClearance(world, i, scale);
    });
}

// Workspace::wallClearance of every sphere (findWallClearances) and, for passes by
// wavefronts, the wavefronts (findWavefronts; in the colored order on several threads, its
// border's: findBorderWavefronts). On several threads, one finds the wavefronts (a chain of
// pairs: one thread's work) while the others find the clearances.
void findWavefrontsAndWallClearances(World& world, const Params& params) {
    const int threads = threadsFor(world, params);
    const bool byWavefronts = passesByWavefronts(world, params);
    const bool border = params.order == PairOrder::Colored && threads > 1;
    if (!byWavefronts && !border) {
        findWallClearances(world, params);
        return;
    }
    if (threads == 1) {
        findWavefronts(world, threads);
        findWallClearances(world, params);
        return;
    }
    std::vector<double>& clearance = world.workspace.wallClearance;  // m
    clearance.resize(world.size());
    const double scale = planeScale(world);  // m
    const int sphereTasks = kSphereTasksPerThread * (threads - 1);
    runTasks(threads, 1 + sphereTasks, [&](int t) {
        if (t == 0) {
            border ? findBorderWavefronts(world, threads) : findWavefronts(world, threads);
            return;
        }
        const Range range = rangeOf(world.size(), t - 1, sphereTasks);
        for (std::uint32_t i = range.begin; i < range.end; ++i) clearance[i] = wallClearance(world, i, scale);
    });
}

}  // namespace

StepStats stepWithPositionResponse(World& world, const Params& params, double h,
                                   PositionResponse response) {
    StepStats stats;
    integrateVelocity(world, params, h);  // A
    integratePosition(world, params, h);
    findOrderedPairs(world, params, stats);
    if (params.shock == ShockPropagation::On) world.workspace.contactGraph.positionsBeforePasses = world.position;
    {
        const StageTimer timer(stats.passesSeconds);
        findWavefrontsAndWallClearances(world, params);
        beginMeasuringImpacts(world, params);
        const bool together = solvesTogether(params.solver);
        runPasses(world, params, stats, [&](int pass) {
            if (together) {
                findContacts(world, params);
                respondWithSolver(world, params, stats, pass);
            }
            particlesVelocityAndPosition(world, params, stats, pass, response, !together);  // B
            wallsVelocityAndPosition(world, params, stats, pass, response, !together);      // C
        });
        // A global solver answers the velocities before each pass's projection: the contacts
        // the last projection closed again or made are answered once more, velocities only,
        // so that none still approaches at the step's end (positivity; the fast gas under
        // generalized reflections kept one approaching at 5.9 m/s, the pyramid at 2e-5 m/s).
        if (together) {
            findContacts(world, params);
            respondWithSolver(world, params, stats, params.passes);
        }
        propagateShock(world, params, stats, true);
        endWithPositivity(world, params, stats, params.shock == ShockPropagation::On);
        endMeasuringImpacts(world, stats);
    }
    return stats;
}

StepStats stepPositionBased(World& world, const Params& params, double h) {
    return stepWithPositionResponse(world, params, h, PositionResponse::Projection);
}

}  // namespace physics
