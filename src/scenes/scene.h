#pragma once
// A scene is the data a lecture slide needs: a box of planes, spheres (given
// one by one or generated), the solver parameters and a seed. buildWorld turns
// it into the physics::World the solver advances. Units: SI (m, s, kg), z up.
#include <cstdint>
#include <iterator>
#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/params.h"
#include "physics/world.h"
#include "scenes/claims.h"

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

// The course's emitter ("rain into the cube"): one sphere every `period` seconds at
// `position`. Emission k (0-based) is due at time (k + 1) period; it is placed only
// where it overlaps no sphere and no plane, else it waits for a later step. Its radius
// and velocity are drawn from the scene seed, the emitter's index and k, so the same
// scene rains the same way. See emitDue.
struct Emitter {
    double period = 0.5;                 // s, T (the "emit_period" parameter for the first one)
    glm::dvec3 position{0.0, 0.0, 1.5};  // m, centre of every new sphere
    glm::dvec3 velocity{0.0};            // m/s, mean velocity of a new sphere
    double spread = 0.0;                 // m/s: each component uniform in mean +- spread
    double radiusMin = 0.05;             // m; radius uniform in [radiusMin, radiusMax]
    double radiusMax = 0.05;             // m
    MassRule massRule = MassRule::Density;
    double density = 1000.0;  // kg/m^3, with MassRule::Density
    double mass = 1.0;        // kg, with MassRule::Fixed
    int max = 100;            // spheres it emits at most, in [0, kMaxGeneratedCount]
    int emitted = 0;          // already emitted when the scene starts (a saved state), <= max
};

// A box of space, m: min below max on every axis.
struct Region {
    glm::dvec3 min{0.0};  // m
    glm::dvec3 max{0.0};  // m
};

// The spheres' colourings by name, in render::ColorBy's order (a scene's "color_by", the
// page's links, capture's --color-by).
constexpr const char* kColorByNames[] = {"id", "speed", "contact", "penetration"};
// What each colouring's colours mean, in one line, in the same order (render/palette.cpp
// draws them; the speed scale tops at snapshotSpheres' 3 m/s): under the window's readouts
// and the page's "Colour by". "" for id, where each sphere simply has its own.
constexpr const char* kColorByLegends[] = {
    "",
    "dark purple at rest, teal 1.5 m/s, yellow 3 m/s and faster",
    "blue free, orange a bounce (faster than \u03b5), green a static contact (slide 13)",
    "each sphere's deepest overlap: dark \u2264 0.01 %, blue 0.1 %, green 1 %, yellow \u2265 10 % of r"};
static_assert(std::size(kColorByLegends) == std::size(kColorByNames));

// The time scale's range (the window's slider, a scene's "time_scale").
constexpr double kTimeScaleRange[2] = {0.01, 4.0};

// How the camera opens, and where C puts it back (key "camera"): its angles, and the
// region it fits. Slide 14's presets look straight at their mirror plane, so that a
// symmetric answer looks symmetric, and frame the slab of the box their spheres move in,
// so that four views on a projector draw them larger than the whole box would and none
// leaves a view (the box stays drawn; the wheel zooms out).
struct SceneCamera {
    std::optional<double> azimuthDeg;    // deg, around +z from +x; none: the three-quarter view's
    std::optional<double> elevationDeg;  // deg, above the xy plane, |el| <= 88; none: the default
    std::optional<Region> fits;          // none: the box (or the spheres, without one)
};

struct Scene {
    std::string title;
    std::string slide;        // which lecture slide it illustrates, e.g. "Rigid spheres 4/14"
    std::string description;  // 1-2 sentences for the UI: what to look at, which slider to move
    // Spheres the description's figures were measured with: builtSphereCount as the file
    // gave it (0: a scene built in code, nothing measured).
    std::size_t textCount = 0;
    std::optional<Box> box;   // none: no walls but the extra planes
    std::vector<physics::Plane> planes;  // extra planes, unit normals pointing into the free side
    // Mirror planes the scene is symmetric in (key "mirror"): the demo measures how far
    // the state drifts from its mirror image (Smith et al.'s symmetry, slide 14).
    std::vector<physics::Plane> mirrors;
    SceneCamera camera;
    // "time_scale": the simulated seconds per real second the window and the page open the
    // scene at (below 1: slow motion, for an impact over in a fraction of a second); capture
    // and simulate count simulated time and ignore it.
    double timeScale = 1.0;
    // "paused": the window and the page open it paused at its start, for a lesson in its first
    // step (16-20 start touching: the impact is over before the class has looked).
    bool opensPaused = false;
    // "color_by": the colouring the window and the page open it with, a kColorByNames index
    // (-1: the viewer's own). 21 and 22 open coloured by penetration: their stacks, sunk in
    // by 0.02 to 19 % of r, look alike in the other colourings.
    int colorBy = -1;
    physics::Params params;
    std::uint64_t seed = 1;
    std::vector<Sphere> spheres;
    std::vector<Generator> generators;
    std::vector<Emitter> emitters;
    std::vector<Claim> claims;  // what the texts say, as the lab-sheet test checks it (claims.h)
    // Side by side on opening: the overrides of the other views, as --compare takes them
    // ("method=position,reflection,continuous"; overrides.h). Empty: one view.
    std::vector<std::string> compare;
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

// `text` (a title) with each "{count}" replaced by builtSphereCount: a preset's title that
// names its count stays true when --set count= changes it.
std::string withCount(std::string text, const Scene& scene);

// The description as the class reads it: withCount's, and where the count has changed since
// the file (textCount), a last sentence says the count its figures were measured with (06's
// and 11's figures hold at their own count only: the pile of 3000 overlaps 2.3 % of r, not
// under 1.2 %).
std::string describedText(const Scene& scene);

// How many spheres buildWorld places: the explicit ones and every generator's count.
// The spheres after them in a world are the emitted ones, in the order of emission.
std::size_t builtSphereCount(const Scene& scene);

// For each of scene.emitters, how many spheres it has emitted into `world` built from
// `scene`: world.emitted, which buildWorld starts at each emitter's `emitted` and emitDue
// advances. Emissions are taken in the order they fall due, (k + 1) period, ties by
// emitter index; an emission that cannot be placed holds back the later ones.
std::vector<int> emittedCounts(const Scene& scene, const physics::World& world);

// The emitters' step: call after each time step (physics::step). Adds, at world.time,
// every emission that is due and can be placed without overlap; one that cannot waits
// for a later step (so after t seconds an emitter has emitted floor(t / T) spheres, fewer
// while its spot is taken or once it reaches max). Deterministic. Returns the number added.
int emitDue(const Scene& scene, physics::World& world);

}  // namespace scenes
