// Pair order `colored`: not the lecture's. Slide 14 says the order of correction
// matters; this order is one more fixed order, chosen for speed. The candidate pairs are
// coloured greedily (each takes the lowest colour that none of its two spheres' pairs
// took before it, in index order), then visited colour by colour. No two pairs of one
// colour share a sphere, so a colour's pairs give the same result in any order: threads
// share them without waiting (solver_stages.h's forEachPairInPassOrder), and the result
// is the same, bit for bit, on any thread count.
#include <algorithm>
#include <array>

#include "physics/solver_stages.h"

namespace physics {

void colorPairs(World& world) {
    Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = ws.visitOrder;  // in index order
    ws.colorsOfSphere.assign(world.size(), 0);
    ws.colorOfPair.resize(pairs.size());
    ws.colorStart.assign(kPairColors + 1, 0);
    // Greedy colouring in index order: a list that changes little from one step to the
    // next keeps its colours up to the first pair that changed.
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        std::uint64_t& first = ws.colorsOfSphere[pairs[k].i];
        std::uint64_t& second = ws.colorsOfSphere[pairs[k].j];
        const std::uint64_t taken = first | second;
        const unsigned color = taken == ~std::uint64_t(0) ? kOverflowColor : unsigned(__builtin_ctzll(~taken));
        if (color != kOverflowColor) {
            first |= std::uint64_t(1) << color;
            second |= std::uint64_t(1) << color;
        }
        ws.colorOfPair[k] = std::uint8_t(color);
        ++ws.colorStart[color + 1];
    }
    for (unsigned c = 0; c < kPairColors; ++c) ws.colorStart[c + 1] += ws.colorStart[c];
    // Placed by colour, each colour in index order (a counting sort).
    ws.colorSorted.resize(pairs.size());
    std::array<std::uint32_t, kPairColors> next;  // where each colour's next pair goes
    std::copy(ws.colorStart.begin(), ws.colorStart.end() - 1, next.begin());
    for (std::size_t k = 0; k < pairs.size(); ++k) ws.colorSorted[next[ws.colorOfPair[k]]++] = pairs[k];
    ws.visitOrder.swap(ws.colorSorted);
}

}  // namespace physics
