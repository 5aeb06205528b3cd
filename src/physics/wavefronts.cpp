// The lecture's pair orders (index, reversed, shuffled) run wavefront by wavefront, so
// that the position based pair stage answers several pairs side by side and on several
// threads, with the pass order's result bit for bit (solver_stages.h's forEachWavefront).
// A pair's wavefront is the number of pairs before it, in pass order, in the longest run
// of pairs that each share a sphere with the next: one more than the latest wavefront of
// its two spheres' earlier pairs.
#include <algorithm>
#include <cmath>

#include "physics/solver_stages.h"

namespace physics {

bool passesByWavefronts(const World& world, const Params& params) {
    static const bool wideLanes = laneWidths().back() >= 4;
    const bool positionStage = params.method == Method::PositionBased || params.method == Method::Reflection;
    return wideLanes && positionStage && params.order != PairOrder::Colored && !solvesTogether(params.solver) &&
           !world.answersOneAtATime();
}

namespace {

// Numbers each pair's wavefront into ofPair; returns how many wavefronts there are.
std::uint32_t numberWavefronts(const SpherePair* pairs, std::size_t count, std::vector<std::uint32_t>& next,
                               std::vector<std::uint32_t>& ofPair) {
    std::uint32_t wavefronts = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t w = std::max(next[pairs[k].i], next[pairs[k].j]);
        ofPair[k] = w;
        next[pairs[k].i] = next[pairs[k].j] = w + 1;
        wavefronts = std::max(wavefronts, w + 1);
    }
    return wavefronts;
}

// The same with strips: ofPair gets each pair's key (wavefront x count + the strip of its
// first sphere), and `strips` its span.
std::uint32_t numberWavefrontsByStrips(const SpherePair* pairs, std::size_t count, std::vector<std::uint32_t>& next,
                                       std::vector<std::uint32_t>& ofPair, Workspace::WavefrontStrips& strips) {
    const std::uint8_t* strip = strips.ofSphere.data();
    std::uint32_t wavefronts = 0;
    int span = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = pairs[k].i, j = pairs[k].j;
        const std::uint32_t w = std::max(next[i], next[j]);
        ofPair[k] = w * strips.count + strip[i];
        span = std::max(span, std::abs(int(strip[i]) - int(strip[j])));
        next[i] = next[j] = w + 1;
        wavefronts = std::max(wavefronts, w + 1);
    }
    strips.span = std::uint32_t(span);
    return wavefronts;
}

}  // namespace

void sortIntoWavefronts(const SpherePair* pairs, std::size_t pairCount, std::vector<std::uint32_t>& next,
                        std::vector<std::uint32_t>& ofPair, std::vector<std::uint32_t>& start,
                        std::vector<SpherePair>& order, Workspace::WavefrontStrips* strips) {
    ofPair.resize(pairCount);
    const std::uint32_t wavefronts = strips ? numberWavefrontsByStrips(pairs, pairCount, next, ofPair, *strips)
                                            : numberWavefronts(pairs, pairCount, next, ofPair);
    for (std::size_t k = 0; k < pairCount; ++k) next[pairs[k].i] = next[pairs[k].j] = 0;
    // Placed by key (wavefront, or wavefront x strips + strip), each in pass order (a
    // counting sort).
    const std::uint32_t count = strips ? strips->count : 1;
    const std::uint32_t keys = wavefronts * count;
    start.assign(std::size_t(keys) + 1, 0);
    for (std::size_t k = 0; k < pairCount; ++k) ++start[ofPair[k] + 1];
    for (std::uint32_t key = 0; key < keys; ++key) start[key + 1] += start[key];
    order.resize(pairCount);
    for (std::size_t k = 0; k < pairCount; ++k) order[start[ofPair[k]]++] = pairs[k];
    // start[key] is now where key + 1 starts.
    if (strips) {
        strips->start.resize(std::size_t(keys) + 1);
        strips->start[0] = 0;
        std::copy(start.begin(), start.begin() + keys, strips->start.begin() + 1);
    }
    // Wavefront w starts where key w x count - 1 ends. (Each read before it is written over:
    // downwards with one strip, upwards with more.)
    if (count == 1) {
        for (std::uint32_t w = wavefronts; w > 0; --w) start[w] = start[w - 1];
    } else {
        for (std::uint32_t w = 1; w <= wavefronts; ++w) start[w] = start[std::size_t(w) * count - 1];
    }
    start[0] = 0;
    start.resize(std::size_t(wavefronts) + 1);
}

namespace {

// Strips across the pile, for the wavefronts on several threads (findWavefronts): this
// many for each thread (16 strips on two threads; 64 did no better), at most 256.
constexpr std::uint32_t kStripsPerThread = 8;

// What splitting the spheres at `middle` (m) along `axis` between two threads costs: the
// share of cache lines of contact states (64 spheres numbered one after another) that hold
// spheres of both sides, which both threads would write; plus how unevenly the sides split
// a run of numbers, as a wavefront is one (its pairs in a band of numbers). Sampled: one
// line in 8.
double splitCost(const World& world, int axis, double middle) {
    constexpr std::size_t kLine = 64, kSampled = 8;
    const std::size_t n = world.size(), run = std::max(kLine * kSampled, n / 16);
    double mixed = 0.0, uneven = 0.0;
    int lines = 0, runs = 0;
    for (std::size_t start = 0; start < n; start += run) {
        int below = 0, counted = 0;
        for (std::size_t line = start; line < std::min(start + run, n); line += kLine * kSampled) {
            int lineBelow = 0, lineCount = 0;
            for (std::size_t i = line; i < std::min(line + kLine, n); ++i, ++lineCount) {
                lineBelow += world.position[i][axis] < middle;
            }
            mixed += lineBelow > 0 && lineBelow < lineCount;
            ++lines;
            below += lineBelow;
            counted += lineCount;
        }
        uneven += std::abs(2.0 * below - counted) / counted;
        ++runs;
    }
    return mixed / lines + uneven / runs;
}

// Per sphere, its strip of `count` equal ones across the axis that splitCost finds
// cheapest. The pile is numbered along x, then y, then z: across x each row of it (one
// line of contact states) is on both sides, across z a wavefront on one. Two threads over
// one (64k, index order, landing, same state): 1.46 across x, 1.25 across z, 1.64-1.72
// across y, which splitCost takes.
void findStrips(const World& world, std::uint32_t count, std::vector<std::uint8_t>& strip) {
    strip.resize(world.size());
    if (world.size() == 0) return;
    glm::dvec3 low = world.position[0], high = low;  // m
    for (const glm::dvec3& p : world.position) low = glm::min(low, p), high = glm::max(high, p);
    const glm::dvec3 extent = high - low;  // m
    const glm::dvec3 middle = 0.5 * (low + high);  // m
    int axis = 0;
    double least = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const double cost = splitCost(world, a, middle[a]);
        if (cost < least) axis = a, least = cost;
    }
    const double perStrip = count / std::max(extent[axis], 1e-300);  // 1/m
    for (std::size_t i = 0; i < world.size(); ++i) {
        const double at = (world.position[i][axis] - low[axis]) * perStrip;  // NaN: strip 0
        strip[i] = std::uint8_t(at > 0.0 ? std::min<double>(at, count - 1) : 0.0);
    }
}

}  // namespace

// The wavefronts of a lecture's order, or of the colored order's border, for the passes.
// On several threads, a wavefront's pairs go by strips across the pile, and each thread
// takes a run of strips through every wavefront of a pass (StripPass). In pass order a
// wavefront's pairs lie in a band of sphere numbers that moves up from one wavefront to
// the next (in the landing 64k pile, half of a wavefront's pairs within 7 000 numbers, its
// middle 600 higher in the next). Cut by number, each wavefront handed the spheres around
// its middle to the other thread, their cache lines with them; cut by strip, a sphere
// stays with the thread that takes its side of the pile.
namespace {

// The strips of an earlier step serve for this many steps: a pile's spheres move little
// from step to step, and a sphere in another strip than the one it is placed in costs a
// wait at most (StripPass: the result is the same whatever the strips). Finding them went
// over every sphere twice, on the one thread that then sorts the wavefronts (0.17 ms a
// step in the landing 64k pile).
constexpr std::uint64_t kStripsKeptSteps = 16;

bool stripsServe(const Workspace::WavefrontStrips& strips, std::uint32_t count, const World& world) {
    return strips.count == count && strips.ofSphere.size() == world.size() && world.stepCount >= strips.foundAtStep &&
           world.stepCount - strips.foundAtStep < kStripsKeptSteps;
}

// Workspace::wavefrontOrder and wavefrontStart from pairs[0, count), for `threads` threads
// (on several, by strips: Workspace::wavefrontStrips).
void sortByWavefronts(World& world, int threads, const SpherePair* pairs, std::size_t count) {
    Workspace& ws = world.workspace;
    ws.wavefrontNext.resize(world.size(), 0);
    Workspace::WavefrontStrips* strips = nullptr;
    ws.wavefrontStrips.threads = threads;
    if (threads > 1) {
        strips = &ws.wavefrontStrips;
        const std::uint32_t stripCount = std::min<std::uint32_t>(kStripsPerThread * std::uint32_t(threads), 256);
        if (!stripsServe(*strips, stripCount, world)) {
            strips->count = stripCount;
            strips->foundAtStep = world.stepCount;
            findStrips(world, stripCount, strips->ofSphere);
        }
    }
    sortIntoWavefronts(pairs, count, ws.wavefrontNext, ws.wavefrontOfPair, ws.wavefrontStart, ws.wavefrontOrder,
                       strips);
}

}  // namespace

void findWavefronts(World& world, int threads) {
    sortByWavefronts(world, threads, world.workspace.visitOrder.data(), world.workspace.visitOrder.size());
}

void findBorderWavefronts(World& world, int threads) {
    Workspace& ws = world.workspace;
    const std::uint32_t border = colorGroups(ws) - 1;  // the groups: the blocks, then the border
    const std::uint32_t first = colorRange(ws, border, 0).begin, end = colorRange(ws, border, kGroupColors - 1).end;
    sortByWavefronts(world, threads, ws.visitOrder.data() + first, end - first);
    ws.borderByWavefronts = true;
}

}  // namespace physics
