#include "physics/step.h"

#include <algorithm>
#include <limits>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "physics/broad_phase.h"
#include "physics/random.h"
#include "physics/solver_stages.h"
#include "physics/thread_team.h"

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
// A jittering pile moves some sphere that far at every step, and a list built with
// the skin would serve once only, costing more tests: after two such builds the grid
// builds with the margin alone, and tries the skin again every kSkinRetry builds.
constexpr int kSkinRetry = 16;

// Below this many spheres a step takes microseconds: handing out its stages to
// other threads would cost more than it saves.
constexpr std::size_t kParallelMinSpheres = 4096;
// Automatic threads (Params::threads = 0) start where a second thread pays: on two
// cores, two threads ran 0.97-1.04x as fast as one at 6k spheres, 1.06-1.07x at 8k and
// 1.11-1.18x at 16k (spheres_bench_solver, the pile, two runs).
constexpr std::size_t kAutomaticParallelMinSpheres = 8192;
constexpr int kMostAutomaticThreads = 8;

// m: how far beyond touching the next build reaches.
double buildReach(const Workspace& ws, double margin, double skin) {
    const bool skinUseless = ws.buildsNotReused >= 2 && ws.buildsNotReused % kSkinRetry != 0;
    return skinUseless ? margin : skin;
}

struct Extent {
    double maxRadius = 0.0;  // m
    double radiusSum = 0.0;  // m
};

// In kExtentLanes independent running maxima and sums, joined at the end: one chain of
// additions through every radius took 0.19 ms a step at 64k spheres. The sum only tells
// whether the radii changed since the broad phase's build (compared with itself), and
// its lanes do not depend on the thread count.
constexpr std::size_t kExtentLanes = 8;

Extent extentOf(const World& world) {
    const std::vector<double>& radius = world.radius;  // m
    double most[kExtentLanes] = {}, sum[kExtentLanes] = {};
    const std::size_t whole = radius.size() - radius.size() % kExtentLanes;
    for (std::size_t i = 0; i < whole; i += kExtentLanes) {
        for (std::size_t lane = 0; lane < kExtentLanes; ++lane) {
            most[lane] = std::max(most[lane], radius[i + lane]);
            sum[lane] += radius[i + lane];
        }
    }
    for (std::size_t i = whole; i < radius.size(); ++i) {
        most[0] = std::max(most[0], radius[i]);
        sum[0] += radius[i];
    }
    Extent e;
    for (std::size_t lane = 0; lane < kExtentLanes; ++lane) {
        e.maxRadius = std::max(e.maxRadius, most[lane]);
        e.radiusSum += sum[lane];
    }
    return e;
}

// A sphere that has moved more than half of (reach - margin) since the build may meet
// spheres outside the cached pairs: a mover. Two others have closed their distance by at
// most reach - margin, so every pair of them within the margin now is cached. Past this
// share of movers a new build costs less than finding their pairs one by one: in a
// resting pile the movers grow a few at each step, and every step until the next build
// searches them all. From the same states (4 solver steps a frame, the broad phase's ms a
// frame at 1 in 8, 16, 32, 64): the resting 10k pile 2.43, 1.60, 1.18, 1.10; the resting
// 100k pile 30.7, 23.4, 22.3, 22.5; the landing 64k pile and a 16k gas, which build at
// nearly every step, the same at all four.
constexpr std::size_t kMostMoversPerSphere = 32;  // 1 in 32

// Whether the cached pairs can serve now; ws.movers and ws.isMover <- the movers.
bool cacheServes(World& world, const Extent& extent, double margin, int threads) {
    Workspace& ws = world.workspace;
    if (!ws.cached || ws.positionsAtBuild.size() != world.size() || ws.radiusSumAtBuild != extent.radiusSum) {
        return false;
    }
    const double slack = 0.5 * (ws.reachAtBuild - margin);  // m
    ws.isMover.resize(world.size());
    std::vector<std::size_t> moverStart(std::size_t(threads) + 1, 0);  // task t's movers; then where they go
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(world.size(), t, threads);
        std::size_t count = 0;
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            const glm::dvec3 move = world.position[i] - ws.positionsAtBuild[i];
            ws.isMover[i] = !(glm::dot(move, move) <= slack * slack);  // a NaN moves
            count += ws.isMover[i];
        }
        moverStart[std::size_t(t) + 1] = count;
    });
    for (int t = 0; t < threads; ++t) moverStart[std::size_t(t) + 1] += moverStart[std::size_t(t)];
    // Below a few thousand spheres a new build costs less than the movers' searches (the
    // 1k pile ran 10 % slower with them): a mover there means a build.
    const std::size_t most = world.size() >= kParallelMinSpheres ? world.size() / kMostMoversPerSphere : 0;
    ws.movers.resize(moverStart.back() > most ? 0 : moverStart.back());
    if (moverStart.back() > most) return false;
    runTasks(threads, threads, [&](int t) {  // listed on the threads too, in index order
        const Range range = rangeOf(world.size(), t, threads);
        std::size_t next = moverStart[std::size_t(t)];
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            if (ws.isMover[i]) ws.movers[next++] = i;
        }
    });
    return true;
}

// out <- the pairs within `margin` of touching, in index order: the cached pairs of
// spheres that are not movers, filtered, and the movers' pairs found anew (cacheServes).
void keepPairsWithinReach(World& world, double margin, int threads, std::vector<SpherePair>& out,
                          StepStats& stats) {
    Workspace& ws = world.workspace;
    const bool anyMover = !ws.movers.empty();
    const int tasks = threads > 1 ? 4 * threads : 1;
    ws.tasks.resize(std::size_t(tasks));
    std::vector<std::size_t> keptStart(std::size_t(tasks) + 1, 0);  // task t's kept pairs; then where they go in out
    runTasks(threads, tasks, [&](int t) {
        const Range range = rangeOf(ws.pairs.size(), t, tasks);
        // Each pair written and counted when kept, without a branch: about half of the
        // cached pairs are within the margin, as good as at random.
        std::vector<SpherePair>& candidates = ws.tasks[std::size_t(t)].kept;
        if (candidates.size() < range.end - range.begin) candidates.resize(range.end - range.begin);
        std::size_t count = 0;
        for (std::uint32_t k = range.begin; k < range.end; ++k) {
            const SpherePair pair = ws.pairs[k];
            const bool moves = anyMover && (ws.isMover[pair.i] | ws.isMover[pair.j]);
            candidates[count] = pair;
            count += !moves & withinReach(world, pair, margin);
        }
        keptStart[std::size_t(t) + 1] = count;
    });
    for (int t = 0; t < tasks; ++t) keptStart[std::size_t(t) + 1] += keptStart[std::size_t(t)];
    out.resize(keptStart.back());
    runTasks(threads, tasks, [&](int t) {  // joined on the threads too (0.1 ms at 64k)
        const std::size_t begin = keptStart[std::size_t(t)], end = keptStart[std::size_t(t) + 1];
        const SpherePair* first = ws.tasks[std::size_t(t)].kept.data();
        std::copy(first, first + (end - begin), out.begin() + std::ptrdiff_t(begin));
    });
    if (!anyMover) return;
    stats.pairTests += findMoverPairs(world, margin, ws, threads);
    const std::size_t kept = out.size();
    out.insert(out.end(), ws.moverPairs.begin(), ws.moverPairs.end());
    std::inplace_merge(out.begin(), out.begin() + std::ptrdiff_t(kept), out.end(), inIndexOrder);
}

void reorder(World& world, PairOrder order, int threads) {
    std::vector<SpherePair>& pairs = world.workspace.visitOrder;
    if (order == PairOrder::Colored) colorPairs(world, threads);
    if (order == PairOrder::Reversed) std::reverse(pairs.begin(), pairs.end());
    if (order != PairOrder::Shuffled) return;
    Random random(world.seed ^ (world.stepCount * 0x9E3779B97F4A7C15ull));
    for (std::size_t k = pairs.size(); k > 1; --k) std::swap(pairs[k - 1], pairs[random.below(k)]);
}

// Slabs across one axis (0: x, 1: y) of the spheres' centres, as many as threads, cut
// where each holds about as many centres (a far-flung sphere cannot empty a slab).
struct Slabs {
    int axis = 0;
    int count = 1;
    std::array<double, kMostSolverThreads - 1> cuts{};  // m, ascending: slab s ends at cuts[s]

    std::uint32_t of(const glm::dvec3& centre) const {
        const double c = centre[axis];  // m
        if (!std::isfinite(c)) return 0u;
        return std::uint32_t(std::upper_bound(cuts.data(), cuts.data() + (count - 1), c) - cuts.data());
    }
};

// The most centres whose coordinates place the cuts: enough for cuts at about the
// right quantiles, few enough to cost nothing next to the share-out.
constexpr std::size_t kSlabSample = 4096;

// `count` slabs across `axis`, cut at the quantiles of a sample of the centres (`sample`
// is scratch). The sample's numbers are scattered by a multiplicative hash, so that no
// stride lines up with the rows of a lattice. A centre not finite goes to the first slab.
Slabs slabsAcross(const World& world, int axis, int count, std::vector<double>& sample) {
    sample.clear();
    const std::uint64_t n = world.size(), taken = std::min<std::uint64_t>(n, kSlabSample);
    for (std::uint64_t k = 0; k < taken; ++k) {
        const std::uint64_t i = taken == n ? k : (k * 2654435761u) % n;
        if (std::isfinite(world.position[i][axis])) sample.push_back(world.position[i][axis]);
    }
    Slabs slabs{axis, count, {}};
    if (sample.empty()) return slabs;  // every cut at 0 m
    for (int s = 1; s < count; ++s) {
        const auto at = sample.begin() + std::ptrdiff_t(sample.size() * std::size_t(s) / std::size_t(count));
        std::nth_element(sample.begin(), at, sample.end());
        slabs.cuts[std::size_t(s - 1)] = *at;  // ascending, as s is
    }
    return slabs;
}

// How many times the slab changes from one sphere number to the next.
std::size_t slabChanges(const World& world, const Slabs& slabs) {
    std::size_t changes = 0;
    std::uint32_t last = world.size() > 0 ? slabs.of(world.position[0]) : 0u;
    for (std::size_t i = 1; i < world.size(); ++i) {
        const std::uint32_t slab = slabs.of(world.position[i]);
        changes += slab != last;
        last = slab;
    }
    return changes;
}

// Slabs of x or of y, whichever keeps the longer runs of consecutive sphere numbers in
// one slab. The passes visit the pairs by number, so the threads keep pace with each
// other and wait where one's run of numbers meets the other's: the scenes' lattices
// number the spheres row by row along x, layer by layer up z, so slabs of x cut every
// row (a wait every few dozen pairs), slabs of y each layer once. Not z: for these
// numbers its slabs are ranges of numbers, whole layers, and each thread would wait for
// the one below (shares by ranges of numbers measured 1.0x). An axis with no change at
// all has every sphere in one slab (all centres at one coordinate): the other wins.
Slabs shareSlabs(World& world, int threads) {
    std::vector<double>& sample = world.workspace.slabSample;
    const Slabs x = slabsAcross(world, 0, threads, sample), y = slabsAcross(world, 1, threads, sample);
    const auto cost = [&](const Slabs& slabs) {
        const std::size_t changes = slabChanges(world, slabs);
        return changes > 0 ? changes : world.size();
    };
    return cost(y) < cost(x) ? y : x;
}

// Shares visitOrder's pairs out between `threads` threads (Workspace::sharedPairs): by
// the slab (shareSlabs) that holds the first sphere.
void sharePairsOut(World& world, int threads) {
    Workspace& ws = world.workspace;
    const Slabs slabs = shareSlabs(world, threads);
    const auto threadOf = [&](std::uint32_t sphere) { return slabs.of(world.position[sphere]); };
    ws.shareThreads = threads;
    ws.shareStart.assign(std::size_t(threads) + 1, 0);
    ws.threadOfPair.resize(ws.visitOrder.size());
    for (std::size_t k = 0; k < ws.visitOrder.size(); ++k) {
        ws.threadOfPair[k] = threadOf(ws.visitOrder[k].i);
        ++ws.shareStart[ws.threadOfPair[k] + 1];
    }
    for (int t = 0; t < threads; ++t) ws.shareStart[std::size_t(t) + 1] += ws.shareStart[std::size_t(t)];
    // Walk the pass order, noting where each sphere was met last.
    ws.sharedPairs.resize(ws.visitOrder.size());
    ws.pairNeeds.resize(2 * ws.visitOrder.size());
    ws.lastPairOf.assign(world.size(), {});
    std::uint32_t placed[kMostSolverThreads];  // where each thread's next pair goes
    std::copy(ws.shareStart.begin(), ws.shareStart.end() - 1, placed);
    for (std::size_t k = 0; k < ws.visitOrder.size(); ++k) {
        const SpherePair pair = ws.visitOrder[k];
        const std::uint32_t t = ws.threadOfPair[k], slot = placed[t]++;
        ws.sharedPairs[slot] = pair;
        const std::uint32_t doneWithThis = slot - ws.shareStart[t] + 1;
        for (int side = 0; side < 2; ++side) {
            Workspace::PairNeed& last = ws.lastPairOf[side == 0 ? pair.i : pair.j];
            ws.pairNeeds[2 * slot + std::size_t(side)] = last.thread != t ? last : Workspace::PairNeed{};
            last = {t, doneWithThis};
        }
    }
}

}  // namespace

namespace {

// The threads automatic mode starts with: one per core this process may use.
int automaticMany() {
    static const int cores = usableCores();
    return std::min(cores, kMostAutomaticThreads);
}

// Whether automatic mode chooses this world's threads (AutomaticThreads).
bool threadsChosenAutomatically(const World& world, const Params& params) {
    return params.threads == 0 && world.size() >= kAutomaticParallelMinSpheres && automaticMany() > 1 &&
           params.method != Method::Continuous && params.solver != Solver::Simultaneous;
}

}  // namespace

int solverThreads(const World& world, const Params& params) {
    // Impacts in time order are one sequence: the continuous method runs on one thread; so
    // does the simultaneous solver, whose sums per sphere then add in one order. (The
    // global solvers share out whole clusters of touching spheres.)
    if (!kCanStartThreads || world.size() < kParallelMinSpheres || params.method == Method::Continuous ||
        params.solver == Solver::Simultaneous) {
        return 1;
    }
    if (params.threads > 0) return std::min(params.threads, kMostSolverThreads);
    if (!threadsChosenAutomatically(world, params)) return 1;
    const int chosen = world.workspace.automaticThreads.current();
    return chosen > 0 ? chosen : automaticMany();
}

StepStats& StepStats::operator+=(const StepStats& o) {
    pairTests += o.pairTests;
    broadPhaseBuilds += o.broadPhaseBuilds;
    candidatePairs += o.candidatePairs;
    sphereContacts += o.sphereContacts;
    wallContacts += o.wallContacts;
    collisions += o.collisions;
    staticContacts += o.staticContacts;
    mostSpheresInContact = std::max(mostSpheresInContact, o.mostSpheresInContact);
    passesUsed += o.passesUsed;
    passCapHits += o.passCapHits;
    lcpSweeps += o.lcpSweeps;
    lcpResidual = std::max(lcpResidual, o.lcpResidual);
    reflectionRounds += o.reflectionRounds;
    reflectionCapHits += o.reflectionCapHits;
    shockLevels = std::max(shockLevels, o.shockLevels);
    shockRounds += o.shockRounds;
    impacts += o.impacts;
    events += o.events;
    toiIterations += o.toiIterations;
    cappedSteps += o.cappedSteps;
    broadPhaseSeconds += o.broadPhaseSeconds;
    passesSeconds += o.passesSeconds;
    return *this;
}

void integrateVelocity(World& world, const Params& params, double h) {
    StepStats none;
    forEachSphere(world, params, none, [&](std::uint32_t i, StepStats&) { world.velocity[i] += h * params.gravity; });
}

void integratePosition(World& world, const Params& params, double h) {
    StepStats none;
    forEachSphere(world, params, none, [&](std::uint32_t i, StepStats&) { world.position[i] += h * world.velocity[i]; });
}

void findPairsWithinReach(World& world, const Params& params, StepStats& stats, std::vector<SpherePair>& out) {
    const StageTimer timer(stats.broadPhaseSeconds);
    Workspace& ws = world.workspace;
    const int threads = solverThreads(world, params);
    const Extent extent = extentOf(world);
    const double margin = kMarginFraction * extent.maxRadius;
    ws.margin = margin;
    if (params.broadPhase == BroadPhase::AllPairs) {  // the lecture's loop, every step
        ws.cached = false;
        stats.pairTests += findPairs(params.broadPhase, world, margin, ws);
        ++stats.broadPhaseBuilds;
        out.swap(ws.pairs);  // the pairs are not kept
    } else if (cacheServes(world, extent, margin, threads)) {
        ws.reusedSinceBuild = true;
        keepPairsWithinReach(world, margin, threads, out, stats);
    } else {
        ws.buildsNotReused = ws.built && !ws.reusedSinceBuild ? ws.buildsNotReused + 1 : 0;
        ws.reusedSinceBuild = false;
        ws.built = true;
        ws.reachAtBuild = buildReach(ws, margin, kSkinFraction * extent.maxRadius);
        stats.pairTests += findPairs(params.broadPhase, world, ws.reachAtBuild, ws, threads);
        ++stats.broadPhaseBuilds;
        // Without a skin the list serves this step only, and holds exactly the pairs
        // within the margin (the same test, on the same numbers): nothing to keep.
        ws.cached = ws.reachAtBuild > margin;
        if (ws.cached) {
            ws.positionsAtBuild = world.position;
            ws.radiusSumAtBuild = extent.radiusSum;
            ws.movers.clear();
            keepPairsWithinReach(world, margin, threads, out, stats);
        } else {
            out.swap(ws.pairs);  // the pairs are not kept
        }
    }
}

void findOrderedPairs(World& world, const Params& params, StepStats& stats) {
    Workspace& ws = world.workspace;
    findPairsWithinReach(world, params, stats, ws.visitOrder);
    const StageTimer timer(stats.broadPhaseSeconds);
    stats.candidatePairs += ws.visitOrder.size();
    const int passThreads = threadsFor(world, params);
    reorder(world, params.order, passThreads);
    ws.shareThreads = 1;
    ws.borderByWavefronts = false;
    // The colored order shares out its blocks and colours as it goes (forEachColor; in the
    // position stages its border by wavefronts), and the lecture's orders in the position
    // stages go by wavefronts (forEachWavefront): both found with the wall clearances.
    if (passThreads > 1 && params.order != PairOrder::Colored && !passesByWavefronts(world, params)) {
        sharePairsOut(world, passThreads);
    }
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

Response respondToContact(World& world, const SpherePair& pair, const SphereContact& contact,
                          const Params& params, StepStats& stats, int pass) {
    const glm::dvec3 before[2] = {world.velocity[pair.i], world.velocity[pair.j]};  // m/s
    const Response response = respondToSphere(world.velocity[pair.i], world.velocity[pair.j],
                                              world.mass[pair.i], world.mass[pair.j], contact.u,
                                              params);
    record(world, pair.i, response);
    record(world, pair.j, response);
    count(stats, response);
    if (world.measureImpacts && response != Response::None) noteAnswered(world, pair.i, pair.j);
    stats.sphereContacts += pass == 0;
    if (world.recordContacts && response != Response::None) {
        ContactEvent event{pair.i, static_cast<std::int32_t>(pair.j), pass,
                           response == Response::Bounce, contact.u,
                           world.position[pair.i] - world.radius[pair.i] * contact.u,
                           contact.depth, {before[0], before[1]},
                           {world.velocity[pair.i], world.velocity[pair.j]},
                           {world.mass[pair.i], world.mass[pair.j]}};
        event.solverStep = world.stepCount;  // timeOfImpact and solvedImpulse: -1, a pairwise response
        world.contacts.push_back(event);
    }
    return response;
}

Response respondToContact(World& world, std::uint32_t i, std::size_t planeIndex, const Plane& face,
                          const Params& params, StepStats& stats, int pass) {
    const glm::dvec3 before = world.velocity[i];
    const Response response = respondToPlane(world.velocity[i], face.normal, params);
    record(world, i, response);
    count(stats, response);
    if (world.measureImpacts && response != Response::None) noteAnswered(world, i, -1);
    stats.wallContacts += pass == 0;
    if (world.recordContacts && response != Response::None) {
        const double distance = glm::dot(world.position[i] - face.point, face.normal);  // m
        ContactEvent event{i, -1 - static_cast<std::int32_t>(planeIndex), pass,
                           response == Response::Bounce, face.normal,
                           world.position[i] - distance * face.normal, world.radius[i] - distance,
                           {before, glm::dvec3(0.0)}, {world.velocity[i], glm::dvec3(0.0)},
                           {world.mass[i], 0.0}};
        event.solverStep = world.stepCount;  // timeOfImpact and solvedImpulse: -1, a pairwise response
        world.contacts.push_back(event);
    }
    return response;
}

Response respondToFrozenContact(World& world, std::uint32_t i, std::uint32_t frozen, const SphereContact& contact,
                                const Params& params, StepStats& stats) {
    const glm::dvec3 before = world.velocity[i];  // m/s
    const Response response = respondToFrozenSphere(world.velocity[i], world.velocity[frozen], contact.u, params);
    record(world, i, response);
    count(stats, response);
    if (world.measureImpacts && response != Response::None) noteAnswered(world, i, frozen);
    if (world.recordContacts && response != Response::None) {  // the frozen sphere: infinitely heavy
        ContactEvent event{i, static_cast<std::int32_t>(frozen), params.passes, response == Response::Bounce,
                           contact.u, world.position[i] - world.radius[i] * contact.u, contact.depth,
                           {before, world.velocity[frozen]}, {world.velocity[i], world.velocity[frozen]},
                           {world.mass[i], std::numeric_limits<double>::infinity()}};
        event.solverStep = world.stepCount;  // timeOfImpact and solvedImpulse: -1, a pairwise response
        world.contacts.push_back(event);
    }
    return response;
}

void findContacts(World& world, const Params& params) {
    Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = pairsAsVisited(world, params);
    ws.pairTouches.resize(pairs.size());
    ws.pairContacts.resize(pairs.size());
    const int threads = threadsFor(world, params);
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(pairs.size(), t, threads);
        for (std::uint32_t k = range.begin; k < range.end; ++k) {
            ws.pairTouches[k] = touching(world, pairs[k], ws.pairContacts[k]);
        }
    });
    ws.wallStart.assign(world.size() + 1, 0);
    ws.wallContacts.clear();
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        forEachTouchedPlane(world, i, [&](std::size_t k, const Plane& face) {
            ws.wallContacts.push_back({static_cast<std::uint32_t>(k), face});
        });
        ws.wallStart[i + 1] = static_cast<std::uint32_t>(ws.wallContacts.size());
    }
}

bool contactsStillApproach(World& world, const Params& params) {
    findContacts(world, params);
    const Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = pairsAsVisited(world, params);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (!ws.pairTouches[k]) continue;
        const glm::dvec3 relative = world.velocity[pairs[k].j] - world.velocity[pairs[k].i];  // m/s
        if (glm::dot(relative, ws.pairContacts[k].u) > kConvergedApproachSpeed) return true;
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        for (std::uint32_t w = ws.wallStart[i]; w < ws.wallStart[i + 1]; ++w) {
            if (glm::dot(world.velocity[i], ws.wallContacts[w].face.normal) < -kConvergedApproachSpeed) return true;
        }
    }
    return false;
}

void findWallClearances(World& world, const Params& params) {
    world.workspace.wallClearance.resize(world.size());
    const double scale = planeScale(world);  // m
    StepStats none;
    forEachSphere(world, params, none, [&](std::uint32_t i, StepStats&) {
        world.workspace.wallClearance[i] = wallClearance(world, i, scale);
    });
}

void respondToAllContacts(World& world, const Params& params, StepStats& stats, int pass) {
    const Workspace& ws = world.workspace;
    assert(ws.pairTouches.size() == pairsAsVisited(world, params).size());  // findContacts ran
    forEachPairInPassOrder(world, params, stats, [&](const SpherePair* pairs, std::uint32_t first,
                                                     std::uint32_t last, StepStats& s) {
        for (std::uint32_t k = first; k < last; ++k) {
            if (ws.pairTouches[k]) respondToContact(world, pairs[k], ws.pairContacts[k], params, s, pass);
        }
    });
    forEachSphere(world, params, stats, [&](std::uint32_t i, StepStats& s) {
        for (std::uint32_t w = ws.wallStart[i]; w < ws.wallStart[i + 1]; ++w) {
            respondToContact(world, i, ws.wallContacts[w].plane, ws.wallContacts[w].face, params, s, pass);
        }
    });
}

namespace {

StepStats solverStep(World& world, const Params& params, double h) {
    switch (params.method) {
        case Method::PositionBased: return stepPositionBased(world, params, h);
        case Method::VelocityBased: return stepVelocityBased(world, params, h);
        case Method::ResponseOnly: return stepResponseOnly(world, params, h);
        case Method::Reflection: return stepReflection(world, params, h);
        case Method::Continuous: return stepContinuous(world, params, h);
    }
    return {};
}

}  // namespace

StepStats step(World& world, const Params& params) {
    StepStats stats;
    world.contacts.clear();
    const double h = params.solverStep();
    AutomaticThreads& automatic = world.workspace.automaticThreads;
    for (int s = 0; s < params.substeps; ++s) {
        // A step that logs its contacts or measures its impacts runs on one thread whatever
        // the choice: not timed.
        const bool timed = threadsChosenAutomatically(world, params) && !world.answersOneAtATime();
        if (timed) automatic.next(automaticMany());
        const auto start = std::chrono::steady_clock::now();
        std::fill(world.contactState.begin(), world.contactState.end(), ContactState::Free);
        stats += solverStep(world, params, h);
        const auto inContact = std::count_if(world.contactState.begin(), world.contactState.end(),
                                             [](ContactState state) { return state != ContactState::Free; });
        stats.mostSpheresInContact = std::max(stats.mostSpheresInContact, std::uint64_t(inContact));
        world.time += h;
        ++world.stepCount;
        stats.threads = threadsFor(world, params);
        if (timed) {
            automatic.record(stats.threads, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        stats.slowerThreads = timed ? automatic.slowerCount() : 0;
    }
    return stats;
}

}  // namespace physics
