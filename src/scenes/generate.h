#pragma once
// Internal to spheres_scenes: placing spheres without overlap, for buildWorld.
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "physics/world.h"
#include "scenes/scene.h"

namespace scenes::detail {

// The spheres placed so far, bucketed in cubic cells at least one largest
// diameter wide, so that an overlap test looks at the 27 cells around a centre.
class OccupancyGrid {
  public:
    explicit OccupancyGrid(double cellSize);  // m, >= 2 * the largest radius

    void add(const glm::dvec3& p, double r);
    // The first placed sphere that (p, r) overlaps deeper than
    // allowedFraction * the smaller radius; touching is no overlap.
    std::optional<std::size_t> overlapping(const glm::dvec3& p, double r,
                                           double allowedFraction) const;
    std::size_t size() const { return centres_.size(); }

  private:
    struct Cell {
        std::int64_t x, y, z;
        bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct CellHash {
        std::size_t operator()(const Cell& c) const;
    };
    Cell cellOf(const glm::dvec3& p) const;

    double cellSize_;  // m
    std::vector<glm::dvec3> centres_;
    std::vector<double> radii_;
    std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells_;
};

// The first plane that the sphere (p, r) crosses by more than allowedFraction * r
// (for a thin wall, the face on the side of p).
std::optional<std::size_t> crossedPlane(const std::vector<physics::Plane>& planes,
                                        const glm::dvec3& p, double r, double allowedFraction);

// The unit vector along n; n itself when it is unit to 1e-12 already (so that
// normalising twice changes no bit); nothing for a zero or non-finite n.
std::optional<glm::dvec3> unitNormal(const glm::dvec3& n);

// A name for plane `index` of a world whose first `boxPlaneCount` planes are the box.
std::string planeName(std::size_t index, int boxPlaneCount);

// Adds generator `index`'s spheres to the world (and the grid). Throws SceneError
// with path "/generate/<index>/..." when the region cannot hold them.
void generate(const Generator& generator, std::size_t index, std::uint64_t seed,
              OccupancyGrid& grid, physics::World& world);

}  // namespace scenes::detail
