#include "physics/broad_phase.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace physics {
namespace {

bool withinReach(const World& world, std::uint32_t i, std::uint32_t j, double margin) {
    const double reach = world.radius[i] + world.radius[j] + margin;
    const glm::dvec3 delta = world.position[i] - world.position[j];
    return glm::dot(delta, delta) <= reach * reach;
}

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

GridShape chooseGrid(const World& world, double margin) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : world.position) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    GridShape grid;
    grid.origin = lo;
    grid.cellSize = std::max(2.0 * maxRadius(world) + margin, 1e-9);
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
        ws.cellOfSphere[i] = grid.linear(grid.cellOf(world.position[i]));
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
}

// Pairs (i, j > i) from the 27 cells around sphere i, appended in ascending j.
std::uint64_t pairsAround(const World& world, const GridShape& grid, const Workspace& ws,
                          std::uint32_t i, double margin, std::vector<SpherePair>& pairs) {
    const glm::ivec3 c = grid.cellOf(world.position[i]);
    const glm::ivec3 lo = glm::max(c - 1, glm::ivec3(0));
    const glm::ivec3 hi = glm::min(c + 1, grid.dims - 1);
    const std::size_t first = pairs.size();
    std::uint64_t tests = 0;
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) {
            const std::uint32_t row = grid.linear({0, y, z});
            for (std::uint32_t k = ws.cellStart[row + lo.x]; k < ws.cellStart[row + hi.x + 1]; ++k) {
                const std::uint32_t j = ws.sphereByCell[k];
                if (j <= i) continue;
                ++tests;
                if (withinReach(world, i, j, margin)) pairs.push_back({i, j});
            }
        }
    }
    std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(first), pairs.end(),
              [](const SpherePair& a, const SpherePair& b) { return a.j < b.j; });
    return tests;
}

}  // namespace

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
            if (withinReach(world, i, j, margin)) pairs.push_back({i, j});
        }
    }
    return tests;
}

std::uint64_t findPairsGrid(const World& world, double margin, Workspace& workspace) {
    workspace.pairs.clear();
    if (world.size() < 2) return 0;
    const GridShape grid = chooseGrid(world, margin);
    sortByCell(world, grid, workspace);
    std::uint64_t tests = 0;
    const auto n = static_cast<std::uint32_t>(world.size());
    for (std::uint32_t i = 0; i < n; ++i) tests += pairsAround(world, grid, workspace, i, margin, workspace.pairs);
    return tests;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace);
}

}  // namespace physics
