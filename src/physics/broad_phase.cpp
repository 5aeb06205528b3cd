#include "physics/broad_phase.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "physics/counting_sort.h"
#include "physics/solver_stages.h"

namespace physics {
namespace {

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

std::pair<glm::dvec3, glm::dvec3> boundsOfCentres(const World& world, int threads) {
    std::vector<glm::dvec3> lows(static_cast<std::size_t>(threads)), highs(static_cast<std::size_t>(threads));  // m, each task's box
    runTasks(threads, threads, [&](int t) {
        const Range range = rangeOf(world.size(), t, threads);
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            const glm::dvec3& p = world.position[i];
            if (!finite(p)) continue;
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        lows[std::size_t(t)] = lo;
        highs[std::size_t(t)] = hi;
    });
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (int t = 0; t < threads; ++t) {
        lo = glm::min(lo, lows[std::size_t(t)]);
        hi = glm::max(hi, highs[std::size_t(t)]);
    }
    if (!finite(lo) || !finite(hi)) lo = hi = glm::dvec3(0.0);
    return {lo, hi};
}

namespace {

// The grid covers the spheres' bounding box. Cells are never smaller than one
// largest diameter plus the margin, and grow if needed to keep at most ~4 cells
// per sphere, so spheres that fly far apart cannot blow up the memory.

// A sphere with a non-finite centre (a blown-up state, which the app reports) sits in
// cell 0 and meets nothing: its distances are NaN, and NaN is never within reach.
GridShape chooseGrid(const World& world, double margin, int threads) {
    const auto [lo, hi] = boundsOfCentres(world, threads);  // m
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
    const int groups = std::min(threads, kMostSortGroups);
    const auto spheresOf = [&](int g, const auto& visit) {  // a range of sphere numbers each
        const Range spheres = rangeOf(n, g, groups);
        for (std::uint32_t i = spheres.begin; i < spheres.end; ++i) visit(ws.cellOfSphere[i], i);
    };
    countingSort(std::size_t(grid.dims.x) * grid.dims.y * grid.dims.z, groups, spheresOf, ws.cellStart,
                 ws.cellCounts, [&](std::uint32_t i, std::uint32_t slot) {
                     ws.sphereByCell[slot] = i;
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


// pairs <- the tasks' pairs (task after task), in index order: a counting sort by first
// sphere (each group of consecutive tasks counted apart, countingSort), then each sphere's
// pairs sorted by second sphere.
void sortByFirstSphere(std::size_t n, const std::vector<TaskScratch>& parts, Workspace& ws, int threads) {
    const int groups = std::max(1, std::min({threads, kMostSortGroups, int(parts.size())}));
    const auto pairsOf = [&](int g, const auto& visit) {
        const Range tasks = rangeOf(parts.size(), g, groups);
        for (std::uint32_t t = tasks.begin; t < tasks.end; ++t) {
            for (const SpherePair& pair : parts[t].pairs) visit(pair.i, pair);
        }
    };
    std::size_t total = 0;
    for (const TaskScratch& part : parts) total += part.pairs.size();
    // Every slot is written below: resized from the last build's list, about as long, the
    // vector zeroes next to nothing (cleared first, it zeroed 1.1 MB at 64k, on one thread
    // while the others waited).
    ws.pairs.resize(total);
    countingSort(n, groups, pairsOf, ws.pairStart, ws.pairCounts,
                 [&](const SpherePair& pair, std::uint32_t slot) { ws.pairs[slot] = pair; });
    // Each thread takes the spheres of an equal share of the pairs (a landing pile's first
    // numbers, landed, hold most of them).
    const std::vector<std::uint32_t>& start = ws.pairStart;
    const auto firstSphereOfShare = [&](int t) {
        const Range share = rangeOf(total, t, threads);
        return std::uint32_t(std::lower_bound(start.begin(), start.end() - 1, share.begin) - start.begin());
    };
    runTasks(threads, threads, [&](int t) {
        const std::uint32_t end = t + 1 == threads ? std::uint32_t(n) : firstSphereOfShare(t + 1);
        for (std::uint32_t i = firstSphereOfShare(t); i < end; ++i) {
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
    const auto n = static_cast<std::uint32_t>(world.size());
    if (n < 2) {
        workspace.pairs.clear();
        return 0;
    }
    threads = std::max(threads, 1);
    const GridShape grid = chooseGrid(world, margin, threads);
    workspace.gridAtBuild = grid;
    sortByCell(world, grid, workspace, threads);
    // Each task finds the pairs of one range of the cell order; sorted together, they
    // are in index order whatever the number of tasks. Threads take them as they come:
    // 16 a thread, so that the last one taken is short (with 4, the 64k landing pile's
    // broad phase on two threads took about 0.15 ms a step more).
    const int tasks = threads > 1 ? 16 * threads : 1;
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

namespace {

// The cells around c (c's too), row by row along x: visit(first, last) with the linear
// numbers of a row's first and last cell, which are consecutive.
template <class Visit>
void forRowsAround(const GridShape& grid, const glm::ivec3& c, const Visit& visit) {
    const glm::ivec3 lo = glm::max(c - 1, glm::ivec3(0)), hi = glm::min(c + 1, grid.dims - 1);
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) visit(grid.linear({lo.x, y, z}), grid.linear({hi.x, y, z}));
    }
}

// The movers' pairs with the spheres that stayed: each mover in the build grid's cells
// around where it is now. Appends to `out`, returns the distance tests.
std::uint64_t moverPairsWithStayers(const World& world, double margin, const Workspace& ws, Range movers,
                                    std::vector<SpherePair>& out) {
    const GridShape& grid = ws.gridAtBuild;
    std::uint64_t tests = 0;
    for (std::uint32_t m = movers.begin; m < movers.end; ++m) {
        const std::uint32_t i = ws.movers[m];
        if (!finite(world.position[i])) continue;  // NaN is never within reach
        forRowsAround(grid, grid.cellOf(world.position[i]), [&](std::uint32_t first, std::uint32_t last) {
            // A row of up to three cells is one run of slots.
            for (std::uint32_t slot = ws.cellStart[first]; slot < ws.cellStart[last + 1]; ++slot) {
                const std::uint32_t j = ws.sphereByCell[slot];
                if (ws.isMover[j]) continue;
                ++tests;
                const SpherePair pair{std::min(i, j), std::max(i, j)};
                if (withinReach(world, pair, margin)) out.push_back(pair);
            }
        });
    }
    return tests;
}

// ws.moverCells <- where each cell's movers start in ws.moversByCell, by the cell's
// number: a table of open addressing (linear probing), at least twice as big as the cells.
void tableMoverCells(Workspace& ws) {
    const std::vector<Workspace::MoverInCell>& byCell = ws.moversByCell;
    std::size_t size = 16;
    while (size < 2 * byCell.size()) size *= 2;
    ws.moverCells.assign(size, 0);
    for (std::uint32_t k = 0; k < byCell.size(); ++k) {
        if (k > 0 && byCell[k].cell == byCell[k - 1].cell) continue;
        std::size_t slot = byCell[k].cell & (size - 1);
        while (ws.moverCells[slot] != 0) slot = (slot + 1) & (size - 1);
        ws.moverCells[slot] = (std::uint64_t(byCell[k].cell) + 1) << 32 | k;
    }
}

// The first of ws.moversByCell in a cell of [first, last]; moversByCell.size() if none.
std::uint32_t firstMoverIn(const Workspace& ws, std::uint32_t first, std::uint32_t last) {
    const std::size_t mask = ws.moverCells.size() - 1;
    for (std::uint32_t cell = first; cell <= last; ++cell) {
        for (std::size_t slot = cell & mask; ws.moverCells[slot] != 0; slot = (slot + 1) & mask) {
            if (ws.moverCells[slot] >> 32 == std::uint64_t(cell) + 1) return std::uint32_t(ws.moverCells[slot]);
        }
    }
    return std::uint32_t(ws.moversByCell.size());
}

// The movers' pairs with each other: ws.moversByCell (sorted by the build grid's cell they
// are in now, then by number) from `range`, each against the movers of the cells around it,
// each pair once. Appends to `out`, returns the distance tests.
std::uint64_t moverPairsWithMovers(const World& world, double margin, const Workspace& ws, Range range,
                                   std::vector<SpherePair>& out) {
    const std::vector<Workspace::MoverInCell>& byCell = ws.moversByCell;
    std::uint64_t tests = 0;
    for (std::uint32_t k = range.begin; k < range.end; ++k) {
        const Workspace::MoverInCell& mover = byCell[k];
        forRowsAround(ws.gridAtBuild, ws.gridAtBuild.cellAt(mover.cell), [&](std::uint32_t first, std::uint32_t last) {
            for (std::uint32_t other = firstMoverIn(ws, first, last); other < byCell.size() && byCell[other].cell <= last;
                 ++other) {
                if (byCell[other].sphere <= mover.sphere) continue;
                ++tests;
                const SpherePair pair{mover.sphere, byCell[other].sphere};
                if (withinReach(world, pair, margin)) out.push_back(pair);
            }
        });
    }
    return tests;
}

}  // namespace

// On several threads each task takes a share of the movers and finds their pairs apart;
// sorted together they are the pairs of one thread (each pair is found once, from one
// mover). The 64k landing pile's 7 000 movers took 4.1 ms a step on one thread, two thirds
// of its broad phase on two.
std::uint64_t findMoverPairs(const World& world, double margin, Workspace& ws, int threads) {
    std::vector<SpherePair>& out = ws.moverPairs;
    using MoverInCell = Workspace::MoverInCell;
    std::vector<MoverInCell>& byCell = ws.moversByCell;
    byCell.clear();
    for (std::uint32_t i : ws.movers) {
        if (finite(world.position[i])) byCell.push_back({ws.gridAtBuild.linear(ws.gridAtBuild.cellOf(world.position[i])), i});
    }
    std::sort(byCell.begin(), byCell.end(), [](const MoverInCell& a, const MoverInCell& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.sphere < b.sphere;
    });
    tableMoverCells(ws);
    threads = std::max(threads, 1);
    const int tasks = threads > 1 ? 4 * threads : 1;
    ws.tasks.resize(std::size_t(tasks));
    std::vector<std::uint64_t> tests(std::size_t(tasks), 0);
    runTasks(threads, tasks, [&](int t) {
        std::vector<SpherePair>& found = ws.tasks[std::size_t(t)].pairs;
        found.clear();
        tests[std::size_t(t)] = moverPairsWithStayers(world, margin, ws, rangeOf(ws.movers.size(), t, tasks), found) +
                                moverPairsWithMovers(world, margin, ws, rangeOf(byCell.size(), t, tasks), found);
    });
    out.clear();
    std::uint64_t total = 0;
    for (int t = 0; t < tasks; ++t) {
        out.insert(out.end(), ws.tasks[std::size_t(t)].pairs.begin(), ws.tasks[std::size_t(t)].pairs.end());
        total += tests[std::size_t(t)];
    }
    std::sort(out.begin(), out.end(), inIndexOrder);
    return total;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace,
                        int threads) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace, threads);
}

}  // namespace physics
