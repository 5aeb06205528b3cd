#include "physics/broad_phase.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

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
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t i = ws.sphereByCell[k];
        ws.cellOrdered[k] = glm::dvec4(world.position[i], world.radius[i]);
    }
}

// The 13 neighbour cells "after" a cell (z, then y, then x): with the cell itself,
// every pair of neighbouring cells is visited exactly once.
constexpr int kForward[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},  {-1, -1, 1},
                                 {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},  {1, 0, 1},
                                 {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};

bool withinReach(const glm::dvec4& a, const glm::dvec4& b, double margin) {
    const double reach = a.w + b.w + margin;
    const glm::dvec3 delta = glm::dvec3(a) - glm::dvec3(b);
    return glm::dot(delta, delta) <= reach * reach;
}

// Tests the spheres at cell-ordered positions [a0, a1) against [b0, b1).
std::uint64_t testRange(Workspace& ws, std::uint32_t a0, std::uint32_t a1, std::uint32_t b0,
                        std::uint32_t b1, bool sameCell, double margin) {
    std::uint64_t tests = 0;
    for (std::uint32_t a = a0; a < a1; ++a) {
        for (std::uint32_t b = sameCell ? a + 1 : b0; b < b1; ++b) {
            ++tests;
            if (!withinReach(ws.cellOrdered[a], ws.cellOrdered[b], margin)) continue;
            const std::uint32_t i = ws.sphereByCell[a], j = ws.sphereByCell[b];
            ws.unorderedPairs.push_back({std::min(i, j), std::max(i, j)});
        }
    }
    return tests;
}

std::uint64_t scanCells(const GridShape& grid, double margin, Workspace& ws) {
    std::uint64_t tests = 0;
    for (int z = 0; z < grid.dims.z; ++z) {
        for (int y = 0; y < grid.dims.y; ++y) {
            for (int x = 0; x < grid.dims.x; ++x) {
                const std::uint32_t c = grid.linear({x, y, z});
                const std::uint32_t a0 = ws.cellStart[c], a1 = ws.cellStart[c + 1];
                if (a0 == a1) continue;
                tests += testRange(ws, a0, a1, a0, a1, true, margin);
                for (const auto& d : kForward) {
                    const glm::ivec3 n(x + d[0], y + d[1], z + d[2]);
                    if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
                        glm::any(glm::greaterThanEqual(n, grid.dims))) continue;
                    const std::uint32_t cn = grid.linear(n);
                    tests += testRange(ws, a0, a1, ws.cellStart[cn], ws.cellStart[cn + 1], false, margin);
                }
            }
        }
    }
    return tests;
}

// Puts the pairs in the lecture's loop order (i, then j) with a counting sort by i
// and a short sort of each i's few partners.
void orderByIndex(std::size_t sphereCount, Workspace& ws) {
    ws.pairStart.assign(sphereCount + 1, 0);
    for (const SpherePair& p : ws.unorderedPairs) ++ws.pairStart[p.i + 1];
    for (std::size_t i = 0; i < sphereCount; ++i) ws.pairStart[i + 1] += ws.pairStart[i];
    ws.pairs.resize(ws.unorderedPairs.size());
    for (const SpherePair& p : ws.unorderedPairs) ws.pairs[ws.pairStart[p.i]++] = p;
    auto begin = ws.pairs.begin();
    for (std::size_t i = 0; i < sphereCount; ++i) {  // pairStart[i] now ends sphere i's run
        const auto end = ws.pairs.begin() + ws.pairStart[i];
        std::sort(begin, end, [](const SpherePair& a, const SpherePair& b) { return a.j < b.j; });
        begin = end;
    }
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

std::uint64_t findPairsGrid(const World& world, double margin, Workspace& workspace) {
    workspace.pairs.clear();
    if (world.size() < 2) return 0;
    const GridShape grid = chooseGrid(world, margin);
    sortByCell(world, grid, workspace);
    workspace.unorderedPairs.clear();
    const std::uint64_t tests = scanCells(grid, margin, workspace);
    orderByIndex(world.size(), workspace);
    return tests;
}

std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace) {
    if (kind == BroadPhase::AllPairs) return findPairsAllPairs(world, margin, workspace.pairs);
    return findPairsGrid(world, margin, workspace);
}

}  // namespace physics
