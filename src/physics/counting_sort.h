#pragma once
// A stable counting sort spread over threads: the broad phase's cells and pairs, the
// colored order's blocks. Internal to the physics library.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "physics/solver_stages.h"

namespace physics {

// The most groups a counting sort counts apart: each keeps a count per bucket (4 bytes a
// cell of the grid, four cells a sphere: 16 MB a group at 1M spheres).
constexpr int kMostSortGroups = 8;

// Stable counting sort into buckets [0, buckets), on `groups` threads: forEachItem(g,
// visit) calls visit(key, item) for group g's items, in their order, and place(item, slot)
// puts an item at its slot. Group g counts its items apart (counts[g * buckets + b]), then
// each group finds the slots of a range of buckets, bucket by bucket and within one the
// groups in order, then places its items: the order of one thread, whatever the number of
// groups. Leaves start[b] = the first slot of bucket b (buckets + 1 entries).
template <class ForEachItem, class Place>
void countingSort(std::size_t buckets, int groups, const ForEachItem& forEachItem, std::vector<std::uint32_t>& start,
                  std::vector<std::uint32_t>& counts, const Place& place) {
    groups = std::max(1, groups);
    counts.resize(std::size_t(groups) * buckets);
    start.resize(buckets + 1);
    runTasks(groups, groups, [&](int g) {
        std::uint32_t* mine = counts.data() + std::size_t(g) * buckets;
        std::fill(mine, mine + buckets, 0u);
        forEachItem(g, [&](std::uint32_t key, const auto&) { ++mine[key]; });
    });
    std::vector<std::uint64_t> rangeFirst(std::size_t(groups) + 1, 0);  // each range of buckets' first slot
    runTasks(groups, groups, [&](int r) {
        const Range range = rangeOf(buckets, r, groups);
        std::uint64_t total = 0;
        for (std::uint32_t b = range.begin; b < range.end; ++b) {
            for (int g = 0; g < groups; ++g) total += counts[std::size_t(g) * buckets + b];
        }
        rangeFirst[std::size_t(r) + 1] = total;
    });
    for (int r = 0; r < groups; ++r) rangeFirst[std::size_t(r) + 1] += rangeFirst[std::size_t(r)];
    runTasks(groups, groups, [&](int r) {  // the counts become each group's next slot
        const Range range = rangeOf(buckets, r, groups);
        auto next = std::uint32_t(rangeFirst[std::size_t(r)]);
        for (std::uint32_t b = range.begin; b < range.end; ++b) {
            start[b] = next;
            for (int g = 0; g < groups; ++g) {
                std::uint32_t& c = counts[std::size_t(g) * buckets + b];
                const std::uint32_t inBucket = c;
                c = next;
                next += inBucket;
            }
        }
    });
    start[buckets] = std::uint32_t(rangeFirst[std::size_t(groups)]);
    runTasks(groups, groups, [&](int g) {
        std::uint32_t* slot = counts.data() + std::size_t(g) * buckets;
        forEachItem(g, [&](std::uint32_t key, const auto& item) { place(item, slot[key]++); });
    });
}

}  // namespace physics
