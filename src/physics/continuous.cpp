// Continuous collision detection, slide 7's third answer to a penetration: "go
// backward in time to the exact instant of collision (+) physically correct,
// (-) computationally heavy (binary search, etc.)".
// Within a solver step of length h each sphere follows the parabola semi-implicit Euler
// puts it on in free flight, p(t) = p + w t + 1/2 g t^2 with w = v + (h/2) g (its points
// at t = h, 2h, ... are the integrator's). Impacts are handled in time order:
//   A. predict each sphere's first impact with the planes and with its candidates;
//   B. take the earliest impact, move its spheres along their paths to that instant,
//      and apply the lecture's response there, at exact contact (slides 4, 11-13);
//   C. predict again for the spheres whose velocity changed (what was predicted for
//      their old paths is stale, and passed over); back to B until the step ends;
//   D. move every sphere to the end of the step: v = its path's velocity - (h/2) g.
// A static contact (slide 13, relative normal speed <= epsilon) makes no further
// impact in the step, or a resting sphere would collide infinitely often; it rests
// until a bounce changes one of its spheres. Gravity presses it in by 1/2 g h^2
// meanwhile, and D cancels that approach and projects it out (slide 8). Past
// Params::maxEvents impacts the step goes to D at once and is counted.
// With slide 14's solvers that answer contacts together, impacts that fall at one instant
// (within kSameInstant) are answered together instead of one after the other: lcp and
// generalized reflections as one cluster, simultaneous by summing the lecture's responses
// from the same velocities (Bernoulli's problem stays symmetric). Sequential and
// until-converged take them in the queue's order.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "physics/broad_phase.h"
#include "physics/complementarity.h"
#include "physics/solver_stages.h"
#include "physics/time_of_impact.h"

namespace physics {
namespace {

// Where sphere i's path is at time t (s) of the step, and how fast it goes there.
glm::dvec3 positionAt(const World& world, std::uint32_t i, double t, const glm::dvec3& g) {
    const double dt = t - world.workspace.continuous.pathStart[i];  // s
    return world.position[i] + dt * world.velocity[i] + (0.5 * dt * dt) * g;
}
glm::dvec3 velocityAt(const World& world, std::uint32_t i, double t, const glm::dvec3& g) {
    return world.velocity[i] + (t - world.workspace.continuous.pathStart[i]) * g;
}

// Starts sphere i's path anew at time t (s), where it is then.
void moveTo(World& world, std::uint32_t i, double t, const glm::dvec3& g) {
    world.position[i] = positionAt(world, i, t, g);
    world.velocity[i] = velocityAt(world, i, t, g);
    world.workspace.continuous.pathStart[i] = t;
}

// m: how far sphere i can get from where its path starts by time `end` (s).
double travel(const World& world, std::uint32_t i, double end, const glm::dvec3& g) {
    const double dt = end - world.workspace.continuous.pathStart[i];  // s
    return glm::length(world.velocity[i]) * dt + 0.5 * glm::length(g) * dt * dt;
}

// Static marks of the pairs kept from the last candidate list (both sorted by (i, j)).
void carryRestingMarks(ContinuousWorkspace& cw, const std::vector<SpherePair>& pairs) {
    const auto key = [](const SpherePair& p) { return (std::uint64_t(p.i) << 32) | p.j; };
    cw.pairResting.assign(pairs.size(), 0);
    for (std::size_t k = 0, old = 0; k < pairs.size() && old < cw.previousPairs.size(); ++k) {
        while (old < cw.previousPairs.size() && key(cw.previousPairs[old]) < key(pairs[k])) ++old;
        if (old < cw.previousPairs.size() && key(cw.previousPairs[old]) == key(pairs[k])) {
            cw.pairResting[k] = cw.previousResting[old];
        }
    }
}

// pairStart and pairOf: each sphere's candidate pairs, by a counting sort.
void indexPairsBySphere(ContinuousWorkspace& cw, const std::vector<SpherePair>& pairs, std::size_t spheres) {
    cw.pairStart.assign(spheres + 1, 0);
    for (const SpherePair& p : pairs) ++cw.pairStart[p.i + 1], ++cw.pairStart[p.j + 1];
    for (std::size_t i = 0; i < spheres; ++i) cw.pairStart[i + 1] += cw.pairStart[i];
    cw.pairOf.resize(2 * pairs.size());
    cw.nextSlot.assign(cw.pairStart.begin(), cw.pairStart.end() - 1);
    for (std::uint32_t k = 0; k < pairs.size(); ++k) {
        cw.pairOf[cw.nextSlot[pairs[k].i]++] = k;
        cw.pairOf[cw.nextSlot[pairs[k].j]++] = k;
    }
}

// Candidate pairs (Workspace::pairs, by sphere in ContinuousWorkspace): every pair that
// can meet before time `end` (s) while no sphere travels farther than `reach` from
// where its path starts now. Keeps the static contacts found so far.
void findCandidates(World& world, const Params& params, double end, StepStats& stats) {
    const StageTimer timer(stats.broadPhaseSeconds);
    Workspace& ws = world.workspace;
    ContinuousWorkspace& cw = ws.continuous;
    double reach = 0.0;  // m
    for (std::uint32_t i = 0; i < world.size(); ++i) reach = std::max(reach, travel(world, i, end, params.gravity));
    cw.reach = std::isfinite(reach) ? reach : 0.0;
    cw.anchor = world.position;
    cw.previousPairs.swap(ws.pairs);
    cw.previousResting.swap(cw.pairResting);
    // Two spheres close by at most twice the reach; the rest is slack for rounding.
    stats.pairTests += findPairs(params.broadPhase, world, 2.0 * cw.reach * (1.0 + 1e-9) + 1e-12, ws);
    ++stats.broadPhaseBuilds;
    stats.candidatePairs += ws.pairs.size();
    carryRestingMarks(cw, ws.pairs);
    indexPairsBySphere(cw, ws.pairs, world.size());
}

// The earliest impact first; ties in a fixed order, so that a run repeats exactly.
bool later(const PredictedImpact& a, const PredictedImpact& b) {
    if (a.time != b.time) return a.time > b.time;
    if (a.i != b.i) return a.i > b.i;
    return a.other > b.other;
}

void push(ContinuousWorkspace& cw, const PredictedImpact& impact) {
    cw.queue.push_back(impact);
    std::push_heap(cw.queue.begin(), cw.queue.end(), later);
}

std::uint32_t partner(const SpherePair& pair, std::uint32_t i) { return pair.i == i ? pair.j : pair.i; }

// Sphere i's path at time `now` (s): where it is and how fast it goes.
struct PathPoint {
    glm::dvec3 p, w;  // m, m/s
};
PathPoint pathAt(const World& world, std::uint32_t i, double now, const glm::dvec3& g) {
    return {positionAt(world, i, now, g), velocityAt(world, i, now, g)};
}

// Queues a contact found from time `now` (s) by sphere i with `other`.
void note(World& world, const Contact& contact, double now, std::uint32_t i, std::int32_t other, StepStats& stats) {
    ContinuousWorkspace& cw = world.workspace.continuous;
    stats.toiIterations += contact.iterations;
    if (!contact.found) return;
    push(cw, {now + contact.time, i, other, cw.version[i], other >= 0 ? cw.version[std::uint32_t(other)] : 0u});
}

// A: sphere i's first impact with each plane it is not resting on, from time `now` (s)
// to the end of the step at h (s).
void predictPlanes(World& world, const Params& params, std::uint32_t i, const PathPoint& at, double now, double h,
                   StepStats& stats) {
    const ContinuousWorkspace& cw = world.workspace.continuous;
    const std::size_t planes = world.planes.size();
    for (std::size_t k = 0; k < planes; ++k) {
        if (cw.planeResting[i * planes + k]) continue;
        const Gap gap = gapToPlane(at.p, at.w, world.radius[i], params.gravity, faceFor(world.planes[k], at.p));
        note(world, firstContact(gap, h - now, params.timeOfImpact), now, i, -1 - std::int32_t(k), stats);
    }
}

// A: the first impact of candidate pair k (not resting), seen from its sphere i.
void predictPair(World& world, const Params& params, std::uint32_t k, std::uint32_t i, const PathPoint& at,
                 double now, double h, StepStats& stats) {
    if (world.workspace.continuous.pairResting[k]) return;
    const std::uint32_t j = partner(world.workspace.pairs[k], i);
    const PathPoint other = pathAt(world, j, now, params.gravity);
    const Gap gap = squaredGap(at.p - other.p, at.w - other.w, world.radius[i] + world.radius[j]);
    note(world, firstContact(gap, h - now, params.timeOfImpact), now, i, std::int32_t(j), stats);
}

// A, for sphere i from time `now` (s): the planes and every candidate pair.
void predict(World& world, const Params& params, std::uint32_t i, double now, double h, StepStats& stats) {
    const ContinuousWorkspace& cw = world.workspace.continuous;
    const PathPoint at = pathAt(world, i, now, params.gravity);
    predictPlanes(world, params, i, at, now, h, stats);
    for (std::uint32_t e = cw.pairStart[i]; e < cw.pairStart[i + 1]; ++e) {
        predictPair(world, params, cw.pairOf[e], i, at, now, h, stats);
    }
}

// A, at the start of the step: every sphere's planes, and every pair once.
void predictAll(World& world, const Params& params, double h, StepStats& stats) {
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        predictPlanes(world, params, i, {world.position[i], world.velocity[i]}, 0.0, h, stats);
    }
    for (std::uint32_t k = 0; k < world.workspace.pairs.size(); ++k) {
        const std::uint32_t i = world.workspace.pairs[k].i;
        predictPair(world, params, k, i, {world.position[i], world.velocity[i]}, 0.0, h, stats);
    }
}

// The candidate pair of spheres i and j (it exists: the impact was predicted from it).
std::uint32_t pairIndex(const World& world, std::uint32_t i, std::uint32_t j) {
    const ContinuousWorkspace& cw = world.workspace.continuous;
    for (std::uint32_t e = cw.pairStart[i];; ++e) {
        if (partner(world.workspace.pairs[cw.pairOf[e]], i) == j) return cw.pairOf[e];
    }
}

// A bounce sets sphere i moving anew: whatever it rested on may be hit again.
void wakeUp(World& world, std::uint32_t i) {
    ContinuousWorkspace& cw = world.workspace.continuous;
    const std::size_t planes = world.planes.size();
    std::fill_n(cw.planeResting.begin() + std::ptrdiff_t(i * planes), planes, 0);
    for (std::uint32_t e = cw.pairStart[i]; e < cw.pairStart[i + 1]; ++e) cw.pairResting[cw.pairOf[e]] = 0;
}

// B: the lecture's response at the instant of contact. Returns what it did, having
// marked a static contact as resting.
Response respondAtContact(World& world, const Params& params, const PredictedImpact& impact, StepStats& stats) {
    ContinuousWorkspace& cw = world.workspace.continuous;
    const std::uint32_t i = impact.i;
    moveTo(world, i, impact.time, params.gravity);
    const std::size_t before = world.contacts.size();
    Response response;
    if (impact.other < 0) {
        const std::size_t k = std::size_t(-1 - impact.other);
        response = respondToContact(world, i, k, faceFor(world.planes[k], world.position[i]), params, stats, 0);
        if (response == Response::Static) cw.planeResting[i * world.planes.size() + k] = 1;
    } else {
        const std::uint32_t j = std::uint32_t(impact.other);
        moveTo(world, j, impact.time, params.gravity);
        const SpherePair pair{std::min(i, j), std::max(i, j)};
        SphereContact contact;
        const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];  // m
        const double distance = glm::length(delta);
        contact.u = distance > 0.0 ? delta / distance : glm::dvec3(0.0, 0.0, 1.0);
        contact.depth = world.radius[i] + world.radius[j] - distance;
        response = respondToContact(world, pair, contact, params, stats, 0);
        if (response == Response::Static) cw.pairResting[pairIndex(world, i, j)] = 1;
    }
    if (world.contacts.size() > before) world.contacts.back().timeOfImpact = impact.time;
    return response;
}

bool stale(const World& world, const PredictedImpact& impact) {
    const ContinuousWorkspace& cw = world.workspace.continuous;
    return cw.version[impact.i] != impact.versionOfI ||
           (impact.other >= 0 && cw.version[std::uint32_t(impact.other)] != impact.versionOfOther);
}

// The contact of an impact, its spheres moved to its instant.
LcpContact contactAtImpact(World& world, const Params& params, const PredictedImpact& impact) {
    const std::uint32_t i = impact.i;
    moveTo(world, i, impact.time, params.gravity);
    if (impact.other < 0) {
        const std::size_t k = std::size_t(-1 - impact.other);
        const Plane face = faceFor(world.planes[k], world.position[i]);
        const double depth = world.radius[i] - glm::dot(world.position[i] - face.point, face.normal);  // m
        return contactFor(world, params, i, -1, impact.other, face.normal, depth);
    }
    const std::uint32_t j = std::uint32_t(impact.other);
    moveTo(world, j, impact.time, params.gravity);
    const glm::dvec3 delta = world.position[i] - world.position[j];  // m
    const double distance = glm::length(delta);
    const glm::dvec3 u = distance > 0.0 ? delta / distance : glm::dvec3(0.0, 0.0, 1.0);
    return contactFor(world, params, i, j, impact.other, u, world.radius[i] + world.radius[j] - distance);
}

// B for impacts at one instant, with lcp or generalized reflections: solved together as
// one cluster, then alpha and mu. Bounce if any bounced, Static if the others rested.
Response respondTogether(World& world, const Params& params, const std::vector<PredictedImpact>& group,
                         StepStats& stats) {
    ContinuousWorkspace& cw = world.workspace.continuous;
    std::vector<LcpContact>& contacts = world.workspace.lcpContacts;
    contacts.clear();
    for (const PredictedImpact& impact : group) contacts.push_back(contactAtImpact(world, params, impact));
    const std::vector<glm::dvec3> before = world.recordContacts ? world.velocity : std::vector<glm::dvec3>();
    ContactCluster cluster{0, std::uint32_t(contacts.size())};
    if (params.solver == Solver::Lcp) {
        solveLcpCluster(world, contacts.data(), cluster);
    } else {
        reflectCluster(world, params, contacts.data(), cluster);
    }
    countCluster(cluster, stats);
    dampTangential(world, params, contacts);
    const std::size_t logged = world.contacts.size();
    reportContacts(world, contacts, before, stats, 0);
    for (std::size_t k = logged; k < world.contacts.size(); ++k) world.contacts[k].timeOfImpact = group[0].time;
    Response response = Response::None;
    for (const LcpContact& c : contacts) {
        if (c.lambda > 0.0 && !c.isStatic) response = Response::Bounce;
        if (!c.isStatic || response == Response::Bounce) continue;
        response = Response::Static;
        if (c.j < 0) {
            cw.planeResting[c.i * world.planes.size() + std::size_t(-1 - c.other)] = 1;
        } else {
            cw.pairResting[pairIndex(world, c.i, std::uint32_t(c.j))] = 1;
        }
    }
    return response;
}

// B for impacts at one instant with the simultaneous solver (slide 14's pairwise Jacobi):
// each answered by the lecture's response from the same velocities, the changes summed.
Response respondSimultaneouslyAt(World& world, const Params& params, const std::vector<PredictedImpact>& group,
                                 StepStats& stats) {
    std::vector<glm::dvec3>& start = world.workspace.passStart;  // m/s, of the group's spheres
    std::vector<glm::dvec3>& change = world.workspace.velocityChange;
    const auto spheresOf = [](const PredictedImpact& impact, std::uint32_t out[2]) {
        out[0] = impact.i;
        out[1] = impact.other >= 0 ? std::uint32_t(impact.other) : impact.i;
        return impact.other >= 0 ? 2 : 1;
    };
    start.resize(2 * group.size());
    change.assign(2 * group.size(), glm::dvec3(0.0));
    std::uint32_t s[2];
    for (std::size_t k = 0; k < group.size(); ++k) {  // every sphere at the instant first
        for (int n = spheresOf(group[k], s); n-- > 0;) moveTo(world, s[n], group[k].time, params.gravity);
    }
    for (std::size_t k = 0; k < group.size(); ++k) {
        for (int n = spheresOf(group[k], s); n-- > 0;) start[2 * k + std::size_t(n)] = world.velocity[s[n]];
    }
    Response response = Response::None;
    for (std::size_t k = 0; k < group.size(); ++k) {
        const Response r = respondAtContact(world, params, group[k], stats);
        if (r == Response::Bounce || (r == Response::Static && response == Response::None)) response = r;
        for (int n = spheresOf(group[k], s); n-- > 0;) {
            change[2 * k + std::size_t(n)] = world.velocity[s[n]] - start[2 * k + std::size_t(n)];
            world.velocity[s[n]] = start[2 * k + std::size_t(n)];
        }
    }
    for (std::size_t k = 0; k < group.size(); ++k) {
        for (int n = spheresOf(group[k], s); n-- > 0;) world.velocity[s[n]] += change[2 * k + std::size_t(n)];
    }
    return response;
}

// s: impacts this close in time are one simultaneous impact for the global solvers (the
// instants are found to kBisectionTolerance).
constexpr double kSameInstant = 1e-12;

// `group` holds the impact just taken; the queue's others at its instant that are not
// stale join it.
void takeSameInstant(World& world, std::vector<PredictedImpact>& group) {
    std::vector<PredictedImpact>& queue = world.workspace.continuous.queue;
    while (!queue.empty() && queue.front().time <= group.front().time + kSameInstant) {
        std::pop_heap(queue.begin(), queue.end(), later);
        const PredictedImpact next = queue.back();
        queue.pop_back();
        if (!stale(world, next)) group.push_back(next);
    }
}

// C, for the spheres of an impact that changed them. When one may now travel beyond the
// reach the candidates were found for, they are found again first.
void predictAgain(World& world, const Params& params, const PredictedImpact& impact, Response response,
                  double h, StepStats& stats) {
    ContinuousWorkspace& cw = world.workspace.continuous;
    const std::uint32_t spheres[2] = {impact.i, impact.other >= 0 ? std::uint32_t(impact.other) : impact.i};
    const int count = impact.other >= 0 ? 2 : 1;
    bool outOfReach = false;
    for (int s = 0; s < count; ++s) {
        const std::uint32_t i = spheres[s];
        ++cw.version[i];
        if (response == Response::Bounce) wakeUp(world, i);
        outOfReach = outOfReach || glm::length(world.position[i] - cw.anchor[i]) + travel(world, i, h, params.gravity) > cw.reach;
    }
    if (outOfReach) findCandidates(world, params, h, stats);
    for (int s = 0; s < count; ++s) predict(world, params, spheres[s], impact.time, h, stats);
}

// D, after the spheres reached the end of the step: what gravity pressed into a static
// contact (or, past the cap, any overlap) is cancelled and projected out, K passes of
// sphere pairs then walls, as the position based method orders them (and, as it does,
// passing by the spheres whose wall clearance shows they touch no wall).
void projectOverlaps(World& world, const Params& params) {
    std::vector<double>& clearance = world.workspace.wallClearance;  // m
    findWallClearances(world, params);
    const double scale = planeScale(world);  // m
    for (int pass = 0; pass < params.passes; ++pass) {
        for (const SpherePair& pair : world.workspace.pairs) {
            SphereContact contact;
            if (!touching(world, pair, contact) || contact.depth <= 0.0) continue;
            cancelApproachBetween(world.velocity[pair.i], world.velocity[pair.j], world.mass[pair.i],
                                  world.mass[pair.j], contact.u);
            const Separation moved =
                separateSpheres(world.position[pair.i], world.position[pair.j], world.mass[pair.i],
                                world.mass[pair.j], contact.u, contact.depth, params.split);
            clearance[pair.i] -= moved.first;
            clearance[pair.j] -= moved.second;
        }
        for (std::uint32_t i = 0; i < world.size(); ++i) {
            if (clearance[i] > 0.0) continue;
            forEachTouchedPlane(world, i, [&](std::size_t, const Plane& face) {
                cancelApproachToPlane(world.velocity[i], face.normal);
                projectOnPlane(world.position[i], world.radius[i], face);
            });
            clearance[i] = wallClearance(world, i, scale);
        }
    }
}

}  // namespace

StepStats stepContinuous(World& world, const Params& params, double h) {
    StepStats stats;
    ContinuousWorkspace& cw = world.workspace.continuous;
    const glm::dvec3& g = params.gravity;
    world.workspace.cached = false;  // the other methods' pair cache: not kept up to date here
    for (glm::dvec3& v : world.velocity) v += (0.5 * h) * g;  // the paths' velocities w at t = 0
    cw.pathStart.assign(world.size(), 0.0);
    cw.version.assign(world.size(), 0);
    cw.planeResting.assign(world.size() * world.planes.size(), 0);
    cw.pairResting.clear();
    world.workspace.pairs.clear();
    findCandidates(world, params, h, stats);  // timed as the broad phase, the rest as the passes
    const StageTimer timer(stats.passesSeconds);
    cw.queue.clear();
    predictAll(world, params, h, stats);  // A
    const bool together = solvesTogether(params.solver);
    while (!cw.queue.empty()) {
        std::pop_heap(cw.queue.begin(), cw.queue.end(), later);
        const PredictedImpact impact = cw.queue.back();
        cw.queue.pop_back();
        if (stale(world, impact)) continue;
        if (stats.events >= params.maxEvents(world.size())) {
            stats.cappedSteps = 1;
            break;
        }
        std::vector<PredictedImpact>& group = cw.sameInstant;
        group.assign(1, impact);
        if (together) takeSameInstant(world, group);
        const Response response = group.size() == 1                       ? respondAtContact(world, params, impact, stats)
                                   : params.solver == Solver::Simultaneous ? respondSimultaneouslyAt(world, params, group, stats)
                                                                           : respondTogether(world, params, group, stats);  // B
        if (response == Response::None) continue;
        stats.events += group.size();
        for (const PredictedImpact& taken : group) predictAgain(world, params, taken, response, h, stats);  // C
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {  // D
        moveTo(world, i, h, g);
        world.velocity[i] -= (0.5 * h) * g;
    }
    projectOverlaps(world, params);
    return stats;
}

}  // namespace physics
