// Slide 14's contact graph (Guendelman, Bridson and Fedkiw 2003), as the shock sweep
// (shock_propagation.cpp) reads it: spheres are its nodes, the candidate pairs (all within
// the margin of touching) its edges; level 0 is every sphere within the margin of a plane,
// level k + 1 every sphere next to level k and none lower (a breadth-first search).
//
// Each sphere's neighbours are kept in three runs, each by number: one level down (the
// frozen spheres it is pushed off), in its own level (its contacts inside the level), then
// the rest. A resting pile changes a few of its pairs at every step (19 a step in the 10k
// pile at rest) and its levels with them, so the graph is kept from step to step and
// updated around what changed: the levels repaired by the same search, started from the
// changed pairs, and the runs of only the spheres whose neighbours or levels changed. The
// result is the graph found anew, entry for entry (a test compares them after every step).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "physics/solver_stages.h"

namespace physics {
namespace {

// Past this share of the spheres with a changed pair, the graph is found anew: the update
// would visit most of it anyway.
constexpr std::size_t kMostChangedPairsPerSphere = 8;  // 1 in 8
constexpr std::int32_t kNoLevelYet = std::numeric_limits<std::int32_t>::max();  // a level being repaired

// Whether sphere i is within the margin of a plane (level 0). `clearance`, when the
// position based passes kept it (solver_stages.h's wallClearance), passes by the spheres
// surely farther: most of them.
bool levelZero(const World& world, std::uint32_t i, const std::vector<double>* clearance) {
    if (clearance && (*clearance)[i] > world.workspace.margin) return false;
    return nearAPlane(world, i, world.workspace.margin);
}

// graph.edgeStart and graph.neighbour from the pairs. A pair the passes left a hair apart is
// an edge too, so the sweep's moves, which may close it, still reach the spheres above it (a
// column at K = 4 kept a gap under its top sphere, which no level then lifted: 0.47 % of
// r). Each sphere's neighbours by number, whatever the pair order: pairs taken in index
// order (i, then j) give them so, and shuffled or coloured ones are sorted.
void findEdges(std::size_t n, const std::vector<SpherePair>& pairs, PairOrder order, ContactGraph& graph) {
    graph.edgeStart.assign(n + 1, 0);
    for (const SpherePair& pair : pairs) {
        ++graph.edgeStart[pair.i + 1];
        ++graph.edgeStart[pair.j + 1];
    }
    for (std::size_t i = 0; i < n; ++i) graph.edgeStart[i + 1] += graph.edgeStart[i];
    graph.neighbour.resize(graph.edgeStart[n]);
    graph.next.assign(graph.edgeStart.begin(), graph.edgeStart.end() - 1);
    const auto add = [&](const SpherePair& pair) {
        graph.neighbour[graph.next[pair.i]++] = pair.j;
        graph.neighbour[graph.next[pair.j]++] = pair.i;
    };
    if (order == PairOrder::Reversed) {
        std::for_each(pairs.rbegin(), pairs.rend(), add);
    } else {
        std::for_each(pairs.begin(), pairs.end(), add);
    }
    if (order != PairOrder::Shuffled && order != PairOrder::Colored) return;
    for (std::size_t i = 0; i < n; ++i) {
        std::sort(graph.neighbour.begin() + graph.edgeStart[i], graph.neighbour.begin() + graph.edgeStart[i + 1]);
    }
}

// graph.level by a breadth-first search from the spheres near a plane (`zero`).
void findLevels(const std::vector<std::uint8_t>& zero, ContactGraph& graph) {
    const std::size_t n = zero.size();
    std::vector<std::uint32_t>& queue = graph.queue;  // breadth-first order
    queue.resize(n + 1);  // each sphere once, and a slot written past the last
    graph.level.resize(n);
    // The queue is written without a branch on whether a sphere is met for the first time
    // (as good as random: a mispredicted branch per edge cost more than the search).
    std::size_t tail = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        graph.level[i] = zero[i] ? 0 : -1;
        queue[tail] = i;
        tail += zero[i];
    }
    for (std::size_t head = 0; head < tail; ++head) {
        const std::uint32_t i = queue[head];
        const std::int32_t above = graph.level[i] + 1;
        for (std::uint32_t e = graph.edgeStart[i]; e < graph.edgeStart[i + 1]; ++e) {
            const std::uint32_t j = graph.neighbour[e];
            const bool first = graph.level[j] < 0;
            graph.level[j] = first ? above : graph.level[j];
            queue[tail] = j;
            tail += first;
        }
    }
}

// graph.byLevel and levelStart: the spheres with a level, by level, then by number.
void orderByLevel(ContactGraph& graph) {
    const std::size_t n = graph.level.size();
    std::int32_t top = -1;
    for (const std::int32_t level : graph.level) top = std::max(top, level);
    const std::size_t levels = std::size_t(top + 1);
    graph.levelStart.assign(levels + 1, 0);
    for (const std::int32_t level : graph.level) {
        if (level >= 0) ++graph.levelStart[std::size_t(level) + 1];
    }
    for (std::size_t k = 0; k < levels; ++k) graph.levelStart[k + 1] += graph.levelStart[k];
    graph.next.assign(graph.levelStart.begin(), graph.levelStart.end() - 1);
    graph.byLevel.resize(graph.levelStart.back());
    for (std::uint32_t i = 0; i < n; ++i) {
        if (graph.level[i] >= 0) graph.byLevel[graph.next[std::size_t(graph.level[i])]++] = i;
    }
    graph.again.resize(graph.byLevel.size());
    graph.goesOn.resize(graph.byLevel.size());
    graph.byBelow.resize(graph.byLevel.size());
}

// Sphere i's neighbours, given by number, into its three runs (below, beside, the rest),
// each by number. Each neighbour is written to every run and kept where it belongs (no
// branch: which run a neighbour belongs to is as good as random).
void splitIntoRuns(ContactGraph& graph, std::uint32_t i) {
    const std::uint32_t first = graph.edgeStart[i], count = graph.edgeStart[i + 1] - first;
    std::uint32_t* list = graph.neighbour.data() + first;
    std::vector<std::uint32_t>& runs = graph.runs;  // scratch, with a slot written past the last
    runs.resize(count + 1);
    const std::int32_t level = graph.level[i];
    std::uint32_t w = 0, before = 0;
    for (std::uint32_t e = 0; e < count; ++e) {
        runs[w] = list[e];
        w += graph.level[list[e]] == level - 1;
    }
    const std::uint32_t below = w;
    for (std::uint32_t e = 0; e < count; ++e) {
        const bool beside = graph.level[list[e]] == level;
        runs[w] = list[e];
        w += beside;
        before += beside & (list[e] < i);
    }
    const std::uint32_t beside = w - below;
    for (std::uint32_t e = 0; e < count; ++e) {
        runs[w] = list[e];
        w += graph.level[list[e]] != level - 1 && graph.level[list[e]] != level;
    }
    std::copy(runs.begin(), runs.begin() + count, list);
    graph.belowCount[i] = below;
    graph.besideCount[i] = beside;
    graph.besideBefore[i] = before;
}

}  // namespace

bool findContactGraphAnew(const std::vector<SpherePair>& pairs, PairOrder order, const std::vector<std::uint8_t>& zero,
                          ContactGraph& graph) {
    const std::size_t n = zero.size();
    graph.belowCount.assign(n, 0);
    graph.besideCount.assign(n, 0);
    graph.besideBefore.assign(n, 0);
    graph.moved.assign(n, 0);
    // The pairs are the last solver step's: a state put back since (the timeline) may hold
    // fewer spheres. The app clears them then; no pair is read out of range either way.
    const auto inRange = [n](const SpherePair& pair) { return pair.i < n && pair.j < n; };
    const bool allInRange = std::all_of(pairs.begin(), pairs.end(), inRange);
    if (allInRange) {
        findEdges(n, pairs, order, graph);
    } else {
        graph.edgeStart.assign(n + 1, 0);
        graph.neighbour.clear();
    }
    findLevels(zero, graph);
    orderByLevel(graph);
    for (std::uint32_t i = 0; i < n; ++i) splitIntoRuns(graph, i);
    return allInRange;
}

namespace {

// The pairs in index order: (i, j) with i < j, by i, then by j.
bool inIndexOrderPairs(PairOrder order) { return order == PairOrder::Index || order == PairOrder::Reversed; }

// A pair as one number: index order is ascending order.
std::uint64_t key(const SpherePair& pair) { return std::uint64_t(pair.i) << 32 | pair.j; }

// graph.added and graph.removed: the pairs of `pairs` (in index order, read backwards when
// `Backwards`) not in graph.builtFrom, and those of builtFrom not in `pairs`. False (and
// the lists cut short) past `most` of them.
template <bool Backwards>
bool findChangedPairs(const std::vector<SpherePair>& pairs, ContactGraph& graph, std::size_t most) {
    graph.added.clear();
    graph.removed.clear();
    const std::vector<SpherePair>& old = graph.builtFrom;
    const std::size_t count = pairs.size();
    const auto at = [&](std::size_t k) -> const SpherePair& { return Backwards ? pairs[count - 1 - k] : pairs[k]; };
    std::size_t a = 0, b = 0;
    for (;;) {
        if (!Backwards) {  // most of them are the same: compared a block at a time first
            constexpr std::size_t kBlock = 64;
            while (a + kBlock <= count && b + kBlock <= old.size() &&
                   std::memcmp(&pairs[a], &old[b], kBlock * sizeof(SpherePair)) == 0) {
                a += kBlock, b += kBlock;
            }
        }
        while (a < count && b < old.size() && key(at(a)) == key(old[b])) ++a, ++b;
        if (a == count && b == old.size()) return true;
        if (graph.added.size() + graph.removed.size() >= most) return false;
        if (b == old.size() || (a < count && key(at(a)) < key(old[b]))) {
            graph.added.push_back(at(a++));
        } else {
            graph.removed.push_back(old[b++]);
        }
    }
}

// graph.edgeStart and neighbour with graph.added and removed applied: the spheres they
// name get their neighbours by number (and are added to graph.touched), the others keep
// theirs, in their runs.
void applyChangedPairs(ContactGraph& graph) {
    const std::size_t n = graph.level.size();
    std::vector<ContactGraph::Change>& changes = graph.changes;  // by sphere
    changes.clear();
    for (const SpherePair& pair : graph.added) changes.push_back({pair.i, pair.j, true}), changes.push_back({pair.j, pair.i, true});
    for (const SpherePair& pair : graph.removed) changes.push_back({pair.i, pair.j, false}), changes.push_back({pair.j, pair.i, false});
    std::sort(changes.begin(), changes.end(), [](const ContactGraph::Change& a, const ContactGraph::Change& b) {
        return a.sphere != b.sphere ? a.sphere < b.sphere : a.other < b.other;
    });
    std::vector<std::uint32_t>& start = graph.next;  // the new edgeStart
    std::vector<std::uint32_t>& list = graph.queue;  // the new neighbour
    start.resize(n + 1);
    list.clear();
    list.reserve(graph.neighbour.size() + graph.added.size() * 2);
    // The spheres [from, to) keep their neighbours, moved along by what the changes added.
    const auto keep = [&](std::uint32_t from, std::uint32_t to) {
        const std::uint32_t shift = std::uint32_t(list.size()) - graph.edgeStart[from];  // modulo 2^32
        for (std::uint32_t i = from; i < to; ++i) start[i] = graph.edgeStart[i] + shift;
        list.insert(list.end(), graph.neighbour.begin() + graph.edgeStart[from], graph.neighbour.begin() + graph.edgeStart[to]);
    };
    std::uint32_t kept = 0;  // the first sphere not yet placed
    for (std::size_t c = 0; c < changes.size();) {
        const std::uint32_t i = changes[c].sphere;
        keep(kept, i);
        graph.touched.push_back(i);
        start[i] = std::uint32_t(list.size());
        const std::size_t mine = list.size();
        for (; c < changes.size() && changes[c].sphere == i; ++c) {
            if (changes[c].added) list.push_back(changes[c].other);
        }
        for (std::uint32_t e = graph.edgeStart[i]; e < graph.edgeStart[i + 1]; ++e) {
            const std::uint32_t j = graph.neighbour[e];
            const SpherePair pair{std::min(i, j), std::max(i, j)};
            const bool removed = std::binary_search(graph.removed.begin(), graph.removed.end(), pair,
                                                    [](const SpherePair& a, const SpherePair& b) { return key(a) < key(b); });
            if (!removed) list.push_back(j);
        }
        std::sort(list.begin() + std::ptrdiff_t(mine), list.end());
        kept = i + 1;
    }
    keep(kept, std::uint32_t(n));
    start[n] = std::uint32_t(list.size());
    graph.edgeStart.swap(start);
    graph.neighbour.swap(list);
}

// Remembers sphere i's level before the repair (once) in graph.relevelled.
void noteLevel(ContactGraph& graph, std::uint32_t i) {
    if (graph.moved[i]) return;
    graph.moved[i] = 1;
    graph.relevelled.push_back({i, graph.level[i]});
}

// The levels after the changes (graph.added, removed, and the spheres whose nearness to a
// plane changed, `zero` being the new one), as a new search would find them. First every
// sphere that lost all it stood on (no neighbour one level down, and not near a plane) is
// unset, and so, in turn, the spheres one level up that stood only on it; then the levels
// are found again from the spheres around them, the new pairs and the new spheres near a
// plane, nearest first (a search by rounds of increasing level).
void repairLevels(ContactGraph& graph, const std::vector<std::uint8_t>& zero,
                  const std::vector<std::uint32_t>& zeroChanged) {
    std::vector<std::int32_t>& level = graph.level;
    const auto neighbours = [&](std::uint32_t i, const auto& visit) {
        for (std::uint32_t e = graph.edgeStart[i]; e < graph.edgeStart[i + 1]; ++e) visit(graph.neighbour[e]);
    };
    // Unset the spheres that stand on nothing any more.
    std::vector<std::uint32_t>& check = graph.queue;
    check.clear();
    for (const SpherePair& pair : graph.removed) check.push_back(pair.i), check.push_back(pair.j);
    check.insert(check.end(), zeroChanged.begin(), zeroChanged.end());
    std::vector<std::uint32_t>& unset = graph.unset;
    unset.clear();
    for (std::size_t head = 0; head < check.size(); ++head) {
        const std::uint32_t i = check[head];
        const std::int32_t was = level[i];
        if (was < 0 || was == kNoLevelYet) continue;
        bool stands = was == 0 && zero[i];
        if (was > 0) neighbours(i, [&](std::uint32_t j) { stands = stands || level[j] == was - 1; });
        if (stands) continue;
        noteLevel(graph, i);
        level[i] = kNoLevelYet;
        unset.push_back(i);
        neighbours(i, [&](std::uint32_t j) {
            if (level[j] == was + 1) check.push_back(j);
        });
    }
    // Find them again, round by round: round k sets the spheres of level k.
    std::vector<std::vector<std::uint32_t>>& rounds = graph.rounds;
    for (std::vector<std::uint32_t>& round : rounds) round.clear();
    const auto now = [&](std::uint32_t i) { return level[i] < 0 ? kNoLevelYet : level[i]; };
    const auto offer = [&](std::uint32_t i, std::int32_t k) {
        if (k >= now(i)) return;
        if (rounds.size() <= std::size_t(k)) rounds.resize(std::size_t(k) + 1);
        rounds[std::size_t(k)].push_back(i);
    };
    for (const std::uint32_t i : zeroChanged) {
        if (zero[i]) offer(i, 0);
    }
    for (const SpherePair& pair : graph.added) {
        if (now(pair.i) != kNoLevelYet) offer(pair.j, now(pair.i) + 1);
        if (now(pair.j) != kNoLevelYet) offer(pair.i, now(pair.j) + 1);
    }
    for (const std::uint32_t i : unset) {
        std::int32_t lowest = kNoLevelYet;
        neighbours(i, [&](std::uint32_t j) { lowest = std::min(lowest, now(j)); });
        if (zero[i]) offer(i, 0);
        if (lowest != kNoLevelYet) offer(i, lowest + 1);
    }
    for (std::size_t k = 0; k < rounds.size(); ++k) {
        for (std::size_t r = 0; r < rounds[k].size(); ++r) {  // the round may grow: not a range-for
            const std::uint32_t i = rounds[k][r];
            if (std::int32_t(k) >= now(i)) continue;
            noteLevel(graph, i);
            level[i] = std::int32_t(k);
            neighbours(i, [&](std::uint32_t j) { offer(j, std::int32_t(k) + 1); });
        }
    }
    for (const std::uint32_t i : unset) {
        if (level[i] == kNoLevelYet) level[i] = -1;  // reaches no plane now
    }
}

// After the repair: the runs found again of the spheres with changed neighbours
// (graph.touched), of those whose level changed, and of their neighbours; the repair's
// marks cleared. Returns whether any level changed.
bool splitChangedRuns(ContactGraph& graph) {
    std::vector<std::uint32_t>& split = graph.unset;  // free again after the repair
    split.assign(graph.touched.begin(), graph.touched.end());
    bool levelsChanged = false;
    for (const ContactGraph::Relevelled& r : graph.relevelled) {
        graph.moved[r.sphere] = 0;
        if (graph.level[r.sphere] == r.was) continue;
        levelsChanged = true;
        split.push_back(r.sphere);
        for (std::uint32_t e = graph.edgeStart[r.sphere]; e < graph.edgeStart[r.sphere + 1]; ++e) {
            split.push_back(graph.neighbour[e]);
        }
    }
    std::sort(split.begin(), split.end());
    split.erase(std::unique(split.begin(), split.end()), split.end());
    for (const std::uint32_t i : split) {
        // Back in order by number first: its runs are each by number, but not together.
        std::sort(graph.neighbour.begin() + graph.edgeStart[i], graph.neighbour.begin() + graph.edgeStart[i + 1]);
        splitIntoRuns(graph, i);
    }
    return levelsChanged;
}

// The graph of `pairs` updated from the last one; false where it cannot be (found anew).
bool update(const World& world, const std::vector<SpherePair>& pairs, PairOrder order, ContactGraph& graph,
            const std::vector<std::uint8_t>& zero) {
    const std::size_t n = world.size();
    if (!graph.builtInIndexOrder || !inIndexOrderPairs(order) || graph.level.size() != n || graph.levelStart.empty()) {
        return false;
    }
    const auto inRange = [n](const SpherePair& pair) { return pair.i < n && pair.j < n; };
    if (!std::all_of(pairs.begin(), pairs.end(), inRange)) return false;
    const std::size_t most = n / kMostChangedPairsPerSphere;
    const bool small = order == PairOrder::Reversed ? findChangedPairs<true>(pairs, graph, most)
                                                     : findChangedPairs<false>(pairs, graph, most);
    if (!small) return false;
    std::vector<std::uint32_t>& zeroChanged = graph.zeroChanged;
    zeroChanged.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (bool(zero[i]) != (graph.level[i] == 0)) zeroChanged.push_back(i);
    }
    if (graph.added.empty() && graph.removed.empty() && zeroChanged.empty()) return true;  // the same graph
    graph.touched.clear();
    if (!graph.added.empty() || !graph.removed.empty()) applyChangedPairs(graph);
    graph.relevelled.clear();
    repairLevels(graph, zero, zeroChanged);
    if (splitChangedRuns(graph)) orderByLevel(graph);
    return true;
}

}  // namespace

void keepContactGraph(const World& world, const std::vector<SpherePair>& pairs, PairOrder order, ContactGraph& graph,
                      const std::vector<double>* clearance) {
    const std::size_t n = world.size();
    std::vector<std::uint8_t>& zero = graph.zero;
    zero.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) zero[i] = levelZero(world, i, clearance);
    const bool updated = update(world, pairs, order, graph, zero);
    const bool inRange = updated || findContactGraphAnew(pairs, order, zero, graph);
    graph.builtInIndexOrder = inRange && inIndexOrderPairs(order);  // the next step's may update it
    if (updated && graph.added.empty() && graph.removed.empty()) return;  // builtFrom holds these pairs
    if (order == PairOrder::Reversed) {
        graph.builtFrom.assign(pairs.rbegin(), pairs.rend());
    } else {
        graph.builtFrom = pairs;
    }
}

void findContactGraph(const World& world, PairOrder order, ContactGraph& graph) {
    graph.builtInIndexOrder = false;  // found anew
    keepContactGraph(world, world.workspace.visitOrder, order, graph, nullptr);
}

}  // namespace physics
