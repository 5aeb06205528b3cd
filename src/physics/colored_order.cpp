// Pair order `colored`: not the lecture's. Slide 14 says the order of correction
// matters; this order is one more fixed order, chosen for speed. The candidate pairs are
// coloured greedily (each takes the lowest colour that none of its two spheres' pairs
// took before it, in index order), then visited colour by colour. No two pairs of one
// colour share a sphere, so a colour's pairs give the same result in any order: threads
// share them without waiting, and several are answered side by side (colored_lanes.cpp).
// The result is the same, bit for bit, on any thread count.
//
// So that a pass does not sweep the whole world once per colour (from 100k spheres on,
// the spheres' data no longer stays in the caches), the pairs inside each block of 4096
// sphere numbers are coloured and visited block by block, then the pairs between blocks
// (solver_stages.h's forEachColor). The scenes number their spheres row by row, so a
// block starts as a few layers of a pile, and most pairs lie inside one; once a pile has
// landed, its spheres have left their layers and most pairs lie between blocks (82 % in
// the 64k pile at 1.5 s). On several threads the position stages take those by wavefronts
// and strips (findBorderWavefronts).

#include "physics/solver_stages.h"

namespace physics {

void colorPairs(World& world) {
    Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = ws.visitOrder;  // in index order
    const std::size_t n = world.size();
    const std::uint32_t groups = std::uint32_t((n + kBlockSpheres - 1) / kBlockSpheres) + 1;  // blocks, border
    const std::uint32_t overflowKey = groups * kGroupColors;
    // A sphere's colours inside its block at [0, n), between blocks at [n, 2 n): the two
    // groups are visited apart, and may each use every colour.
    ws.colorsOfSphere.assign(2 * n, 0);
    ws.colorOfPair.resize(pairs.size());
    ws.colorStart.assign(std::size_t(overflowKey) + 2, 0);
    // Greedy colouring in index order: a list that changes little from one step to the
    // next keeps its colours up to the first pair that changed.
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::uint32_t i = pairs[k].i, j = pairs[k].j;
        const bool inside = i / kBlockSpheres == j / kBlockSpheres;
        std::uint64_t* colors = ws.colorsOfSphere.data() + (inside ? 0 : n);
        const std::uint64_t taken = colors[i] | colors[j];
        std::uint32_t key = overflowKey;
        if (taken != ~std::uint64_t(0)) {
            const unsigned color = unsigned(__builtin_ctzll(~taken));
            colors[i] |= std::uint64_t(1) << color;
            colors[j] |= std::uint64_t(1) << color;
            key = (inside ? i / kBlockSpheres : groups - 1) * kGroupColors + color;
        }
        ws.colorOfPair[k] = key;
        ++ws.colorStart[key + 1];
    }
    for (std::size_t key = 0; key <= overflowKey; ++key) ws.colorStart[key + 1] += ws.colorStart[key];
    // Placed by key, each colour in index order (a counting sort).
    ws.colorSorted.resize(pairs.size());
    std::vector<std::uint32_t>& next = ws.colorNext;
    next.assign(ws.colorStart.begin(), ws.colorStart.end() - 1);
    for (std::size_t k = 0; k < pairs.size(); ++k) ws.colorSorted[next[ws.colorOfPair[k]]++] = pairs[k];
    ws.visitOrder.swap(ws.colorSorted);
}

}  // namespace physics
