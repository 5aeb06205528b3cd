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

// The most groups sortByFirstSphere counts apart: each keeps a count per sphere.
constexpr int kMostSortGroups = 8;

// pairs <- the tasks' pairs (task after task), in index order: a counting sort by first
// sphere, then each sphere's pairs sorted by second sphere. On several threads each group
// of consecutive tasks counts its own pairs per sphere and places them after those of the
// groups before it: the order of one thread, stable, whatever the number of groups.
void sortByFirstSphere(std::size_t n, const std::vector<TaskScratch>& parts, Workspace& ws, int threads) {
    const int groups = std::max(1, std::min({threads, kMostSortGroups, int(parts.size())}));
    const auto partsOf = [&](int g) { return rangeOf(parts.size(), g, groups); };
    std::vector<std::uint32_t>& count = ws.pairCounts;  // count[g * n + i], then where g places i's next
    count.assign(std::size_t(groups) * n, 0);
    runTasks(threads, groups, [&](int g) {
        std::uint32_t* mine = count.data() + std::size_t(g) * n;
        const Range r = partsOf(g);
        for (std::uint32_t t = r.begin; t < r.end; ++t) {
            for (const SpherePair& pair : parts[t].pairs) ++mine[pair.i];
        }
    });
    // start[i] and each group's first slot for sphere i, over ranges of spheres: each range's
    // total first, then the ranges' offsets one after another, then the slots.
    std::vector<std::uint32_t>& start = ws.pairStart;
    start.assign(n + 1, 0);
    std::vector<std::uint64_t> rangeTotal(std::size_t(groups) + 1, 0);
    runTasks(threads, groups, [&](int r) {
        const Range spheres = rangeOf(n, r, groups);
        std::uint64_t total = 0;
        for (std::uint32_t i = spheres.begin; i < spheres.end; ++i) {
            for (int g = 0; g < groups; ++g) total += count[std::size_t(g) * n + i];
        }
        rangeTotal[std::size_t(r) + 1] = total;
    });
    for (int r = 0; r < groups; ++r) rangeTotal[std::size_t(r) + 1] += rangeTotal[std::size_t(r)];
    runTasks(threads, groups, [&](int r) {
        const Range spheres = rangeOf(n, r, groups);
        auto next = std::uint32_t(rangeTotal[std::size_t(r)]);
        for (std::uint32_t i = spheres.begin; i < spheres.end; ++i) {
            start[i] = next;
            for (int g = 0; g < groups; ++g) {
                std::uint32_t& c = count[std::size_t(g) * n + i];
                const std::uint32_t pairsOfGroup = c;
                c = next;
                next += pairsOfGroup;
            }
        }
    });
    start[n] = std::uint32_t(rangeTotal[std::size_t(groups)]);
    ws.pairs.resize(start[n]);
    runTasks(threads, groups, [&](int g) {
        std::uint32_t* slot = count.data() + std::size_t(g) * n;
        const Range r = partsOf(g);
        for (std::uint32_t t = r.begin; t < r.end; ++t) {
            for (const SpherePair& pair : parts[t].pairs) ws.pairs[slot[pair.i]++] = pair;
        }
    });
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(n, t, threads);
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            sortBySecondSphere(ws.pairs.data() + start[i], ws.pairs.data() + start[i + 1]);
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
    workspace.gridAtBuild = grid;
    sortByCell(world, grid, workspace, threads);
    // Each task finds the pairs of one range of the cell order; sorted together, they
    // are in index order whatever the number of tasks.
    const int tasks = threads > 1 ? 4 * threads : 1;
    workspace.tasks.resize(std::size_t(tasks));
    std::vector<std::uint64_t> tests(std::size_t(tasks), 0);
    runTasks(threads, tasks, [&](int t) {
        TaskScratch& scratch = workspace.tasks[std::size_t(t)];
        scratch.pairs.clear();
        const Range range = rangeOf(n, t, tasks);
        tests[std::size_t(t)] = forwardPairs(range.begin, range.end, grid, margin, workspace, scratch);
    });
    std::uint64_t total = 0;
    for (int t = 0; t < tasks; ++t) total += tests[std::size_t(t)];
    sortByFirstSphere(n, workspace.tasks, workspace, threads);
    return total;
}

// The cells around c (c's too), row by row along x: visit(first, last) with the linear
// numbers of a row's first and last cell, which are consecutive.
template <class Visit>
void forRowsAround(const GridShape& grid, const glm::ivec3& c, const Visit& visit) {
    const glm::ivec3 lo = glm::max(c - 1, glm::ivec3(0)), hi = glm::min(c + 1, grid.dims - 1);
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) visit(grid.linear({lo.x, y, z}), grid.linear({hi.x, y, z}));
    }
}

std::uint64_t findMoverPairs(const World& world, double margin, Workspace& ws) {
    const GridShape& grid = ws.gridAtBuild;
    std::vector<SpherePair>& out = ws.moverPairs;
    out.clear();
    std::uint64_t tests = 0;
    const auto test = [&](std::uint32_t a, std::uint32_t b) {
        ++tests;
        const SpherePair pair{std::min(a, b), std::max(a, b)};
        if (withinReach(world, pair, margin)) out.push_back(pair);
    };
    for (std::size_t m = 0; m < ws.movers.size(); ++m) {
        const std::uint32_t i = ws.movers[m];
        if (!finite(world.position[i])) continue;  // NaN is never within reach
        forRowsAround(grid, grid.cellOf(world.position[i]), [&](std::uint32_t first, std::uint32_t last) {
            // A row of up to three cells is one run of slots.
            for (std::uint32_t slot = ws.cellStart[first]; slot < ws.cellStart[last + 1]; ++slot) {
                const std::uint32_t j = ws.sphereByCell[slot];
                if (!ws.isMover[j]) test(i, j);
            }
        });
    }
    // Movers with each other: sorted by the build grid's cell they are in now (then by
    // number), each tested against the movers of the cells around it, each pair once.
    using MoverInCell = Workspace::MoverInCell;
    std::vector<MoverInCell>& byCell = ws.moversByCell;
    byCell.clear();
    for (std::uint32_t i : ws.movers) {
        if (finite(world.position[i])) byCell.push_back({grid.linear(grid.cellOf(world.position[i])), i});
    }
    const auto before = [](const MoverInCell& a, const MoverInCell& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.sphere < b.sphere;
    };
    std::sort(byCell.begin(), byCell.end(), before);
    for (const MoverInCell& mover : byCell) {
        forRowsAround(grid, grid.cellAt(mover.cell), [&](std::uint32_t first, std::uint32_t last) {
            const auto from = std::lower_bound(byCell.begin(), byCell.end(), MoverInCell{first, 0}, before);
            for (auto other = from; other != byCell.end() && other->cell <= last; ++other) {
                if (other->sphere > mover.sphere) test(mover.sphere, other->sphere);
            }
        });
    }
    std::sort(out.begin(), out.end(), inIndexOrder);
    return tests;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace,
                        int threads) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace, threads);
}

}  // namespace physics
