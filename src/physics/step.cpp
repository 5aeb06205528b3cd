#include "physics/step.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "physics/broad_phase.h"
#include "physics/random.h"
#include "physics/solver_stages.h"

namespace physics {
namespace {

// Candidate pairs must reach at least this fraction of the largest radius beyond
// touching, so that contacts created by the corrections of a pass are seen by the next.
constexpr double kMarginFraction = 0.1;
// The grid builds them with this reach and keeps them (a Verlet list) until two
// spheres could have closed the difference: at rest, a pile rebuilds rarely. Each
// step then keeps exactly the pairs within the margin, so the cache never changes
// the result: the next state is a function of this one, as with a fresh build.
constexpr double kSkinFraction = 0.3;

struct Extent {
    double maxRadius = 0.0;  // m
    double radiusSum = 0.0;  // m
};

Extent extentOf(const World& world) {
    Extent e;
    for (double r : world.radius) {
        e.maxRadius = std::max(e.maxRadius, r);
        e.radiusSum += r;
    }
    return e;
}

bool cachedPairsStillReach(const World& world, const Extent& extent, double margin) {
    const Workspace& ws = world.workspace;
    if (!ws.cached || ws.positionsAtBuild.size() != world.size() || ws.radiusSumAtBuild != extent.radiusSum) {
        return false;
    }
    double maxMoveSquared = 0.0;  // m^2
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 move = world.position[i] - ws.positionsAtBuild[i];
        maxMoveSquared = std::max(maxMoveSquared, glm::dot(move, move));
    }
    return 2.0 * std::sqrt(maxMoveSquared) <= ws.reachAtBuild - margin;
}

void reorder(std::vector<SpherePair>& pairs, PairOrder order, std::uint64_t seed,
             std::uint64_t stepCount) {
    if (order == PairOrder::Reversed) std::reverse(pairs.begin(), pairs.end());
    if (order != PairOrder::Shuffled) return;
    Random random(seed ^ (stepCount * 0x9E3779B97F4A7C15ull));
    for (std::size_t k = pairs.size(); k > 1; --k) std::swap(pairs[k - 1], pairs[random.below(k)]);
}

}  // namespace

StepStats& StepStats::operator+=(const StepStats& o) {
    pairTests += o.pairTests;
    broadPhaseBuilds += o.broadPhaseBuilds;
    candidatePairs += o.candidatePairs;
    sphereContacts += o.sphereContacts;
    wallContacts += o.wallContacts;
    collisions += o.collisions;
    staticContacts += o.staticContacts;
    return *this;
}

void integrateVelocity(World& world, const glm::dvec3& gravity, double h) {
    for (glm::dvec3& v : world.velocity) v += h * gravity;
}

void integratePosition(World& world, double h) {
    for (std::size_t i = 0; i < world.size(); ++i) world.position[i] += h * world.velocity[i];
}

void findOrderedPairs(World& world, const Params& params, StepStats& stats) {
    Workspace& ws = world.workspace;
    const Extent extent = extentOf(world);
    const double margin = kMarginFraction * extent.maxRadius;
    if (params.broadPhase == BroadPhase::AllPairs) {  // the lecture's loop, every step
        ws.cached = false;
        stats.pairTests += findPairs(params.broadPhase, world, margin, ws);
        ++stats.broadPhaseBuilds;
    } else if (!cachedPairsStillReach(world, extent, margin)) {
        ws.reachAtBuild = kSkinFraction * extent.maxRadius;
        stats.pairTests += findPairs(params.broadPhase, world, ws.reachAtBuild, ws);
        ws.positionsAtBuild = world.position;
        ws.radiusSumAtBuild = extent.radiusSum;
        ws.cached = true;
        ++stats.broadPhaseBuilds;
    }
    ws.visitOrder.clear();
    for (const SpherePair& pair : ws.pairs) {
        if (withinReach(world, pair, margin)) ws.visitOrder.push_back(pair);
    }
    stats.candidatePairs += ws.visitOrder.size();
    reorder(ws.visitOrder, params.order, world.seed, world.stepCount);
}

bool touching(const World& world, const SpherePair& pair, SphereContact& contact) {
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

bool touching(const World& world, std::uint32_t i, const Plane& plane) {
    return glm::dot(world.position[i] - plane.point, plane.normal) <= world.radius[i];
}

namespace {

// Keeps the strongest thing that happened to a sphere this step.
void record(World& world, std::uint32_t i, Response response) {
    ContactState& state = world.contactState[i];
    if (response == Response::Bounce) state = ContactState::Colliding;
    if (response == Response::Static && state == ContactState::Free) state = ContactState::Static;
}

void count(StepStats& stats, Response response) {
    if (response == Response::Bounce) ++stats.collisions;
    if (response == Response::Static) ++stats.staticContacts;
}

}  // namespace

void respondToContact(World& world, const SpherePair& pair, const SphereContact& contact,
                      const Params& params, StepStats& stats, int pass) {
    const glm::dvec3 before[2] = {world.velocity[pair.i], world.velocity[pair.j]};  // m/s
    const Response response = respondToSphere(world.velocity[pair.i], world.velocity[pair.j],
                                              world.mass[pair.i], world.mass[pair.j], contact.u,
                                              params);
    record(world, pair.i, response);
    record(world, pair.j, response);
    count(stats, response);
    stats.sphereContacts += pass == 0;
    if (world.recordContacts && response != Response::None) {
        world.contacts.push_back({pair.i, static_cast<std::int32_t>(pair.j), pass,
                                  response == Response::Bounce, contact.u,
                                  world.position[pair.i] - world.radius[pair.i] * contact.u,
                                  contact.depth, {before[0], before[1]},
                                  {world.velocity[pair.i], world.velocity[pair.j]},
                                  {world.mass[pair.i], world.mass[pair.j]}});
    }
}

void respondToContact(World& world, std::uint32_t i, std::size_t planeIndex, const Plane& face,
                      const Params& params, StepStats& stats, int pass) {
    const glm::dvec3 before = world.velocity[i];
    const Response response = respondToPlane(world.velocity[i], face.normal, params);
    record(world, i, response);
    count(stats, response);
    stats.wallContacts += pass == 0;
    if (world.recordContacts && response != Response::None) {
        const double distance = glm::dot(world.position[i] - face.point, face.normal);  // m
        world.contacts.push_back({i, -1 - static_cast<std::int32_t>(planeIndex), pass,
                                  response == Response::Bounce, face.normal,
                                  world.position[i] - distance * face.normal, world.radius[i] - distance,
                                  {before, glm::dvec3(0.0)}, {world.velocity[i], glm::dvec3(0.0)},
                                  {world.mass[i], 0.0}});
    }
}

void respondToAllContacts(World& world, const Params& params, StepStats& stats, int pass) {
    for (const SpherePair& pair : world.workspace.visitOrder) {
        SphereContact contact;
        if (touching(world, pair, contact)) respondToContact(world, pair, contact, params, stats, pass);
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        for (std::size_t k = 0; k < world.planes.size(); ++k) {
            const Plane face = faceFor(world.planes[k], world.position[i]);
            if (touching(world, i, face)) respondToContact(world, i, k, face, params, stats, pass);
        }
    }
}

namespace {

StepStats solverStep(World& world, const Params& params, double h) {
    switch (params.method) {
        case Method::PositionBased: return stepPositionBased(world, params, h);
        case Method::VelocityBased: return stepVelocityBased(world, params, h);
        case Method::ResponseOnly: return stepResponseOnly(world, params, h);
    }
    return {};
}

}  // namespace

StepStats step(World& world, const Params& params) {
    StepStats stats;
    world.contacts.clear();
    const double h = params.solverStep();
    for (int s = 0; s < params.substeps; ++s) {
        std::fill(world.contactState.begin(), world.contactState.end(), ContactState::Free);
        stats += solverStep(world, params, h);
        world.time += h;
        ++world.stepCount;
    }
    return stats;
}

}  // namespace physics
