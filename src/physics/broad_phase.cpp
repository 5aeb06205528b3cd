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

// Counting sort: sphereByCell lists sphere indices cell by cell, ascending within a cell.
void sortByCell(const World& world, const GridShape& grid, Workspace& ws) {
    const std::size_t n = world.size();
    const std::size_t cellCount = static_cast<std::size_t>(grid.dims.x) * grid.dims.y * grid.dims.z;
    ws.cellOfSphere.resize(n);
    ws.cellStart.assign(cellCount + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        ws.cellOfSphere[i] = finite(world.position[i]) ? grid.linear(grid.cellOf(world.position[i])) : 0;
        ++ws.cellStart[ws.cellOfSphere[i] + 1];
    }
    for (std::size_t c = 0; c < cellCount; ++c) ws.cellStart[c + 1] += ws.cellStart[c];
    ws.sphereByCell.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        ws.sphereByCell[ws.cellStart[ws.cellOfSphere[i]]++] = static_cast<std::uint32_t>(i);
    }
    // Filling advanced each start to the next cell's: shift back.
    for (std::size_t c = cellCount; c > 0; --c) ws.cellStart[c] = ws.cellStart[c - 1];
    ws.cellStart[0] = 0;
    ws.cellOrdered.resize(n);
    ws.slotOfSphere.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = ws.sphereByCell[k];
        ws.cellOrdered[k] = glm::dvec4(world.position[i], world.radius[i]);
        ws.slotOfSphere[i] = static_cast<std::uint32_t>(k);
    }
}

bool withinReach(const glm::dvec4& a, const glm::dvec4& b, double margin) {
    const double reach = a.w + b.w + margin;
    const glm::dvec3 delta = glm::dvec3(a) - glm::dvec3(b);
    return glm::dot(delta, delta) <= reach * reach;
}

// Appends the pairs (i, j > i) within reach of sphere i, sorted by j, and returns
// the distance tests made. The 27 cells around i's are 9 runs of 3 cells along x,
// each one contiguous range of the cell-sorted spheres. The tests are written
// without branches (about half the candidates have j < i, a few are in reach:
// branches on either would be mispredicted), into `partners`, which only grows.
std::uint64_t pairsOf(std::uint32_t i, const GridShape& grid, double margin, const Workspace& ws,
                      std::vector<std::uint32_t>& partners, std::vector<SpherePair>& out) {
    const glm::dvec4 sphere = ws.cellOrdered[ws.slotOfSphere[i]];
    const glm::ivec3 c = grid.cellOf(glm::dvec3(sphere));
    const int x0 = std::max(c.x - 1, 0), x1 = std::min(c.x + 1, grid.dims.x - 1);
    std::uint32_t runStart[9], runEnd[9];
    int runs = 0;
    std::size_t candidates = 0;
    for (int z = std::max(c.z - 1, 0); z <= std::min(c.z + 1, grid.dims.z - 1); ++z) {
        for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, grid.dims.y - 1); ++y) {
            runStart[runs] = ws.cellStart[grid.linear({x0, y, z})];
            runEnd[runs] = ws.cellStart[grid.linear({x1, y, z}) + 1];
            candidates += runEnd[runs] - runStart[runs];
            ++runs;
        }
    }
    if (partners.size() < candidates) partners.resize(candidates);
    std::uint32_t* found = partners.data();
    std::size_t count = 0;
    std::uint64_t tests = 0;
    for (int run = 0; run < runs; ++run) {
        for (std::uint32_t k = runStart[run]; k < runEnd[run]; ++k) {
            const std::uint32_t j = ws.sphereByCell[k];
            const bool after = j > i;
            tests += after;
            found[count] = j;
            count += after & withinReach(sphere, ws.cellOrdered[k], margin);
        }
    }
    std::sort(found, found + count);
    for (std::size_t k = 0; k < count; ++k) out.push_back({i, found[k]});
    return tests;
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
    const GridShape grid = chooseGrid(world, margin);
    sortByCell(world, grid, workspace);
    // Each task finds the pairs of one range of first spheres i, in index order, so
    // that their concatenation is in index order whatever the number of tasks.
    const int tasks = threads > 1 ? 4 * threads : 1;
    workspace.tasks.resize(std::size_t(tasks));
    std::vector<std::uint64_t> tests(std::size_t(tasks), 0);
    runTasks(threads, tasks, [&](int t) {
        TaskScratch& scratch = workspace.tasks[std::size_t(t)];
        scratch.pairs.clear();
        const Range range = rangeOf(n, t, tasks);
        std::uint64_t made = 0;
        for (std::uint32_t i = range.begin; i < range.end; ++i) made += pairsOf(i, grid, margin, workspace, scratch.partners, scratch.pairs);
        tests[std::size_t(t)] = made;
    });
    std::uint64_t total = 0;
    for (int t = 0; t < tasks; ++t) {
        const std::vector<SpherePair>& part = workspace.tasks[std::size_t(t)].pairs;
        workspace.pairs.insert(workspace.pairs.end(), part.begin(), part.end());
        total += tests[std::size_t(t)];
    }
    return total;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace,
                        int threads) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace, threads);
}

}  // namespace physics
