#pragma once
// The stages the two methods are made of (second deck, "Summary with multiple
// particles"). Internal to the physics library.
#include <algorithm>
#include <atomic>
#include <chrono>
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

// The threads a stage may use: one while contacts are logged (the log is in pass order) or
// the impacts measured (World::answersOneAtATime).
inline int threadsFor(const World& world, const Params& params) {
    return world.answersOneAtATime() ? 1 : solverThreads(world, params);
}

// [0, n) cut into `tasks` ranges of nearly equal size: range t is [begin, end).
struct Range {
    std::uint32_t begin, end;
};
inline Range rangeOf(std::size_t n, int t, int tasks) {
    return {std::uint32_t(n * std::size_t(t) / std::size_t(tasks)),
            std::uint32_t(n * std::size_t(t + 1) / std::size_t(tasks))};
}

// task(t, stats) for each t in [0, tasks) on up to `threads` threads, each task counting
// into a StepStats of its own, the counts summed into `stats` afterwards (neighbours in
// one array would share cache lines, so each task counts in a local first).
template <class Task>
void runCountedTasks(int threads, int tasks, StepStats& stats, const Task& task) {
    std::vector<StepStats> taskStats(static_cast<std::size_t>(tasks));
    runTasks(threads, tasks, [&](int t) {
        StepStats local;
        task(t, local);
        taskStats[std::size_t(t)] = local;
    });
    for (const StepStats& s : taskStats) stats += s;
}

// Tasks per thread of forEachSphere: the threads take them as they come, so that
// spheres that cost more (in the position based wall stage, the few near a wall: the
// bottom of a pile, the lowest indices) are shared too.
constexpr int kSphereTasksPerThread = 8;

// visit(i, stats) on every sphere i once, in parallel (ranges of indices): for stages
// where each sphere changes only itself.
template <class Visit>
void forEachSphere(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const int threads = threadsFor(world, params);
    if (threads == 1) {
        for (std::uint32_t i = 0; i < world.size(); ++i) visit(i, stats);
        return;
    }
    const int tasks = kSphereTasksPerThread * threads;
    runCountedTasks(threads, tasks, stats, [&](int t, StepStats& local) {
        const Range range = rangeOf(world.size(), t, tasks);
        for (std::uint32_t i = range.begin; i < range.end; ++i) visit(i, local);
    });
}

// A share's thread tells the others how far it got after at most this many pairs.
constexpr std::uint32_t kLongestRun = 32;

// Whether the passes run on several threads, each its share of the pairs.
inline bool pairsSharedOut(const World& world, const Params& params) {
    const int threads = threadsFor(world, params);
    return threads > 1 && world.workspace.shareThreads == threads;
}

// The candidate pairs as the passes walk them: in pass order on one thread, shared out
// (Workspace::sharedPairs) on several.
inline const std::vector<SpherePair>& pairsAsVisited(const World& world, const Params& params) {
    return pairsSharedOut(world, params) ? world.workspace.sharedPairs : world.workspace.visitOrder;
}

// One pass over the pairs shared out between threads (Workspace::sharedPairs), with
// the result of the pass order: each share's pairs in order, each pair after the
// pairs of other shares that met its spheres before (Workspace::pairNeeds). A share
// is advanced by one thread at a time, normally its own; a thread that waits for a
// share that nobody is advancing (its thread has no core: other processes took them)
// advances it itself after a short spin, so that a wait costs at most the rest of
// one run of pairs, never a scheduler's time slice. No waits go round in a circle:
// the earliest pair not done in the pass order has every need met.
template <class Visit>
class SharedPass {
public:
    SharedPass(const World& world, int threads, const Visit& visit)
        : ws_(world.workspace), pairs_(world.workspace.sharedPairs.data()), visit_(visit),
          spin_(spinningPays(threads)), shares_(static_cast<std::size_t>(threads)) {}

    // Task `share`: returns once every pair of the share is done, by whichever thread.
    void finish(std::uint32_t share, StepStats& stats) {
        Seen seen{};
        awaitDone(share, size(share), seen, stats, true);
    }

private:
    // A share's word: 2 x (pairs done) + 1 while a thread advances it.
    struct alignas(64) Share {
        WatchedWord word;
    };
    static std::uint32_t doneIn(unsigned word) { return word >> 1; }
    static bool taken(unsigned word) { return (word & 1u) != 0; }

    // What a thread last read of each share's pairs done (they only grow).
    struct Seen {
        std::uint32_t done[kMostSolverThreads];
    };

    std::uint32_t size(std::uint32_t s) const { return ws_.shareStart[s + 1] - ws_.shareStart[s]; }
    bool met(const Workspace::PairNeed& need, const Seen& seen) const { return need.done <= seen.done[need.thread]; }
    bool ready(std::uint32_t k, const Seen& seen) const {
        return met(ws_.pairNeeds[2 * k], seen) && met(ws_.pairNeeds[2 * k + 1], seen);
    }

    // Returns once `count` pairs of share s are done. Advances the share when nobody
    // else does: at once if it is this thread's own, after a spin if not.
    void awaitDone(std::uint32_t s, std::uint32_t count, Seen& seen, StepStats& stats, bool own) {
        WatchedWord& word = shares_[s].word;
        for (unsigned w = word.load();; w = word.load()) {
            seen.done[s] = doneIn(w);
            if (doneIn(w) >= count) return;
            if (taken(w)) {
                word.awaitChange(w, spin_);
            } else if ((own || word.spinForChange(w, spin_) == w) && word.compareExchange(w, w | 1u)) {
                advance(s, count, seen, stats);
            }
        }
    }

    // The first need of pair k not met (refreshing `seen`), or none.
    const Workspace::PairNeed* unmetNeed(std::uint32_t k, Seen& seen) const {
        for (const Workspace::PairNeed* need : {&ws_.pairNeeds[2 * k], &ws_.pairNeeds[2 * k + 1]}) {
            if (met(*need, seen)) continue;
            seen.done[need->thread] = doneIn(shares_[need->thread].word.load());
            if (!met(*need, seen)) return need;
        }
        return nullptr;
    }

    // With share s taken: its pairs until `count` are done. Where a pair must wait for
    // another share, s is given back while that one is awaited (and advanced, if
    // nobody does), then taken again unless another thread has taken it meanwhile.
    void advance(std::uint32_t s, std::uint32_t count, Seen& seen, StepStats& stats) {
        WatchedWord& word = shares_[s].word;
        const std::uint32_t first = ws_.shareStart[s], last = ws_.shareStart[s + 1];
        std::uint32_t k = first + seen.done[s];
        while (k - first < count) {
            if (const Workspace::PairNeed* need = unmetNeed(k, seen)) {
                const unsigned givenBack = 2 * (k - first);
                word.store(givenBack);
                awaitDone(need->thread, need->done, seen, stats, false);
                if (!word.compareExchange(givenBack, givenBack | 1u)) return;
                continue;
            }
            // A run of pairs whose needs are met already, told done at its end.
            std::uint32_t end = k + 1;
            while (end < last && end - k < kLongestRun && ready(end, seen)) ++end;
            visit_(pairs_, k, end, stats);
            word.store(2 * (end - first) + 1);
            k = end;
        }
        word.store(2 * (k - first));
    }

    const Workspace& ws_;
    const SpherePair* pairs_;
    const Visit& visit_;
    const bool spin_;  // waits spin before they sleep (spinningPays)
    std::vector<Share> shares_;
};

// Pair order `colored` (colored_order.cpp). The pairs fall into groups: the pairs
// inside each block of kBlockSpheres spheres (runs of sphere numbers, or in big worlds
// places: colored_order.cpp; blocks share no sphere), then the border group, the pairs
// between blocks. Each group takes up to kGroupColors colours in
// which no two pairs share a sphere; a pair that finds none free joins the overflow,
// visited last, in index order, on one thread.
constexpr unsigned kGroupColors = 64;
// A block's spheres' data (about 75 bytes each in a pass) stays in a core's cache while
// its colours are visited, however many spheres the world holds.
constexpr std::uint32_t kBlockSpheres = 4096;

// Finds the blocks (Workspace::blockOfSphere) and sorts visitOrder (in index order) group
// by group, colour by colour (Workspace::colorStart), on `threads` threads: the same order
// on any number.
void colorPairs(World& world, int threads);

// The groups of the colouring: the blocks, then the border (the last).
inline std::uint32_t colorGroups(const Workspace& ws) {
    return std::uint32_t((ws.colorStart.size() - 2) / kGroupColors);
}
// Where group g's colour c lies in visitOrder.
inline Range colorRange(const Workspace& ws, std::uint32_t g, unsigned c) {
    const std::size_t key = std::size_t(g) * kGroupColors + c;
    return {ws.colorStart[key], ws.colorStart[key + 1]};
}
// Where the overflow lies in visitOrder: its pairs may share a sphere.
inline Range overflowRange(const Workspace& ws) {
    return {ws.colorStart[ws.colorStart.size() - 2], ws.colorStart.back()};
}

// The position based pair stage (B: velocity, if `respond`, and position) over pairs
// [first, last) of one colour, several side by side (colored_lanes.cpp), giving what the
// one-pair code gives, bit for bit; positionFactor is 1 (projection) or 1 + beta
// (reflection). Returns where it stopped: the caller does the rest (fewer pairs than
// lanes, or the overflow colour) one pair at a time. `width`: pairs side by side, one of
// laneWidths(), 0 the widest. Not while contacts are logged (World::recordContacts).
std::uint32_t separateColorInLanes(World& world, const Params& params, const SpherePair* pairs, std::uint32_t first,
                                   std::uint32_t last, StepStats& stats, int pass, double positionFactor,
                                   bool respond, int width = 0);
// The same over pairs [first, last) that share no sphere (a colour outside the overflow,
// a wavefront). With `staticOnly`, only the static contacts' velocities are answered (the
// shock sweep's contacts inside a level: impacts are the passes').
std::uint32_t separateSideBySide(World& world, const Params& params, const SpherePair* pairs, std::uint32_t first,
                                 std::uint32_t last, StepStats& stats, int pass, double positionFactor, bool respond,
                                 bool staticOnly = false, int width = 0);

// Slide 14's contact graph of `pairs` (candidate pairs visited in `order`) into `graph`,
// updated from the graph it holds where that is the last step's (contact_graph.cpp): the
// same as found anew. `clearance`: the position stages' wall clearances, if kept.
void keepContactGraph(const World& world, const std::vector<SpherePair>& pairs, PairOrder order, ContactGraph& graph,
                      const std::vector<double>* clearance);
// The contact graph found anew from `pairs`, `zero` (per sphere: near a plane) giving level
// 0 and the number of spheres. Returns whether every pair names spheres in range (else the
// graph has no edges).
bool findContactGraphAnew(const std::vector<SpherePair>& pairs, PairOrder order, const std::vector<std::uint8_t>& zero,
                          ContactGraph& graph);

// The shock sweep's (shock_propagation.cpp) spheres[0, count) of one level, each pushed off
// the frozen spheres below it in turn, positions only, several side by side: what its
// one-sphere code gives, bit for bit. With `lowerClearance`, each push lowers the
// sphere's wall clearance by its length. With `again`, again[k] <- whether spheres[k] was
// pushed off more than one frozen sphere, one of them deeper than `settled` times its
// radius. `width`: spheres side by side, 1 or one of laneWidths(), 0 the widest. With
// `params` (the sweep's first round), the static contacts are answered too, each before
// its push (respondToFrozenContact's answer, counted in `stats`; no contact log).
void pushOffFrozenSideBySide(World& world, const ContactGraph& graph, const std::uint32_t* spheres,
                             std::size_t count, bool lowerClearance, std::uint8_t* again = nullptr,
                             double settled = 0.0, int width = 0, const Params* params = nullptr,
                             StepStats* stats = nullptr);

// The lane widths this CPU runs, ascending: 2, and 4 with AVX2, 8 with AVX-512.
std::vector<int> laneWidths();

// A colour with fewer pairs than this is visited on one thread: handing it out would cost
// more than it saves (a run of the team costs a few microseconds). Measured when the
// wavefronts too were handed out one by one (the 16k pile's hold about 500 pairs): at
// 2048, its index order gained 1.16x from a second thread, at 512 1.28-1.36x (the colored
// order the same at both; 256 did no better).
constexpr std::uint32_t kColorShareMin = 512;
// Tasks per thread of a colour, taken as they come, so that a thread slowed by another
// process leaves its part to the others.
constexpr int kColorTasksPerThread = 4;

// visit(pairs, first, last, stats) over the pairs [r.begin, r.end), which share no sphere:
// on the caller, or cut into ranges that threads take as they come.
template <class Visit>
void visitSideBySide(int threads, StepStats& stats, const SpherePair* pairs, Range r, const Visit& visit) {
    const std::uint32_t size = r.end - r.begin;
    if (threads == 1 || size < kColorShareMin) {
        if (size > 0) visit(pairs, r.begin, r.end, stats);
        return;
    }
    const int tasks = kColorTasksPerThread * threads;
    runCountedTasks(threads, tasks, stats, [&](int t, StepStats& s) {
        const Range part = rangeOf(size, t, tasks);
        visit(pairs, r.begin + part.begin, r.begin + part.end, s);
    });
}

// The lecture's pair orders (index, reversed, shuffled) wavefront by wavefront
// (wavefronts.cpp): a pair's wavefront is the length of the longest chain of earlier
// pairs, in pass order, that leads to it, each sharing a sphere with the next; no two
// pairs of a wavefront share a sphere. Visited wavefront after wavefront, every sphere
// meets its pairs in pass order, and pairs that share no sphere do not change each other:
// the pass order's result, bit for bit, with a wavefront's pairs several side by side and
// shared between threads. The pile has 30 to 140 wavefronts from 1k to 64k spheres.
//
// Whether the position based pair stage runs by wavefronts: the lecture's orders, the
// sequential solvers (the global ones answer velocities by their own order), no contact
// log, and a CPU with 4 lanes or more (2 lanes cost what they save).
bool passesByWavefronts(const World& world, const Params& params);
// Workspace::wavefrontOrder and wavefrontStart from visitOrder, for `threads` threads (on
// several, with Workspace::wavefrontStrips).
void findWavefronts(World& world, int threads);
// pairs[0, count) (in pass order) into `order`, wavefront by wavefront, each in pass order:
// wavefront w is order[start[w], start[w + 1]). `next`: per sphere, all 0 on entry and on
// return; `ofPair`: scratch. With `strips` (its ofSphere and count given), a wavefront's
// pairs go by the strip of their first sphere, each strip's in pass order, and the strips'
// start and span are found.
void sortIntoWavefronts(const SpherePair* pairs, std::size_t count, std::vector<std::uint32_t>& next,
                        std::vector<std::uint32_t>& ofPair, std::vector<std::uint32_t>& start,
                        std::vector<SpherePair>& order, Workspace::WavefrontStrips* strips = nullptr);
// The colored order on several threads: the border group's pairs (between blocks, colour
// after colour) into Workspace::wavefrontOrder and wavefrontStart by wavefronts and strips,
// as findWavefronts does a lecture's order; each sphere meets its pairs in the same order
// as colour after colour: the same result. With blocks of sphere numbers, a landed pile's
// border holds many pairs (39 % at 10k; 82 % at 64k before its blocks were places, 8 %
// after); shared out colour by colour in ranges of pairs, it handed spheres between the
// threads. The blocks keep their own pass (a block's data stays in a core's cache while its
// colours are visited; by wavefronts too, two threads over one at 64k gained nothing).
// Sets Workspace::borderByWavefronts, which findOrderedPairs clears.
void findBorderWavefronts(World& world, int threads);

// A pass by wavefronts on several threads with no barrier between wavefronts. Each thread
// has a share: a run of strips across the pile (Workspace::WavefrontStrips) holding about
// as many of the pass's pairs as the others' runs. It goes through the wavefronts in its
// strips. Two pairs that share a sphere have their first spheres at most 2 x span strips
// apart (span: the most strips between a pair's two spheres). So before wavefront w a
// share waits only for its neighbours (the shares whose strips come that near) to have
// done wavefront w - 1: every sphere meets its pairs in pass order, the result of one
// thread bit for bit. (Waiting only for the strips of wavefront w - 1 near it, visited
// first, or only for the pairs that met its spheres last, made no step measurably faster
// at 16k or 64k: src/bench/README.md.)
// As in SharedPass, one thread at a time advances a share, normally its own; a thread
// that waits for a share that nobody advances (its thread has no core) advances it itself
// after a short spin. No waits go round in a circle: a wavefront needs only earlier ones,
// so the share with the fewest wavefronts done has what it needs.
template <class Visit>
class StripPass {
  public:
    StripPass(const World& world, int threads, const Visit& visit)
        : strips_(world.workspace.wavefrontStrips), pairs_(world.workspace.wavefrontOrder.data()), visit_(visit),
          wavefronts_(std::uint32_t(std::max<std::size_t>(world.workspace.wavefrontStart.size(), 1) - 1)),
          spin_(spinningPays(threads)), shares_(static_cast<std::size_t>(threads)) {
        cutIntoShares();
        findNeighbours();
    }

    // Task `share`: returns once every wavefront of the share is done, by whichever thread.
    void finish(std::uint32_t share, StepStats& stats) {
        Seen seen{};
        awaitDone(share, wavefronts_, seen, stats, true);
    }

    // Share s's strips, [first, end).
    Range stripsOf(std::uint32_t s) const { return {shares_[s].firstStrip, shares_[s].endStrip}; }
    // Bit u: share u's pairs may share a sphere with share s's.
    std::uint64_t neighboursOf(std::uint32_t s) const { return shares_[s].neighbours; }

  private:
    struct alignas(64) Share {
        WatchedWord word;  // 2 x (wavefronts done) + 1 while a thread advances it
        std::uint32_t firstStrip = 0, endStrip = 0;
        std::uint64_t neighbours = 0;
    };
    // What a thread last read of each share's wavefronts done (they only grow).
    struct Seen {
        std::uint32_t done[kMostSolverThreads];
    };

    // Each share's run of strips: the strips in order, cut where the pairs before reach
    // each share's part of them (a strip goes to the share that holds its middle pair).
    void cutIntoShares() {
        const std::uint32_t count = strips_.count;
        std::uint64_t perStrip[256] = {};
        for (std::uint32_t w = 0; w < wavefronts_; ++w) {
            for (std::uint32_t strip = 0; strip < count; ++strip) {
                const std::size_t key = std::size_t(w) * count + strip;
                perStrip[strip] += strips_.start[key + 1] - strips_.start[key];
            }
        }
        const double all = wavefronts_ > 0 ? double(strips_.start[std::size_t(wavefronts_) * count]) : 0.0;
        const std::uint32_t shares = std::uint32_t(shares_.size());
        std::uint32_t strip = 0;
        double before = 0.0;  // pairs in the strips taken
        for (std::uint32_t s = 0; s < shares; ++s) {
            shares_[s].firstStrip = strip;
            const double end = all * (s + 1) / shares;
            while (strip < count && (s + 1 == shares || before + 0.5 * double(perStrip[strip]) < end)) {
                before += double(perStrip[strip++]);
            }
            shares_[s].endStrip = strip;
        }
    }

    // Shares whose strips come within 2 x span of each other are neighbours.
    void findNeighbours() {
        const std::uint32_t reach = 2 * strips_.span;
        for (std::uint32_t s = 0; s < shares_.size(); ++s) {
            for (std::uint32_t u = 0; u < shares_.size(); ++u) {
                const Share &a = shares_[s], &b = shares_[u];
                if (u == s || a.firstStrip == a.endStrip || b.firstStrip == b.endStrip) continue;
                // Strips between the nearest of each (the runs are disjoint).
                const std::uint32_t gap = b.firstStrip >= a.endStrip ? b.firstStrip + 1 - a.endStrip
                                                                     : a.firstStrip + 1 - b.endStrip;
                if (gap <= reach) shares_[s].neighbours |= std::uint64_t(1) << u;
            }
        }
    }

    // Share s's pairs of wavefront w.
    Range pairsOf(std::uint32_t s, std::uint32_t w) const {
        const std::size_t key = std::size_t(w) * strips_.count;
        return {strips_.start[key + shares_[s].firstStrip], strips_.start[key + shares_[s].endStrip]};
    }

    // Returns once `count` wavefronts of share s are done. Advances the share when nobody
    // else does: at once if it is this thread's own, after a spin if not.
    void awaitDone(std::uint32_t s, std::uint32_t count, Seen& seen, StepStats& stats, bool own) {
        WatchedWord& word = shares_[s].word;
        for (unsigned w = word.load();; w = word.load()) {
            seen.done[s] = w >> 1;
            if (seen.done[s] >= count) return;
            if ((w & 1u) != 0) {
                word.awaitChange(w, spin_);
            } else if ((own || word.spinForChange(w, spin_) == w) && word.compareExchange(w, w | 1u)) {
                advance(s, count, seen, stats);
            }
        }
    }

    // A neighbour of share s that has not done `w` wavefronts (refreshing `seen`), if any
    // (else count is 0).
    struct Need {
        std::uint32_t share = 0, count = 0;
    };
    Need unmetNeed(std::uint32_t s, std::uint32_t w, Seen& seen) const {
        for (std::uint64_t left = shares_[s].neighbours; left != 0; left &= left - 1) {
            const std::uint32_t u = std::uint32_t(__builtin_ctzll(left));
            if (seen.done[u] >= w) continue;
            seen.done[u] = shares_[u].word.load() >> 1;
            if (seen.done[u] < w) return {u, w};
        }
        return {};
    }

    // With share s taken: its wavefronts until `count` are done. Where a wavefront must
    // wait for a neighbour, s is given back while that one is awaited (and advanced, if
    // nobody does), then taken again unless another thread has taken it meanwhile.
    void advance(std::uint32_t s, std::uint32_t count, Seen& seen, StepStats& stats) {
        WatchedWord& word = shares_[s].word;
        std::uint32_t w = seen.done[s];
        while (w < count) {
            const Range pairs = pairsOf(s, w);
            if (pairs.end > pairs.begin) {  // a share with no pairs in w needs nobody
                const Need need = unmetNeed(s, w, seen);
                if (need.count > 0) {
                    const unsigned givenBack = 2 * w;
                    word.store(givenBack);
                    awaitDone(need.share, need.count, seen, stats, false);
                    if (!word.compareExchange(givenBack, givenBack | 1u)) return;
                    continue;
                }
                visit_(pairs_, pairs.begin, pairs.end, stats);
            }
            ++w;
            word.store(2 * w + 1);
        }
        word.store(2 * w);
    }

    const Workspace::WavefrontStrips& strips_;
    const SpherePair* pairs_;
    const Visit& visit_;
    const std::uint32_t wavefronts_;
    const bool spin_;  // waits spin before they sleep (spinningPays)
    std::vector<Share> shares_;
};

// A StripPass over Workspace::wavefrontOrder, each thread its share.
template <class Visit>
void runStripPass(const World& world, int threads, StepStats& stats, const Visit& visit) {
    StripPass<Visit> pass(world, threads, visit);
    runCountedTasks(threads, threads, stats, [&](int share, StepStats& local) { pass.finish(std::uint32_t(share), local); });
}

// visit(pairs, first, last, stats) over the wavefronts in order, each wavefront's pairs
// side by side: on one thread one wavefront after the other, on several a StripPass.
template <class Visit>
void forEachWavefront(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const Workspace& ws = world.workspace;
    const int threads = threadsFor(world, params);
    if (threads > 1 && ws.wavefrontStrips.threads == threads) {
        runStripPass(world, threads, stats, visit);
        return;
    }
    for (std::size_t w = 0; w + 1 < ws.wavefrontStart.size(); ++w) {
        const std::uint32_t first = ws.wavefrontStart[w], last = ws.wavefrontStart[w + 1];
        if (last > first) visit(ws.wavefrontOrder.data(), first, last, stats);
    }
}

// The colored order's pass: the blocks (threads take whole blocks as they come; inside
// one, colour after colour), then the border colour after colour, then the overflow on one
// thread. Where the position stages found the border's wavefronts (findBorderWavefronts),
// the border goes by them, a StripPass; else each colour's pairs are cut into ranges that
// threads take as they come. The same result on any thread count.
template <class Visit>
void forEachColor(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const Workspace& ws = world.workspace;
    const int threads = threadsFor(world, params);
    const SpherePair* pairs = ws.visitOrder.data();
    const std::uint32_t blocks = colorGroups(ws) - 1;
    const auto visitBlock = [&](std::uint32_t g, StepStats& s) {
        for (unsigned c = 0; c < kGroupColors; ++c) {
            const Range r = colorRange(ws, g, c);
            if (r.end > r.begin) visit(pairs, r.begin, r.end, s);
        }
    };
    if (threads == 1 || blocks < 2) {
        for (std::uint32_t g = 0; g < blocks; ++g) visitBlock(g, stats);
    } else {
        runCountedTasks(threads, int(blocks), stats, [&](int g, StepStats& s) { visitBlock(std::uint32_t(g), s); });
    }
    if (threads > 1 && ws.borderByWavefronts && ws.wavefrontStrips.threads == threads) {
        runStripPass(world, threads, stats, visit);
    } else {
        for (unsigned c = 0; c < kGroupColors; ++c) visitSideBySide(threads, stats, pairs, colorRange(ws, blocks, c), visit);
    }
    const Range overflow = overflowRange(ws);
    if (overflow.end > overflow.begin) visit(pairs, overflow.begin, overflow.end, stats);
}

// visit(pairs, first, last, stats) on ranges [first, last) of pairs = pairsAsVisited()
// that together give the result of visiting them in pass order: on one thread the pass
// order itself; on several, SharedPass (or, in the colored order, forEachColor).
template <class Visit>
void forEachPairInPassOrder(World& world, const Params& params, StepStats& stats, const Visit& visit) {
    const Workspace& ws = world.workspace;
    const int threads = threadsFor(world, params);
    if (params.order == PairOrder::Colored) {
        forEachColor(world, params, stats, visit);
        return;
    }
    if (!pairsSharedOut(world, params)) {
        visit(ws.visitOrder.data(), 0u, std::uint32_t(ws.visitOrder.size()), stats);
        return;
    }
    SharedPass<Visit> pass(world, threads, visit);
    runCountedTasks(threads, threads, stats,
                    [&](int share, StepStats& local) { pass.finish(std::uint32_t(share), local); });
}

// Adds the wall time (s) from its construction to the end of its scope to `seconds`:
// the stages' profile in StepStats.
class StageTimer {
  public:
    explicit StageTimer(double& seconds) : seconds_(seconds) {}
    ~StageTimer() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

  private:
    double& seconds_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Field forces, semi-implicit Euler (slide 2): v <- v + h g, then p <- p + h v.
void integrateVelocity(World& world, const Params& params, double h);
void integratePosition(World& world, const Params& params, double h);

// out <- the pairs of spheres within the margin of touching now, in index order: from
// the cached pairs while no sphere has moved past their skin, else from a new search.
// Timed as StepStats::broadPhaseSeconds.
void findPairsWithinReach(World& world, const Params& params, StepStats& stats, std::vector<SpherePair>& out);

// Fills world.workspace.visitOrder with the candidate pairs in the order the passes
// visit them (index, reversed, or shuffled with the world's seed and step count), and
// with several threads shares them out. Timed as StepStats::broadPhaseSeconds.
void findOrderedPairs(World& world, const Params& params, StepStats& stats);

// Narrow phase, slide 9: the pair touches when |p1 - p2| <= r1 + r2.
// (Inline, as the next one: they run for every candidate in every pass.)
inline bool touching(const World& world, const SpherePair& pair, SphereContact& contact) {
    const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];
    const double reach = world.radius[pair.i] + world.radius[pair.j];
    const double distanceSquared = glm::dot(delta, delta);
    if (distanceSquared > reach * reach) return false;
    const double distance = std::sqrt(distanceSquared);
    // Coincident centres have no direction: push them apart along z.
    contact.u = distance > 0.0 ? delta * (1.0 / distance) : glm::dvec3(0.0, 0.0, 1.0);
    contact.depth = reach - distance;
    return true;
}

// Slide 3: the sphere touches the plane when (p - a).n <= r.
inline bool touching(const glm::dvec3& p, double r, const Plane& plane) {
    return glm::dot(p - plane.point, plane.normal) <= r;
}

// visit(k, face) for each plane k that sphere i touches, in plane order, with face =
// faceFor(plane k, the centre as it is then): visit may move the sphere. Plain planes
// are tested where they lie, without a copy (this runs for every sphere and plane in
// every pass, and most spheres touch no wall).
template <class Visit>
inline void forEachTouchedPlane(const World& world, std::uint32_t i, const Visit& visit) {
    const double r = world.radius[i];  // m
    for (std::size_t k = 0; k < world.planes.size(); ++k) {
        const Plane& plane = world.planes[k];
        if (plane.thickness > 0.0) {
            const Plane face = faceFor(plane, world.position[i]);
            if (touching(world.position[i], r, face)) visit(k, face);
        } else if (touching(world.position[i], r, plane)) {
            visit(k, plane);
        }
    }
}

// Whether sphere i is within `margin` (m) of touching a plane's face (slide 3 with r +
// margin): the contact graph's level 0, and the impact measurement's walls.
inline bool nearAPlane(const World& world, std::uint32_t i, double margin) {
    const double reach = world.radius[i] + margin;  // m
    for (const Plane& plane : world.planes) {
        const bool near = plane.thickness > 0.0 ? touching(world.position[i], reach, faceFor(plane, world.position[i]))
                                                : touching(world.position[i], reach, plane);
        if (near) return true;
    }
    return false;
}

// m: the largest |a.x| + |a.y| + |a.z| of the planes' points, at least 1 m: with the
// sphere's own, the scale of the rounding in wallClearance().
inline double planeScale(const World& world) {
    double scale = 1.0;  // m
    for (const Plane& plane : world.planes) {
        scale = std::max(scale, std::abs(plane.point.x) + std::abs(plane.point.y) + std::abs(plane.point.z));
    }
    return scale;
}

// m: a lower bound on the gap between sphere i's surface and every plane's face, less
// a slack for rounding; at or below 0, the sphere may touch a plane. The position based
// method keeps it per sphere (Workspace::wallClearance) to pass by, in its wall stage,
// the spheres that touch no wall: most of them, in a pile. A move of length L lowers a
// gap by at most L because the normals are unit vectors (Plane); `scaleOfPlanes` is
// planeScale(world).
inline double wallClearance(const World& world, std::uint32_t i, double scaleOfPlanes) {
    // Relative to the coordinates: far above the rounding of the distances and of the
    // moves since they were found (about 1e-16 of the coordinates each).
    constexpr double kRoundingSlack = 1e-9;
    const glm::dvec3& p = world.position[i];  // m
    double gap = INFINITY;                    // m
    for (const Plane& plane : world.planes) {
        const double side = glm::dot(p - plane.point, plane.normal);  // m, signed
        gap = std::min(gap, plane.thickness > 0.0 ? std::abs(side) - 0.5 * plane.thickness : side);
    }
    const double scale = scaleOfPlanes + std::abs(p.x) + std::abs(p.y) + std::abs(p.z);  // m
    return gap - world.radius[i] - kRoundingSlack * scale;
}

// Workspace::wallClearance <- wallClearance() of every sphere.
void findWallClearances(World& world, const Params& params);

// The velocity response to one contact (collision_response.h), recorded in the
// spheres' contact state, counted in the stats (contacts on pass 0 only) and, when
// world.recordContacts is on, logged as a ContactEvent.
Response respondToContact(World& world, const SpherePair& pair, const SphereContact& contact,
                          const Params& params, StepStats& stats, int pass);
// `face` is faceFor(world.planes[planeIndex], the sphere's centre).
Response respondToContact(World& world, std::uint32_t i, std::size_t planeIndex, const Plane& face,
                          const Params& params, StepStats& stats, int pass);

// Sphere i's static contact with the frozen sphere `frozen` of a lower level (shock
// propagation; contact.u from it to i): respondToFrozenSphere, recorded in i's contact
// state and counted; logged with the frozen sphere's mass infinite.
Response respondToFrozenContact(World& world, std::uint32_t i, std::uint32_t frozen, const SphereContact& contact,
                                const Params& params, StepStats& stats);

// For methods whose positions stay put while the passes run (velocity based, response
// only): finds the pairs that touch and the walls each sphere touches once per step,
// into the workspace, for respondToAllContacts and the velocity method's cancelling.
// Call after findOrderedPairs.
void findContacts(World& world, const Params& params);

// Velocity response to every touching pair (in pass order), then every wall contact,
// as findContacts found them.
void respondToAllContacts(World& world, const Params& params, StepStats& stats, int pass);

// The same contacts answered simultaneously (slide 14's pairwise Jacobi): every response
// from the velocities at the start of the pass, the changes summed per sphere and applied
// together (simultaneous.cpp).
void respondSimultaneously(World& world, const Params& params, StepStats& stats, int pass);

// Slide 14's global approach: every contact findContacts found in one complementarity
// problem, solved by projected Gauss-Seidel (lcp.cpp).
void solveContactsTogether(World& world, const Params& params, StepStats& stats, int pass);

// Smith et al.'s generalized reflections: the contacts that approach, solved together
// (elastic, blended with inelastic for beta < 1), again until none approaches
// (generalized_reflections.cpp).
void reflectGeneralized(World& world, const Params& params, StepStats& stats, int pass);

// The velocity stage of one pass with the chosen solver, over the contacts findContacts
// found: in turn (sequential, until-converged), from the same velocities (simultaneous)
// or together (lcp, generalized reflections).
inline void respondWithSolver(World& world, const Params& params, StepStats& stats, int pass) {
    switch (params.solver) {
        case Solver::Simultaneous: respondSimultaneously(world, params, stats, pass); return;
        case Solver::Lcp: solveContactsTogether(world, params, stats, pass); return;
        case Solver::GeneralizedReflections: reflectGeneralized(world, params, stats, pass); return;
        default: respondToAllContacts(world, params, stats, pass); return;
    }
}

// The global solvers' (lcp, generalized reflections) positivity at the step's end, after
// the last velocity solve and the shock sweep: alpha and mu, applied after each normal
// solve, and the sweep's answers against frozen spheres leave contacts approaching (the
// 1k pile under the position method: 0.85 m/s; 22_shock_pyramid under lcp: 1.1e-3 m/s).
// complementarity.h's restorePositivity answers them, normal impulses only; `moved`: the
// positions moved since findContacts last ran (the sweep's projection). Other solvers:
// nothing.
void endWithPositivity(World& world, const Params& params, StepStats& stats, bool moved);

// Whether a touching contact of the current positions still approaches faster than
// kConvergedApproachSpeed (finds the contacts again, as findContacts).
bool contactsStillApproach(World& world, const Params& params);

// Slide 14, "multiple collisions": runs pass(k) for k = 0, 1, ... K - 1, or with the
// until-converged solver only until no touching contact approaches (K the cap: a step
// that reaches it is counted). Counts the passes run.
// With World::measureImpacts, the velocities and touching contacts before the velocity
// stage (impact_properties.cpp), and what the stage did to them, into stats.impacts. A
// no-op without it.
void beginMeasuringImpacts(World& world, const Params& params);
void endMeasuringImpacts(World& world, StepStats& stats);
// Between the two: a response changed the velocity of sphere i and of `other` (a sphere; < 0
// a plane, or nothing else moved): their clusters are one for the measures (a plane's: not
// free). Every response calls it while World::measureImpacts (one at a time: answersOneAtATime).
void noteAnswered(World& world, std::uint32_t i, std::int64_t other);

template <class Pass>
void runPasses(World& world, const Params& params, StepStats& stats, const Pass& pass) {
    const bool untilConverged = params.solver == Solver::UntilConverged;
    int run = 0;
    bool converged = false;
    while (run < params.passes && !converged) {
        pass(run++);
        converged = untilConverged && !contactsStillApproach(world, params);
    }
    stats.passesUsed += std::uint64_t(run);
    stats.passCapHits += untilConverged && !converged;
}

// Slide 7's answers to a penetration found after the fact that move the sphere: (1)
// project it on the constraint (out by d), (2) approximate the correct position by
// reflection (out by (1 + beta) d, where it would be had it bounced at the instant
// of contact and gone on at beta times its normal speed).
enum class PositionResponse { Projection, Reflection };

// m: how far the position response moves out of an overlap of depth d (m).
inline double positionResponseDistance(PositionResponse response, double d, const Params& params) {
    return response == PositionResponse::Projection ? d : (1.0 + params.beta) * d;
}

// Slide 14's shock propagation (shock_propagation.cpp), with Params::shock on: after the
// passes, the contact graph's levels swept from the planes up, each frozen once answered.
// `moves`: the position stage too (projection); else velocities only.
void propagateShock(World& world, const Params& params, StepStats& stats, bool moves);

// The position based method's stages (position_based.cpp) with either position response.
StepStats stepWithPositionResponse(World& world, const Params& params, double h,
                                   PositionResponse response);

}  // namespace physics
