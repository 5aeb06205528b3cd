// Slide 14's first global answer: "precompute contact graph, explicit shock propagation
// management" (Guendelman, Bridson and Fedkiw 2003).
// The touching contacts after the ordinary passes form a graph: spheres are its nodes,
// touching pairs its edges. Level 0 is every sphere that touches a plane; level k + 1 every
// sphere that touches level k and none lower. The sweep climbs the levels. In level k:
//   1. the contacts inside the level, both spheres movable (the passes' own response);
//   2. each sphere's contacts with level k - 1, that level frozen: infinitely heavy, it
//      moves no more; then its planes (walls last, as in the position based method);
//   3. level k is frozen.
// The weight of a whole stack then reaches the floor in one sweep, instead of one sphere
// per pass. Spheres that reach no plane (a cluster in free fall) keep what the passes did.
// Last, one more pass over the contacts still deeper than 0.5 % of r, those the levels
// cannot clear (a sphere caged between frozen spheres) among them, splits each between both
// spheres as the passes do (separateWhatIsLeft).
// The graph, kept from step to step and updated where its pairs changed: contact_graph.cpp.
//
// What the sweep answers: every overlap, by projection (the frozen side not moved; with
// the reflection method too: a resting contact does not bounce, and (1 + beta) d lifted
// each level above the last, the column gaining 2.8 % of its energy in 2 s), and the
// static contacts (|c| <= epsilon, slide 13: the approach removed, then mu). A contact
// that approaches faster is an impact: the passes answered it with both masses, and the
// sweep leaves its velocity alone. Answered against a frozen sphere moving
// towards it, an impact would throw the upper sphere off with energy from nowhere (the
// frozen sphere keeps its own), and a struck stack would move as one rigid body.
#include <algorithm>
#include <cmath>

#include "physics/solver_stages.h"

namespace physics {
namespace {

// The position stage of a level repeats until no contact inside it is deeper than this
// fraction of the smaller radius, or for this many rounds; in its first round, a sphere
// is moved off the frozen spheres below it until none is deeper than this fraction of
// its radius, or for this many rounds (a sphere resting on three may need a few).
constexpr double kSettledOverlap = 1e-3;
constexpr int kMostLevelRounds = 4;
constexpr int kMostFrozenRounds = 8;
// A level of fewer spheres is answered on one thread: sharing it out would cost more.
constexpr std::uint32_t kParallelLevelSpheres = 512;
// The position stage finds the pairs within reach again after the passes, for the graph,
// where a sphere moved in them by more than this fraction of the margin.
constexpr double kMoveThatFindsPairsAgain = 0.25;
// After the sweep, a contact deeper than this fraction of the smaller radius is split
// between both spheres (half the aim of 1 % of r for a settled pile).
constexpr double kLeftOverlap = 5e-3;

bool isStatic(double normalSpeed, const Params& params) { return std::abs(normalSpeed) <= params.epsilon; }

// The sweep over one solver step's contacts; `moves`: the position stage too.
class Sweep {
  public:
    Sweep(World& world, const Params& params, StepStats& stats, bool moves)
        : world_(world), graph_(world.workspace.contactGraph), params_(params), stats_(stats), moves_(moves),
          planeScale_(planeScale(world)) {}

    // Level k: its contacts inside, then each sphere's on the frozen level below and on the
    // planes, velocities (static contacts) and overlaps; then the contacts those pushes
    // pressed together again (pressAgain).
    void level(std::uint32_t k) {
        insideFirstRound(k);
        onFrozenLevel(k);
        ++stats_.shockRounds;
        if (moves_) pressAgain(k);
    }

    // What the levels cannot clear. A level counts contacts from the floor, not height: a
    // sphere of level k may have spheres of level k - 1 above it as well as below, all frozen
    // when its level is answered, and its rounds end with it pressed into one of them (up to
    // 2.5 % of r in the 64k pile; 1.5 % in the 10k pile's seed 4 at 5 s, where the aim is
    // 1 %). No number of rounds clears such a cage (a frozen sphere must give way), so once
    // the levels are done, each contact still deeper than kLeftOverlap is split between both
    // spheres, as the position stage's passes split it, and the spheres are put back off their
    // planes (walls last: never crossed). One more pass over the step's pairs, in their order,
    // for the deep contacts only: the same on any thread count. It takes in the spheres with
    // no level too, as the passes do: in the peers' landing 64k pile a cluster in free fall
    // kept 5.9 % of r, against 1.4 % for the whole pile once it was taken in.
    void separateWhatIsLeft(const std::vector<SpherePair>& pairs) {
        if (!moves_) return;
        for (const SpherePair& pair : pairs) {
            if (!pressedDeeper(pair, kLeftOverlap)) continue;
            inside(pair, false);
            onPlanes(pair.i, false, stats_);
            onPlanes(pair.j, false, stats_);
        }
    }

  private:
    // The contacts inside level k, their first round (static contacts answered, then
    // split), in the sweep's order (forEachPairInside). The position stages take them
    // wavefront by wavefront (as wavefronts.cpp does a pass: each sphere meets its pairs in
    // that order, so the result is the same bit for bit), several side by side.
    void insideFirstRound(std::uint32_t k) {
        static const bool wideLanes = laneWidths().back() >= 4;
        if (!wideLanes || !clearanceKept() || world_.answersOneAtATime()) {
            forEachPairInside(k, [&](const SpherePair& pair) { inside(pair, true); });
            return;
        }
        std::vector<SpherePair>& pairs = graph_.insidePairs;
        pairs.clear();
        forEachPairInside(k, [&](const SpherePair& pair) { pairs.push_back(pair); });
        graph_.wavefrontNext.resize(world_.size(), 0);
        std::vector<std::uint32_t>& start = graph_.wavefrontStart;
        std::vector<SpherePair>& order = graph_.byWavefront;
        sortIntoWavefronts(pairs.data(), pairs.size(), graph_.wavefrontNext, graph_.wavefrontOfPair, start, order);
        for (std::size_t w = 0; w + 1 < start.size(); ++w) {
            std::uint32_t c = separateSideBySide(world_, params_, order.data(), start[w], start[w + 1], stats_,
                                                 params_.passes, 1.0, true, true);
            for (; c < start[w + 1]; ++c) inside(order[c], true);
        }
    }

    // visit(pair) on the contacts inside level k: by sphere, then by neighbour, each once.
    template <class Visit>
    void forEachPairInside(std::uint32_t k, const Visit& visit) const {
        for (std::uint32_t s = graph_.levelStart[k]; s < graph_.levelStart[k + 1]; ++s) {
            const std::uint32_t i = graph_.byLevel[s];
            const std::uint32_t* beside = besideOf(i);
            for (std::uint32_t b = graph_.besideBefore[i]; b < graph_.besideCount[i]; ++b) visit(SpherePair{i, beside[b]});
        }
    }
    const std::uint32_t* belowOf(std::uint32_t i) const { return graph_.neighbour.data() + graph_.edgeStart[i]; }
    const std::uint32_t* besideOf(std::uint32_t i) const { return belowOf(i) + graph_.belowCount[i]; }

    // Every sphere of level k against the frozen level below and its planes (onFrozen). Each
    // moves only itself against spheres that no longer move: the level's spheres can be
    // shared between threads, with the result of one thread.
    void onFrozenLevel(std::uint32_t k) {
        const std::uint32_t first = graph_.levelStart[k], count = graph_.levelStart[k + 1] - first;
        if (frozenInLanes()) sortByBelow(graph_.byLevel.data() + first, count, graph_.byBelow.data() + first);
        const int threads = count >= kParallelLevelSpheres ? threadsFor(world_, params_) : 1;
        if (threads == 1) {
            onFrozen(first, first + count, stats_);
            return;
        }
        const int tasks = 4 * threads;
        runCountedTasks(threads, tasks, stats_, [&](int t, StepStats& local) {
            const Range range = rangeOf(count, t, tasks);
            onFrozen(first + range.begin, first + range.end, local);
        });
    }

    // The pushes off the frozen level may press spheres of level k into each other: those
    // contacts, and the frozen contacts of their spheres, are answered again (overlaps
    // only) while any is deeper than kSettledOverlap, for at most kMostLevelRounds rounds
    // in all. Only the few that need it: a whole level's contacts cost as much as a pass.
    void pressAgain(std::uint32_t k) {
        const std::vector<SpherePair>& pressed = graph_.pressed;
        findPressedInside(k);
        std::vector<std::uint32_t>& moved = graph_.queue;  // free again: the levels are found
        for (int round = 1; round < kMostLevelRounds && !pressed.empty(); ++round) {
            for (const SpherePair& pair : pressed) inside(pair, false);
            moved.clear();
            std::size_t besides = 0;  // of the moved spheres
            for (const SpherePair& pair : pressed) {
                for (const std::uint32_t i : {pair.i, pair.j}) {
                    if (graph_.moved[i]) continue;
                    graph_.moved[i] = 1;
                    moved.push_back(i);
                    besides += graph_.besideCount[i];
                }
            }
            // Each moved sphere off the frozen spheres below it once (the level's rounds
            // repeat it), then off its planes: onFrozen's later rounds, side by side.
            graph_.movedByBelow.resize(moved.size());
            sortByBelow(moved.data(), moved.size(), graph_.movedByBelow.data());
            pushOffFrozenSideBySide(world_, graph_, graph_.movedByBelow.data(), moved.size(), clearanceKept());
            for (const std::uint32_t i : moved) onPlanes(i, false, stats_);
            ++stats_.shockRounds;
            if (round + 1 < kMostLevelRounds) findPressedBeside(moved, besides);  // the next round's
            for (const std::uint32_t i : moved) graph_.moved[i] = 0;
        }
    }

    // pressed <- the contacts inside level k pressed deeper than kSettledOverlap. Pairs are
    // kept without a branch (pressed[count] written, count moved on if kept): which are
    // still pressed is as good as random.
    void findPressedInside(std::uint32_t k) {
        std::vector<SpherePair>& pressed = graph_.pressed;
        std::size_t count = 0;
        std::size_t insidePairs = 0;
        for (std::uint32_t s = graph_.levelStart[k]; s < graph_.levelStart[k + 1]; ++s) {
            insidePairs += graph_.besideCount[graph_.byLevel[s]] - graph_.besideBefore[graph_.byLevel[s]];
        }
        pressed.resize(insidePairs);
        forEachPairInside(k, [&](const SpherePair& pair) {
            pressed[count] = pair;
            count += pressedDeeper(pair);
        });
        pressed.resize(count);
    }

    // pressed <- the level's contacts of the spheres just moved (graph_.moved set; `besides`
    // contacts in all) that are pressed deeper than kSettledOverlap, each once (kept as above).
    void findPressedBeside(const std::vector<std::uint32_t>& moved, std::size_t besides) {
        std::vector<SpherePair>& pressed = graph_.pressed;
        std::size_t count = 0;
        pressed.resize(besides);
        for (const std::uint32_t i : moved) {
            const std::uint32_t* beside = besideOf(i);
            for (std::uint32_t b = 0; b < graph_.besideCount[i]; ++b) {
                const std::uint32_t j = beside[b];
                const SpherePair pair{std::min(i, j), std::max(i, j)};
                pressed[count] = pair;
                count += std::size_t(!(graph_.moved[j] && j < i)) & std::size_t(pressedDeeper(pair));
            }
        }
        pressed.resize(count);
    }

    // Whether the pair overlaps by more than `fraction` of the smaller radius: whether its
    // centres are closer than reach - fraction r, compared squared (no square root, no
    // division: this runs on every contact the pushes may have pressed).
    bool pressedDeeper(const SpherePair& pair, double fraction = kSettledOverlap) const {
        const glm::dvec3 delta = world_.position[pair.i] - world_.position[pair.j];
        const double ri = world_.radius[pair.i], rj = world_.radius[pair.j];  // m
        const double closest = ri + rj - fraction * std::min(ri, rj);          // m, > 0
        return glm::dot(delta, delta) < closest * closest;
    }

    // Both spheres in the level: the passes' own response (static contacts) and split.
    void inside(const SpherePair& pair, bool velocities) {
        SphereContact contact;
        if (!touching(world_, pair, contact)) return;
        const std::uint32_t i = pair.i, j = pair.j;
        if (velocities && isStatic(glm::dot(world_.velocity[j] - world_.velocity[i], contact.u), params_)) {
            respondToContact(world_, pair, contact, params_, stats_, params_.passes);
        }
        if (!moves_) return;
        const Separation moved = separateSpheres(world_.position[i], world_.position[j], world_.mass[i],
                                                 world_.mass[j], contact.u, contact.depth, params_.split);
        lowerClearance(i, moved.first);
        lowerClearance(j, moved.second);
    }

    // The position based methods keep each sphere's wall clearance (solver_stages.h's
    // wallClearance: a lower bound on its gap to every plane) through the passes; the
    // sweep lowers it by each move and visits the planes of a sphere only at or below 0,
    // as their wall stage does. The velocity method keeps none: every sphere is visited.
    bool clearanceKept() const { return moves_ && world_.workspace.wallClearance.size() == world_.size(); }
    void lowerClearance(std::uint32_t i, double moved) {
        if (clearanceKept()) world_.workspace.wallClearance[i] -= moved;
    }

    // byLevel's spheres [begin, end) off the frozen spheres below them, then off their
    // planes (walls last: never crossed), in at most kMostFrozenRounds rounds: a round that
    // pushed a sphere off one frozen sphere only, or none deeper than kSettledOverlap of its
    // radius, is its last. The first round answers the static contacts too; the later ones
    // move them only. Both go several spheres side by side (in byBelow's order of the same
    // slots), but the velocity method's first round, and any with the contact log, which go
    // one sphere at a time (in byLevel's). Each sphere moves only itself, against spheres that
    // no longer move: the rounds of one sphere may wait for those of the others.
    void onFrozen(std::uint32_t begin, std::uint32_t end, StepStats& stats) {
        std::uint32_t* again = graph_.again.data() + begin;  // the spheres whose rounds go on
        std::uint8_t* goesOn = graph_.goesOn.data() + begin;
        std::uint32_t count = 0;
        if (frozenInLanes()) {
            const std::uint32_t* spheres = graph_.byBelow.data() + begin;
            pushOffFrozenSideBySide(world_, graph_, spheres, end - begin, clearanceKept(), goesOn, kSettledOverlap, 0,
                                    &params_, &stats);
            for (std::uint32_t c = 0; c < end - begin; ++c) {
                onPlanes(spheres[c], true, stats);
                again[count] = spheres[c];
                count += goesOn[c];
            }
        } else {
            for (std::uint32_t s = begin; s < end; ++s) {
                again[count] = graph_.byLevel[s];
                count += firstRoundOnFrozen(s, stats);
            }
        }
        for (int round = 1; round < kMostFrozenRounds && count > 0; ++round) {
            pushOffFrozenSideBySide(world_, graph_, again, count, clearanceKept(), goesOn, kSettledOverlap);
            std::uint32_t left = 0;
            for (std::uint32_t c = 0; c < count; ++c) {
                onPlanes(again[c], false, stats);
                again[left] = again[c];
                left += goesOn[c];
            }
            count = left;
        }
    }

    // Whether the first round off the frozen level goes several spheres side by side: in the
    // position stages, without the contact log (else one sphere at a time, in byLevel's order).
    bool frozenInLanes() const { return moves_ && !world_.answersOneAtATime(); }

    // spheres[0, count) into `out` by how many frozen spheres each has below, fewest first
    // (a counting sort): the pushes off the frozen level then run as many turns in each
    // lane (8 lanes in the level's order: two thirds of their turns used, in the resting
    // 10k pile). Each sphere moves only itself, against spheres that no longer move: the
    // order changes no result.
    void sortByBelow(const std::uint32_t* spheres, std::uint32_t count, std::uint32_t* out) const {
        constexpr std::uint32_t kKinds = 8;  // 7 or more below go together
        std::uint32_t start[kKinds + 1] = {};
        for (std::uint32_t c = 0; c < count; ++c) ++start[std::min(graph_.belowCount[spheres[c]], kKinds - 1) + 1];
        for (std::uint32_t b = 0; b < kKinds; ++b) start[b + 1] += start[b];
        for (std::uint32_t c = 0; c < count; ++c) out[start[std::min(graph_.belowCount[spheres[c]], kKinds - 1)]++] = spheres[c];
    }

    // byLevel's s-th sphere's first round: velocities (the static contacts), then positions.
    // Returns whether it needs another.
    bool firstRoundOnFrozen(std::uint32_t s, StepStats& stats) {
        const std::uint32_t i = graph_.byLevel[s];
        double deepest = 0.0;  // m
        int pushed = 0;
        const std::uint32_t* below = belowOf(i);
        for (std::uint32_t b = 0; b < graph_.belowCount[i]; ++b) {
            const double depth = onFrozenSphere(i, below[b], stats);  // m
            deepest = std::max(deepest, depth);
            pushed += depth > 0.0;
        }
        onPlanes(i, true, stats);
        return moves_ && pushed > 1 && deepest > kSettledOverlap * world_.radius[i];
    }

    // The first round's contact with a frozen sphere. Returns the overlap (m) it found.
    double onFrozenSphere(std::uint32_t i, std::uint32_t frozen, StepStats& stats) {
        SphereContact contact;  // u from the frozen sphere to i
        if (!touching(world_, SpherePair{i, frozen}, contact)) return 0.0;
        if (isStatic(glm::dot(world_.velocity[frozen] - world_.velocity[i], contact.u), params_)) {
            respondToFrozenContact(world_, i, frozen, contact, params_, stats);
        }
        if (moves_) {
            moveOffFrozenSphere(world_.position[i], contact.u, contact.depth);
            lowerClearance(i, contact.depth);
        }
        return contact.depth;
    }

    void onPlanes(std::uint32_t i, bool velocities, StepStats& stats) {
        const bool kept = clearanceKept();
        if (kept && world_.workspace.wallClearance[i] > 0.0) return;  // touches no plane
        forEachTouchedPlane(world_, i, [&](std::size_t k, const Plane& face) {
            if (velocities && isStatic(glm::dot(world_.velocity[i], face.normal), params_)) {
                respondToContact(world_, i, k, face, params_, stats, params_.passes);
            }
            if (moves_) projectOnPlane(world_.position[i], world_.radius[i], face);
        });
        if (kept) world_.workspace.wallClearance[i] = wallClearance(world_, i, planeScale_);
    }

    World& world_;
    ContactGraph& graph_;
    const Params& params_;
    StepStats& stats_;
    const bool moves_;
    const double planeScale_;  // m: wallClearance's rounding scale
};

}  // namespace

namespace {

// m: the farthest a sphere moved since ContactGraph::positionsBeforePasses.
double farthestMoveInThePasses(const World& world, const ContactGraph& graph) {
    const std::vector<glm::dvec3>& before = graph.positionsBeforePasses;
    if (before.size() != world.size()) return INFINITY;
    double farthestSquared = 0.0;  // m^2
    for (std::size_t i = 0; i < before.size(); ++i) {
        const glm::dvec3 move = world.position[i] - before[i];
        farthestSquared = std::max(farthestSquared, glm::dot(move, move));
    }
    return std::sqrt(farthestSquared);
}

}  // namespace

void propagateShock(World& world, const Params& params, StepStats& stats, bool moves) {
    if (params.shock != ShockPropagation::On) return;
    // The position based passes kept the wall clearances of this step (the velocity
    // method keeps none: its vector may hold another step's).
    const std::vector<double>* clearance =
        moves && world.workspace.wallClearance.size() == world.size() ? &world.workspace.wallClearance : nullptr;
    ContactGraph& graph = world.workspace.contactGraph;
    // The graph of the contacts after the passes: the position stages moved spheres, up to
    // past the margin the step's pairs were found with (an impact's lift pushed a sphere
    // into one it had no pair with; the sweep, blind to that pair, then lifted it deeper:
    // 16.5 % of r in a landing pile of 10k, against 1.9 % once found again).
    // The velocity method moves nothing in its passes: its pairs still hold; nor does the
    // position stage, for the graph, where no sphere moved by a quarter of the margin the
    // pairs were found with (a pair it leaves out is then more than half the margin apart).
    std::vector<SpherePair>* pairs = &world.workspace.visitOrder;
    PairOrder order = params.order;
    if (order == PairOrder::Colored && world.workspace.colorSortedStep == world.stepCount) {
        // The same pairs in index order (colorPairs swapped them out of visitOrder this
        // step): the graph is the same, and can be kept from step to step (keepContactGraph
        // updates it only from pairs in index order; in colour order it was found anew).
        pairs = &world.workspace.colorSorted;
        order = PairOrder::Index;
    }
    if (moves && farthestMoveInThePasses(world, graph) > kMoveThatFindsPairsAgain * world.workspace.margin) {
        pairs = &graph.pairsAfterPasses;
        order = PairOrder::Index;
        findPairsWithinReach(world, params, stats, *pairs);
    }
    keepContactGraph(world, *pairs, order, graph, clearance);
    Sweep sweep(world, params, stats, moves);
    const std::size_t levels = graph.levelStart.size() - 1;
    for (std::uint32_t k = 0; k < levels; ++k) sweep.level(k);
    stats.shockLevels = std::max<std::uint64_t>(stats.shockLevels, levels);
    sweep.separateWhatIsLeft(*pairs);
}

}  // namespace physics
