#pragma once
// The stages the two methods are made of (second deck, "Summary with multiple
// particles"). Internal to the physics library.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "physics/collision_response.h"
#include "physics/step.h"
#include "physics/thread_team.h"

namespace physics {

// The threads the solver uses for this world (params.threads resolved).
int solverThreads(const World& world, const Params& params);

// The threads a stage may use: one while contacts are logged (the log is in pass order).
inline int threadsFor(const World& world, const Params& params) {
    return world.recordContacts ? 1 : solverThreads(world, params);
}

// [0, n) cut into `tasks` ranges of nearly equal size: range t is [begin, end).
struct Range {
    std::uint32_t begin, end;
};
inline Range rangeOf(std::size_t n, int t, int tasks) {
    return {std::uint32_t(n * std::size_t(t) / std::size_t(tasks)),
            std::uint32_t(n * std::size_t(t + 1) / std::size_t(tasks))};
}

// visit(begin, end, stats) on ranges of sphere indices that together cover every
// sphere once, in parallel: for stages where each sphere changes only itself.
template <class Visit>
void forEachSphereRange(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const int threads = threadsFor(world, params);
    if (threads == 1) {
        visit(std::uint32_t(0), std::uint32_t(world.size()), stats);
        return;
    }
    std::vector<StepStats> taskStats(static_cast<std::size_t>(threads));
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(world.size(), t, threads);
        StepStats local;  // neighbours in taskStats share cache lines: count apart
        visit(range.begin, range.end, local);
        taskStats[std::size_t(t)] = local;
    });
    for (const StepStats& s : taskStats) stats += s;
}

// visit(first, last, stats) on the groups of candidate pairs, in pass order: the
// groups before workspace.firstOddGroup, in parallel, then the others. Groups
// handled at the same time share no sphere, so the result is that of one thread.
template <class Visit>
void forEachPairGroup(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const Workspace& ws = world.workspace;
    const SpherePair* pairs = ws.visitOrder.data();
    const int threads = threadsFor(world, params);
    const std::size_t groups = ws.groupStart.size() - 1;
    std::vector<StepStats> groupStats(threads == 1 ? 0 : groups);
    for (const auto& [first, last] : {std::pair{std::size_t(0), ws.firstOddGroup}, std::pair{ws.firstOddGroup, groups}}) {
        runTasks(threads, int(last - first), [&](int t) {
            const std::size_t g = first + std::size_t(t);
            if (threads == 1) {
                visit(pairs + ws.groupStart[g], pairs + ws.groupStart[g + 1], stats);
                return;
            }
            StepStats local;  // neighbours in groupStats share cache lines: count apart
            visit(pairs + ws.groupStart[g], pairs + ws.groupStart[g + 1], local);
            groupStats[g] = local;
        });
    }
    for (const StepStats& s : groupStats) stats += s;
}

// Field forces, semi-implicit Euler (slide 2): v <- v + h g, then p <- p + h v.
void integrateVelocity(World& world, const Params& params, double h);
void integratePosition(World& world, const Params& params, double h);

// Fills world.workspace.pairs with the candidate pairs in the order the passes
// visit them (index, reversed, or shuffled with the world's seed and step count).
void findOrderedPairs(World& world, const Params& params, StepStats& stats);

// Narrow phase, slide 9: the pair touches when |p1 - p2| <= r1 + r2.
struct SphereContact {
    glm::dvec3 u{0.0, 0.0, 1.0};  // (p1 - p2) / |p1 - p2|, from 2 to 1
    double depth = 0.0;           // m, d = r1 + r2 - |p1 - p2| (>= 0 when touching)
};
// (Inline, as the next one: they run for every candidate in every pass.)
inline bool touching(const World& world, const SpherePair& pair, SphereContact& contact) {
    const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];
    const double reach = world.radius[pair.i] + world.radius[pair.j];
    const double distanceSquared = glm::dot(delta, delta);
    if (distanceSquared > reach * reach) return false;
    const double distance = std::sqrt(distanceSquared);
    // Coincident centres have no direction: push them apart along z.
    contact.u = distance > 0.0 ? delta / distance : glm::dvec3(0.0, 0.0, 1.0);
    contact.depth = reach - distance;
    return true;
}

// Slide 3: the sphere touches the plane when (p - a).n <= r.
inline bool touching(const World& world, std::uint32_t i, const Plane& plane) {
    return glm::dot(world.position[i] - plane.point, plane.normal) <= world.radius[i];
}

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
