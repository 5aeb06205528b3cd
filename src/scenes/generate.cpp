#include "scenes/generate.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <sstream>

#include "physics/random.h"

namespace scenes::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Lattice spacing 2 rmax (1 + gap); jitter small enough that neighbours never touch.
constexpr double kLatticeGap = 0.02;
constexpr double kLatticeJitter = 0.25 * kLatticeGap;  // times rmax, per component
// A lattice looks at no more sites than this.
constexpr std::int64_t kMaxLatticeSites = 100000000;
// Random placement gives up on a sphere after this many rejected positions.
constexpr int kMaxAttempts = 10000;
// No packing of equal spheres is denser than this (Kepler).
constexpr double kDensestPacking = 0.7405;
// Random placement (random sequential addition) jams near 38 % of the volume, and long
// before it each sphere takes thousands of tries: 100 000 spheres at 32 % took 43 s, a
// million 12 minutes before giving up. It is refused above this share of the region.
constexpr double kRandomFillLimit = 0.30;
// Generated spheres may touch, never overlap (relative to the smaller radius).
constexpr double kTouching = 1e-9;

std::string prefix(std::size_t index) { return "generate[" + std::to_string(index) + "]: "; }

std::string path(std::size_t index, const char* key) {
    return "/generate/" + std::to_string(index) + "/" + key;
}

std::string metres(double value) {
    std::ostringstream out;
    out << value << " m";
    return out.str();
}

glm::dvec3 uniformVector(physics::Random& random, double spread) {
    const double x = random.uniform(-spread, spread);
    const double y = random.uniform(-spread, spread);
    const double z = random.uniform(-spread, spread);
    return {x, y, z};
}

// Adds one generated sphere: its velocity and mass come from the generator.
void place(const Generator& g, physics::Random& random, const glm::dvec3& p, double r,
           OccupancyGrid& grid, physics::World& world) {
    const glm::dvec3 v = g.velocity + uniformVector(random, g.velocitySpread);
    const double m =
        g.massRule == MassRule::Density ? g.density * 4.0 / 3.0 * kPi * r * r * r : g.mass;
    grid.add(p, r);
    world.addSphere(p, v, r, m);
}

bool isClear(const physics::World& world, const OccupancyGrid& grid, const glm::dvec3& p,
             double r) {
    return !crossedPlane(world.planes, p, r, kTouching) && !grid.overlapping(p, r, kTouching);
}

// The cubic lattice: sites at the centres of cells of side s, the block of
// cells centred in the region, filled bottom layer first (z, then y, then x).
// Sites that would overlap a plane or an earlier sphere are skipped.
void generateLattice(const Generator& g, std::size_t index, physics::Random& random,
                     OccupancyGrid& grid, physics::World& world) {
    const double spacing = 2.0 * g.radiusMax * (1.0 + kLatticeGap);  // m
    const double jitter = kLatticeJitter * g.radiusMax;              // m
    const glm::dvec3 extent = g.regionMax - g.regionMin;
    const glm::dvec3 cells = glm::floor(extent / spacing);
    const glm::dvec3 first = g.regionMin + 0.5 * (extent - cells * spacing) + 0.5 * spacing;
    int placed = 0;
    std::int64_t visited = 0;  // bounded, so that a huge region of skipped sites cannot hang
    auto more = [&] { return placed < g.count && visited < kMaxLatticeSites; };
    for (std::int64_t k = 0; k < cells.z && more(); ++k) {
        for (std::int64_t j = 0; j < cells.y && more(); ++j) {
            for (std::int64_t i = 0; i < cells.x && more(); ++i) {
                ++visited;
                const double r = random.uniform(g.radiusMin, g.radiusMax);
                const glm::dvec3 site = first + spacing * glm::dvec3(i, j, k);
                const glm::dvec3 p = site + uniformVector(random, jitter);
                if (!isClear(world, grid, p, r)) continue;
                place(g, random, p, r, grid, world);
                ++placed;
            }
        }
    }
    if (placed < g.count) {
        throw SceneError(prefix(index) + "the region holds only " + std::to_string(placed) +
                             " spheres in a lattice of spacing " + metres(spacing) +
                             " (clear of the planes and other spheres), count is " +
                             std::to_string(g.count),
                         path(index, "count"));
    }
}

// Rejection sampling: a uniform position in the region, kept if it overlaps nothing.
void generateRandom(const Generator& g, std::size_t index, physics::Random& random,
                    OccupancyGrid& grid, physics::World& world) {
    const glm::dvec3 extent = g.regionMax - g.regionMin;
    const double smallest = 4.0 / 3.0 * kPi * std::pow(g.radiusMin, 3);  // m^3
    const std::string cannotHold = "region cannot hold " + std::to_string(g.count) + " spheres";
    const double region = extent.x * extent.y * extent.z;  // m^3
    if (g.count * smallest > kDensestPacking * region) {
        throw SceneError(prefix(index) + cannotHold + ": their volume exceeds " +
                             "the densest packing of the region",
                         path(index, "count"));
    }
    if (g.count * smallest > kRandomFillLimit * region) {
        throw SceneError(prefix(index) + "random placement cannot fill " +
                             std::to_string(int(std::lround(100.0 * g.count * smallest / region))) +
                             " % of the region (it jams near 38 %, and slows long before): at most " +
                             std::to_string(int(100.0 * kRandomFillLimit)) +
                             " %; use kind lattice, a larger region, or fewer or smaller spheres",
                         path(index, "count"));
    }
    for (int placed = 0; placed < g.count; ++placed) {
        const double r = random.uniform(g.radiusMin, g.radiusMax);
        int attempt = 0;
        glm::dvec3 p;
        do {
            if (++attempt > kMaxAttempts) {
                throw SceneError(prefix(index) + cannotHold + ": random placement found room for " +
                                     std::to_string(placed) + " (gave up after " +
                                     std::to_string(kMaxAttempts) +
                                     " tries); enlarge the region or lower count or radius",
                                 path(index, "count"));
            }
            const double x = random.uniform(g.regionMin.x + r, g.regionMax.x - r);
            const double y = random.uniform(g.regionMin.y + r, g.regionMax.y - r);
            const double z = random.uniform(g.regionMin.z + r, g.regionMax.z - r);
            p = {x, y, z};
        } while (!isClear(world, grid, p, r));
        place(g, random, p, r, grid, world);
    }
}

}  // namespace

OccupancyGrid::OccupancyGrid(double cellSize) : cellSize_(cellSize) {}

std::size_t OccupancyGrid::CellHash::operator()(const Cell& c) const {
    std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
}

OccupancyGrid::Cell OccupancyGrid::cellOf(const glm::dvec3& p) const {
    // Clamped so that absurd coordinates cannot overflow the integer cast.
    auto index = [this](double x) {
        return static_cast<std::int64_t>(std::clamp(std::floor(x / cellSize_), -1e15, 1e15));
    };
    return {index(p.x), index(p.y), index(p.z)};
}

void OccupancyGrid::add(const glm::dvec3& p, double r) {
    cells_[cellOf(p)].push_back(centres_.size());
    centres_.push_back(p);
    radii_.push_back(r);
}

std::optional<std::size_t> OccupancyGrid::overlapping(const glm::dvec3& p, double r,
                                                      double allowedFraction) const {
    const Cell c = cellOf(p);
    std::optional<std::size_t> first;
    for (std::int64_t dz = -1; dz <= 1; ++dz) {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const auto cell = cells_.find({c.x + dx, c.y + dy, c.z + dz});
                if (cell == cells_.end()) continue;
                for (std::size_t i : cell->second) {
                    const double depth = r + radii_[i] - glm::distance(p, centres_[i]);  // m
                    const bool deeper = depth > allowedFraction * std::min(r, radii_[i]);
                    if (deeper && (!first || i < *first)) first = i;
                }
            }
        }
    }
    return first;
}

std::optional<std::size_t> crossedPlane(const std::vector<physics::Plane>& planes,
                                        const glm::dvec3& p, double r, double allowedFraction) {
    for (std::size_t k = 0; k < planes.size(); ++k) {
        const physics::Plane face = physics::faceFor(planes[k], p);  // a thin wall's near face
        const double clearance = glm::dot(p - face.point, face.normal) - r;  // m
        if (clearance < -allowedFraction * r) return k;
    }
    return std::nullopt;
}

std::optional<glm::dvec3> unitNormal(const glm::dvec3& n) {
    const double length = glm::length(n);
    if (!std::isfinite(length) || length < 1e-12) return std::nullopt;
    return std::abs(length - 1.0) <= 1e-12 ? n : n / length;
}

std::string planeName(std::size_t index, int boxPlaneCount) {
    static const char* const kWalls[] = {"floor",   "ceiling", "-x wall",
                                         "+x wall", "-y wall", "+y wall"};
    if (index < static_cast<std::size_t>(boxPlaneCount) && index < 6) {
        return std::string("the box's ") + kWalls[index];
    }
    return "planes[" + std::to_string(index - static_cast<std::size_t>(boxPlaneCount)) + "]";
}

void generate(const Generator& generator, std::size_t index, std::uint64_t seed,
              OccupancyGrid& grid, physics::World& world) {
    physics::Random random(seed);
    if (generator.kind == GeneratorKind::Lattice) {
        generateLattice(generator, index, random, grid, world);
    } else {
        generateRandom(generator, index, random, grid, world);
    }
}

}  // namespace scenes::detail
