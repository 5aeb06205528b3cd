#include "physics/broad_phase.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "physics/solver_stages.h"

namespace physics {
namespace {

// The grid covers the spheres' bounding box. Cells are never smaller than one
// largest diameter plus the margin, and grow if needed to keep at most ~4 cells
// per sphere, so spheres that fly far apart cannot blow up the memory.
struct GridShape {
    glm::dvec3 origin{0.0};  // m, corner of cell (0, 0, 0)
    double cellSize = 1.0;   // m
    glm::ivec3 dims{1};

    glm::ivec3 cellOf(const glm::dvec3& p) const {
        return glm::clamp(glm::ivec3(glm::floor((p - origin) / cellSize)), glm::ivec3(0), dims - 1);
    }
    std::uint32_t linear(const glm::ivec3& c) const {
        return static_cast<std::uint32_t>((c.z * dims.y + c.y) * dims.x + c.x);
    }
    glm::ivec3 cellAt(std::uint32_t linearIndex) const {  // the inverse of linear()
        const int k = static_cast<int>(linearIndex);
        return {k % dims.x, k / dims.x % dims.y, k / dims.x / dims.y};
    }
};

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// A sphere with a non-finite centre (a blown-up state, which the app reports) sits in
// cell 0 and meets nothing: its distances are NaN, and NaN is never within reach.
GridShape chooseGrid(const World& world, double margin) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : world.position) {
        if (!finite(p)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (!finite(lo) || !finite(hi)) lo = hi = glm::dvec3(0.0);
    GridShape grid;
    grid.origin = lo;
    const double cell = 2.0 * maxRadius(world) + margin;  // m
    grid.cellSize = std::isfinite(cell) ? std::max(cell, 1e-9) : 1.0;
    const double maxCells = std::max(4096.0, 4.0 * static_cast<double>(world.size()));
    for (;;) {
        const glm::dvec3 cells = glm::floor((hi - lo) / grid.cellSize) + 1.0;
        const double count = cells.x * cells.y * cells.z;
        if (count <= maxCells) {
            grid.dims = glm::ivec3(cells);
            return grid;
        }
        grid.cellSize *= std::cbrt(count / maxCells) * 1.01;
    }
}

// Stable counting sort of items 0..n-1 by key(k) in [0, buckets): place(k, slot) puts
// item k at its slot. Leaves start[b] = the first slot of bucket b (buckets + 1 entries).
template <class Key, class Place>
void countingSort(std::size_t n, std::size_t buckets, const Key& key, std::vector<std::uint32_t>& start,
                  const Place& place) {
    start.assign(buckets + 1, 0);
    for (std::size_t k = 0; k < n; ++k) ++start[key(k) + 1];
    for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    for (std::size_t k = 0; k < n; ++k) place(k, start[key(k)]++);
    // Placing advanced each start to the next bucket's: shift back.
    for (std::size_t b = buckets; b > 0; --b) start[b] = start[b - 1];
    start[0] = 0;
}

// The grid tests candidates this many at a time, whatever the length of a run (most
// runs hold 1 to 4 spheres, and a loop that stops at each run's end would guess wrong
// at almost every run). Tests past a run's end are made and not counted; the cell order
// carries kLanes - 1 slots of padding so that they read valid memory.
constexpr std::uint32_t kLanes = 4;

// sphereByCell lists sphere indices cell by cell, ascending within a cell, and
// cellOrdered their centres and radii in the same order (then the padding).
void sortByCell(const World& world, const GridShape& grid, Workspace& ws, int threads) {
    const std::size_t n = world.size();
    ws.cellOfSphere.resize(n);
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(n, t, threads);
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            ws.cellOfSphere[i] = finite(world.position[i]) ? grid.linear(grid.cellOf(world.position[i])) : 0;
        }
    });
    ws.sphereByCell.resize(n + kLanes - 1);
    ws.cellOrdered.resize(n + kLanes - 1);
    countingSort(n, std::size_t(grid.dims.x) * grid.dims.y * grid.dims.z,
                 [&](std::size_t i) { return ws.cellOfSphere[i]; }, ws.cellStart,
                 [&](std::size_t i, std::uint32_t slot) {
                     ws.sphereByCell[slot] = static_cast<std::uint32_t>(i);
                     ws.cellOrdered[slot] = glm::dvec4(world.position[i], world.radius[i]);
                 });
}

bool withinReach(const glm::dvec4& a, const glm::dvec4& b, double margin) {
    const double reach = a.w + b.w + margin;
    const glm::dvec3 delta = glm::dvec3(a) - glm::dvec3(b);
    return glm::dot(delta, delta) <= reach * reach;
}

// The forward half of a cell's neighbourhood: the cell itself, and the 13 of its 26
// neighbour cells that come after it. A sphere meets the later spheres of its own cell
// and the spheres of those 13 cells, so each pair of neighbours is met from one side
// only. They are at most 5 contiguous runs of slots: the cell and the next one along x;
// the row y + 1; the three rows of the plane z + 1. The first run starts at the cell's
// first slot; for one of its spheres, it starts just after that sphere.
struct ForwardRuns {
    std::uint32_t start[5], end[5];
    int count = 0;
};
ForwardRuns forwardRuns(std::uint32_t cell, const GridShape& grid, const Workspace& ws) {
    const glm::ivec3 c = grid.cellAt(cell);
    const int x0 = std::max(c.x - 1, 0), x1 = std::min(c.x + 1, grid.dims.x - 1);
    ForwardRuns runs;
    const auto add = [&](std::uint32_t start, std::uint32_t end) {
        runs.start[runs.count] = start;
        runs.end[runs.count++] = end;
    };
    add(ws.cellStart[cell], ws.cellStart[grid.linear({x1, c.y, c.z}) + 1]);
    const auto addRow = [&](int y, int z) {
        add(ws.cellStart[grid.linear({x0, y, z})], ws.cellStart[grid.linear({x1, y, z}) + 1]);
    };
    if (c.y + 1 < grid.dims.y) addRow(c.y + 1, c.z);
    if (c.z + 1 < grid.dims.z) {
        for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, grid.dims.y - 1); ++y) addRow(y, c.z + 1);
    }
    return runs;
}

// Appends the pairs within reach that the sphere at `slot` meets in `runs` (its cell's,
// the first starting after it), as (lower index, higher index), and returns the
// distance tests made. The tests are written without branches (a few candidates are in
// reach: a branch would be mispredicted), into `partners`, which only grows.
std::uint64_t forwardPairsOf(std::uint32_t slot, const ForwardRuns& runs, double margin,
                             const Workspace& ws, std::vector<std::uint32_t>& partners,
                             std::vector<SpherePair>& out) {
    const std::uint32_t i = ws.sphereByCell[slot];
    const glm::dvec4 sphere = ws.cellOrdered[slot];
    std::size_t candidates = 0;
    for (int run = 0; run < runs.count; ++run) candidates += runs.end[run] - runs.start[run];
    if (partners.size() < candidates + kLanes) partners.resize(candidates + kLanes);
    std::uint32_t* partner = partners.data();
    std::size_t count = 0;
    for (int run = 0; run < runs.count; ++run) {
        const std::uint32_t end = runs.end[run];
        for (std::uint32_t k = runs.start[run]; k < end; k += kLanes) {
            for (std::uint32_t lane = k; lane < k + kLanes; ++lane) {
                partner[count] = ws.sphereByCell[lane];
                count += (lane < end) & withinReach(sphere, ws.cellOrdered[lane], margin);
            }
        }
    }
    const std::size_t first = out.size();
    out.resize(first + count);
    SpherePair* found = out.data() + first;
    for (std::size_t k = 0; k < count; ++k) {
        found[k].i = std::min(i, partner[k]);
        found[k].j = std::max(i, partner[k]);
    }
    return candidates;
}

// The pairs that the spheres at slots [begin, end) of the cell order meet, appended to
// scratch.pairs; returns the distance tests made.
std::uint64_t forwardPairs(std::uint32_t begin, std::uint32_t end, const GridShape& grid, double margin,
                           const Workspace& ws, TaskScratch& scratch) {
    std::uint64_t tests = 0;
    std::uint32_t runsCell = UINT32_MAX;  // the cell `runs` belong to
    ForwardRuns runs;
    for (std::uint32_t slot = begin; slot < end; ++slot) {
        const std::uint32_t cell = ws.cellOfSphere[ws.sphereByCell[slot]];
        if (cell != runsCell) {
            runs = forwardRuns(cell, grid, ws);
            runsCell = cell;
        }
        runs.start[0] = slot + 1;  // this sphere meets the spheres after it in its cell
        tests += forwardPairsOf(slot, runs, margin, ws, scratch.partners, scratch.pairs);
    }
    return tests;
}

// Sorts [first, last) by second sphere: insertion for the few pairs a sphere usually
// has, std::sort beyond.
void sortBySecondSphere(SpherePair* first, SpherePair* last) {
    if (last - first < 2) return;  // (an empty vector's data() may be null: no first + 1 on it)
    if (last - first > 16) {
        std::sort(first, last, [](const SpherePair& a, const SpherePair& b) { return a.j < b.j; });
        return;
    }
    for (SpherePair* k = first + 1; k < last; ++k) {
        const SpherePair moving = *k;
        SpherePair* hole = k;
        for (; hole > first && hole[-1].j > moving.j; --hole) *hole = hole[-1];
        *hole = moving;
    }
}

// pairs <- unsorted, in index order: grouped by first sphere (a counting sort), then
// each group sorted by second sphere (in parallel).
void sortByFirstSphere(std::size_t n, const std::vector<SpherePair>& unsorted,
                       std::vector<std::uint32_t>& start, std::vector<SpherePair>& pairs,
                       int threads) {
    pairs.resize(unsorted.size());
    countingSort(unsorted.size(), n, [&](std::size_t k) { return unsorted[k].i; }, start,
                 [&](std::size_t k, std::uint32_t slot) { pairs[slot] = unsorted[k]; });
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(n, t, threads);
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            sortBySecondSphere(pairs.data() + start[i], pairs.data() + start[i + 1]);
        }
    });
}

}  // namespace

bool withinReach(const World& world, const SpherePair& pair, double margin) {
    const double reach = world.radius[pair.i] + world.radius[pair.j] + margin;
    const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];
    return glm::dot(delta, delta) <= reach * reach;
}

double maxRadius(const World& world) {
    double r = 0.0;
    for (double ri : world.radius) r = std::max(r, ri);
    return r;
}

std::uint64_t findPairsAllPairs(const World& world, double margin, std::vector<SpherePair>& pairs) {
    pairs.clear();
    const auto n = static_cast<std::uint32_t>(world.size());
    std::uint64_t tests = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
            ++tests;
            if (withinReach(world, {i, j}, margin)) pairs.push_back({i, j});
        }
    }
    return tests;
}

std::uint64_t findPairsGrid(const World& world, double margin, Workspace& workspace, int threads) {
    workspace.pairs.clear();
    const auto n = static_cast<std::uint32_t>(world.size());
    if (n < 2) return 0;
    threads = std::max(threads, 1);
    const GridShape grid = chooseGrid(world, margin);
    sortByCell(world, grid, workspace, threads);
    // Each task finds the pairs of one range of the cell order; put together and
    // sorted, they are in index order whatever the number of tasks.
    const int tasks = threads > 1 ? 4 * threads : 1;
    workspace.tasks.resize(std::size_t(tasks));
    std::vector<std::uint64_t> tests(std::size_t(tasks), 0);
    runTasks(threads, tasks, [&](int t) {
        TaskScratch& scratch = workspace.tasks[std::size_t(t)];
        scratch.pairs.clear();
        const Range range = rangeOf(n, t, tasks);
        tests[std::size_t(t)] = forwardPairs(range.begin, range.end, grid, margin, workspace, scratch);
    });
    workspace.foundPairs.clear();
    std::uint64_t total = 0;
    for (int t = 0; t < tasks; ++t) {
        const std::vector<SpherePair>& part = workspace.tasks[std::size_t(t)].pairs;
        workspace.foundPairs.insert(workspace.foundPairs.end(), part.begin(), part.end());
        total += tests[std::size_t(t)];
    }
    sortByFirstSphere(n, workspace.foundPairs, workspace.pairStart, workspace.pairs, threads);
    return total;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace,
                        int threads) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace, threads);
}

}  // namespace physics
