#pragma once
// A scene is the data a lecture slide needs: a box of planes, spheres (given
// one by one or generated), the solver parameters and a seed. buildWorld turns
// it into the physics::World the solver advances. Units: SI (m, s, kg), z up.
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/params.h"
#include "physics/world.h"

namespace scenes {

// A scene that cannot be built or read. For scene files what() is one line
// "file:line:col: what is wrong"; path() is the JSON pointer of the offending
// value ("/spheres/3/p") when the error comes from buildWorld, else empty.
class SceneError : public std::runtime_error {
  public:
    explicit SceneError(const std::string& what, std::string path = {})
        : std::runtime_error(what), path_(std::move(path)) {}
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

// The box: x in [-sx/2, sx/2], y in [-sy/2, sy/2], z in [0, sz], floor at z = 0,
// tilted by `tilt` degrees (right-handed about +y) around its centre (0, 0, sz/2).
struct Box {
    glm::dvec3 size{2.0, 2.0, 2.0};  // m
    double tilt = 0.0;               // degrees
};

// The most spheres one generator may make (the "count" parameter's maximum).
constexpr int kMaxGeneratedCount = 1000000;

// One sphere given explicitly.
struct Sphere {
    glm::dvec3 p{0.0};  // m, centre
    glm::dvec3 v{0.0};  // m/s
    double r = 0.05;    // m, > 0
    double m = 1.0;     // kg, > 0
};

enum class GeneratorKind {
    Lattice,  // a cubic lattice of spacing 2 rmax (1 + gap), tiny seeded jitter
    Random,   // uniform positions, rejection of any overlap
};

// How a generated sphere gets its mass.
enum class MassRule {
    Density,  // m = density * 4/3 pi r^3
    Fixed,    // m = mass, whatever the radius
};

// `count` spheres placed so that each lies wholly inside the region
// (centres in [min + r, max - r]) and clear of every plane and sphere before it.
struct Generator {
    GeneratorKind kind = GeneratorKind::Random;
    int count = 0;
    glm::dvec3 regionMin{-0.5, -0.5, 0.0};  // m
    glm::dvec3 regionMax{0.5, 0.5, 1.0};    // m
    double radiusMin = 0.05;                // m; radius uniform in [radiusMin, radiusMax]
    double radiusMax = 0.05;                // m; equal to radiusMin: a fixed radius
    MassRule massRule = MassRule::Density;
    double density = 1000.0;            // kg/m^3, with MassRule::Density
    double mass = 1.0;                  // kg, with MassRule::Fixed
    glm::dvec3 velocity{0.0};           // m/s, mean velocity
    double velocitySpread = 0.0;        // m/s: each component uniform in mean +- spread
    std::optional<std::uint64_t> seed;  // else derived from the scene seed (generatorSeed)
};

struct Scene {
    std::string title;
    std::string slide;        // which lecture slide it illustrates, e.g. "Rigid spheres 4/14"
    std::string description;  // 1-2 sentences for the UI: what to look at, which slider to move
    std::optional<Box> box;   // none: no walls but the extra planes
    std::vector<physics::Plane> planes;  // extra planes, unit normals pointing into the free side
    physics::Params params;
    std::uint64_t seed = 1;
    std::vector<Sphere> spheres;
    std::vector<Generator> generators;
    // A saved state (a file with "time") resumes its clock; its contacts may
    // overlap a little, so buildWorld only refuses gross overlaps for it.
    bool snapshot = false;
    double time = 0.0;            // s, world.time at the start
    std::uint64_t stepCount = 0;  // solver steps already taken (world.stepCount)
};

// The six walls of the box, inward unit normals, in the order
// floor (z = 0), ceiling, -x, +x, -y, +y, tilted about the box centre.
std::vector<physics::Plane> boxPlanes(const Box& box);

// The seed generator `index` uses when it has none of its own.
std::uint64_t generatorSeed(std::uint64_t sceneSeed, std::size_t index);

// Box planes first (world.boxPlaneCount), then the extra planes; explicit
// spheres, then generated ones; world.seed = scene.seed. Deterministic.
// Throws SceneError (with path()) for a sphere outside the box, two spheres
// overlapping, a region outside the box or too small for its count.
physics::World buildWorld(const Scene& scene);

}  // namespace scenes
