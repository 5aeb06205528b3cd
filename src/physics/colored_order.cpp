// Pair order `colored`: not the lecture's. Slide 14 says the order of correction
// matters; this order is one more fixed order, chosen for speed. The candidate pairs are
// coloured greedily (each takes the lowest colour that none of its two spheres' pairs
// took before it, in index order), then visited colour by colour. No two pairs of one
// colour share a sphere, so a colour's pairs give the same result in any order: threads
// share them without waiting, and several are answered side by side (colored_lanes.cpp).
// The result is the same, bit for bit, on any thread count.
//
// So that a pass does not sweep the whole world once per colour (from 100k spheres on,
// the spheres' data no longer stays in the caches), the world is cut into blocks of
// kBlockSpheres spheres: the pairs inside each block are coloured and visited block by
// block, then the pairs between blocks, the border (solver_stages.h's forEachColor; on
// several threads the position stages take the border by wavefronts and strips,
// findBorderWavefronts). From kBlocksByPlaceFrom spheres a block is a place of the world:
// in the landed 64k pile the border then holds 8 % of the pairs. (Blocks of 4096 sphere
// numbers held 82 % there: the scenes number their spheres row by row, and a landed
// pile's spheres have left their rows. src/bench/README.md.)

#include "physics/solver_stages.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>

#include "physics/broad_phase.h"
#include "physics/counting_sort.h"

namespace physics {
namespace {

// The blocks are runs of kBlockSpheres spheres along a Morton curve through tiles of the
// box around the centres, each tile's spheres in index order. A tile would hold this many
// spheres were the box evenly full (a pile's bottom holds more, the air above it fewer),
// so that a block spans a few tiles. (256 and 1024 did no better at 64k and 100k.)
constexpr double kTileSpheres = 512.0;
constexpr int kMostTilesPerAxis = 1024;  // a Morton key holds 10 bits an axis
constexpr double kMostTilesPerBlock = 64.0;

// The low 10 bits of v, spread to every third bit: one axis of a Morton key.
std::uint32_t spreadBits(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

// Cubes across the box around the centres, numbered along the Morton curve.
struct Tiles {
    glm::dvec3 low{0.0};      // m, the box's lowest corner
    glm::dvec3 perTile{0.0};  // 1/m: tiles per metre along each axis
    glm::ivec3 dims{1};
    std::vector<std::uint32_t> rankOf;  // per tile (x fastest, then y, then z), its place on the curve

    std::size_t count() const { return rankOf.size(); }
    std::uint32_t of(const glm::dvec3& centre) const {
        const glm::dvec3 at = (centre - low) * perTile;  // NaN: tile 0
        const auto along = [&](int a) { return int(std::min(std::max(0.0, at[a]), double(dims[a] - 1))); };
        return rankOf[std::size_t((along(2) * dims.y + along(1)) * dims.x + along(0))];
    }
};

Tiles tilesAround(const World& world, int threads) {
    const auto [low, high] = boundsOfCentres(world, threads);  // m
    const glm::dvec3 size = glm::max(high - low, glm::dvec3(1e-9));  // m
    const double spheres = double(std::max<std::size_t>(world.size(), 1));
    double edge = std::cbrt(size.x * size.y * size.z * kTileSpheres / spheres);  // m
    Tiles tiles;
    tiles.low = low;
    // A flat or thin box (every centre at one height) holds far more tiles of that edge
    // than the spheres need: the edge grows until the tiles are at most kMostTilesPerBlock
    // a block.
    const double mostTiles = kMostTilesPerBlock * std::ceil(spheres / double(kBlockSpheres));
    for (;;) {
        for (int a = 0; a < 3; ++a) {
            tiles.dims[a] = int(std::clamp(std::ceil(size[a] / edge), 1.0, double(kMostTilesPerAxis)));
        }
        const double count = double(tiles.dims.x) * tiles.dims.y * tiles.dims.z;
        if (count <= mostTiles) break;
        edge *= std::cbrt(count / mostTiles) * 1.01;
    }
    tiles.perTile = glm::dvec3(tiles.dims) / size;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> curve;  // (Morton key, tile)
    curve.reserve(std::size_t(tiles.dims.x) * tiles.dims.y * tiles.dims.z);
    for (int z = 0; z < tiles.dims.z; ++z) {
        for (int y = 0; y < tiles.dims.y; ++y) {
            for (int x = 0; x < tiles.dims.x; ++x) {
                const std::uint32_t key = spreadBits(std::uint32_t(x)) | spreadBits(std::uint32_t(y)) << 1 |
                                          spreadBits(std::uint32_t(z)) << 2;
                curve.push_back({key, std::uint32_t(curve.size())});
            }
        }
    }
    std::sort(curve.begin(), curve.end());
    tiles.rankOf.resize(curve.size());
    for (std::size_t r = 0; r < curve.size(); ++r) tiles.rankOf[curve[r].second] = std::uint32_t(r);
    return tiles;
}

// Below this many spheres the blocks are runs of sphere numbers. The world's data then
// stays in a core's cache, so places gain nothing on one thread, and blocks of numbers
// share no cache line, which the threads write (measured on two threads: 16k and 32k
// 7-19 % faster by numbers, 48k 6-7 % faster by places; src/bench/README.md).
constexpr std::size_t kBlocksByPlaceFrom = 10 * kBlockSpheres;

// Workspace::blockOfSphere; returns the number of blocks.
std::uint32_t findBlocks(const World& world, Workspace& ws, int threads) {
    const std::size_t n = world.size();
    ws.blockOfSphere.resize(n);
    const std::uint32_t blocks = std::uint32_t((n + kBlockSpheres - 1) / kBlockSpheres);
    if (n < kBlocksByPlaceFrom) {
        for (std::uint32_t i = 0; i < n; ++i) ws.blockOfSphere[i] = i / kBlockSpheres;
        return blocks;
    }
    const Tiles tiles = tilesAround(world, threads);
    ws.tileOfSphere.resize(n);
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(n, t, threads);
        for (std::uint32_t i = range.begin; i < range.end; ++i) ws.tileOfSphere[i] = tiles.of(world.position[i]);
    });
    const int groups = std::min(threads, kMostSortGroups);
    const auto spheresOf = [&](int g, const auto& visit) {  // a range of sphere numbers each
        const Range spheres = rangeOf(n, g, groups);
        for (std::uint32_t i = spheres.begin; i < spheres.end; ++i) visit(ws.tileOfSphere[i], i);
    };
    countingSort(tiles.count(), groups, spheresOf, ws.tileStart, ws.tileCounts,
                 [&](std::uint32_t i, std::uint32_t slot) { ws.blockOfSphere[i] = slot / kBlockSpheres; });
    return blocks;
}

// One task's colouring: the groups `mine` of `groups` (the border is the last). Each
// group's pairs are coloured greedily in index order, and no two groups share a sphere's
// colours, so how the groups are cut into tasks changes nothing. Counts each colour's
// pairs into colorStart[key + 1] (each task its own keys), not the overflow's.
void colorTheGroups(const World& world, Workspace& ws, Workspace::ColoringTask& task, Range mine,
                    std::uint32_t groups) {
    const std::size_t n = world.size();
    const std::uint32_t border = groups - 1, overflowKey = groups * kGroupColors;
    // A sphere's colours inside its block at [0, n), in the border at [n, 2 n): the two
    // groups are visited apart, and may each use every colour (the border's only in the
    // task that colours it).
    task.colorsOfSphere.assign(mine.end == groups ? 2 * n : n, 0);
    if (task.colored.size() < ws.visitOrder.size()) task.colored.resize(ws.visitOrder.size());
    Workspace::ColoringTask::KeyedPair* out = task.colored.data();
    std::uint32_t* count = ws.colorStart.data() + 1;
    std::uint32_t overflow = 0;
    const std::uint32_t* block = ws.blockOfSphere.data();
    const SpherePair* pairs = ws.visitOrder.data();  // in index order
    const std::uint32_t pairCount = std::uint32_t(ws.visitOrder.size());
    std::uint64_t* colorsInside = task.colorsOfSphere.data();
    std::uint64_t* colorsBorder = colorsInside + n;
    for (std::uint32_t k = 0; k < pairCount; ++k) {
        const std::uint32_t i = pairs[k].i, j = pairs[k].j;
        const std::uint32_t bi = block[i], bj = block[j];
        const std::uint32_t group = bi == bj ? bi : border;
        if (group < mine.begin || group >= mine.end) continue;
        std::uint64_t* colors = bi == bj ? colorsInside : colorsBorder;
        const std::uint64_t taken = colors[i] | colors[j];
        std::uint32_t key = overflowKey;
        if (taken != ~std::uint64_t(0)) {
            const std::uint64_t bit = ~taken & (taken + 1);  // the lowest free colour
            colors[i] |= bit;
            colors[j] |= bit;
            key = group * kGroupColors + unsigned(__builtin_ctzll(bit));
            ++count[key];
        } else {
            ++overflow;
        }
        *out++ = {k, key};
    }
    task.count = std::uint32_t(out - task.colored.data());
    task.overflow = overflow;
}

}  // namespace

void colorPairs(World& world, int threads) {
    Workspace& ws = world.workspace;
    const std::uint32_t groups = findBlocks(world, ws, threads) + 1;  // the blocks, the border
    const std::uint32_t overflowKey = groups * kGroupColors;
    const int tasks = int(std::min<std::uint32_t>(std::uint32_t(std::max(threads, 1)), groups));
    ws.coloringTasks.resize(std::size_t(tasks));
    ws.colorStart.assign(std::size_t(overflowKey) + 2, 0);
    runTasks(threads, tasks, [&](int t) {
        colorTheGroups(world, ws, ws.coloringTasks[std::size_t(t)], rangeOf(groups, t, tasks), groups);
    });
    for (const Workspace::ColoringTask& task : ws.coloringTasks) ws.colorStart[overflowKey + 1] += task.overflow;
    for (std::size_t key = 0; key <= overflowKey; ++key) ws.colorStart[key + 1] += ws.colorStart[key];
    // Placed by key, each colour in index order (a counting sort): each task its own keys.
    const std::vector<SpherePair>& pairs = ws.visitOrder;
    ws.colorSorted.resize(pairs.size());
    std::vector<std::uint32_t>& next = ws.colorNext;
    next.assign(ws.colorStart.begin(), ws.colorStart.end() - 1);
    runTasks(threads, tasks, [&](int t) {
        const Workspace::ColoringTask& task = ws.coloringTasks[std::size_t(t)];
        for (std::uint32_t c = 0; c < task.count; ++c) {
            const auto [k, key] = task.colored[c];
            if (key != overflowKey) ws.colorSorted[next[key]++] = pairs[k];
        }
    });
    // The overflow, in index order (rare: a sphere with more than 64 pairs in one group).
    if (ws.colorStart[overflowKey + 1] > ws.colorStart[overflowKey]) {
        std::vector<std::uint32_t> overflow;
        for (const Workspace::ColoringTask& task : ws.coloringTasks) {
            for (std::uint32_t c = 0; c < task.count; ++c) {
                if (task.colored[c].key == overflowKey) overflow.push_back(task.colored[c].pair);
            }
        }
        std::sort(overflow.begin(), overflow.end());
        for (const std::uint32_t k : overflow) ws.colorSorted[next[overflowKey]++] = pairs[k];
    }
    ws.visitOrder.swap(ws.colorSorted);
    ws.colorSortedStep = world.stepCount;  // colorSorted: this step's pairs in index order
}

}  // namespace physics
