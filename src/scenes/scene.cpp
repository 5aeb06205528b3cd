#include "scenes/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

#include "physics/random.h"
#include "scenes/generate.h"
#include "scenes/parameters.h"

namespace scenes {

namespace {

constexpr double kPi = 3.14159265358979323846;
// An authored scene's spheres may touch (up to rounding), never overlap.
constexpr double kTouching = 1e-9;
// m/s: the fastest a scene file may start a sphere (its mean plus its spread). 13 shoots at
// 100 m/s; a sphere at 1e160 m/s made the energy overflow to inf with no value to name.
constexpr double kMostSceneSpeed = 1000.0;
// m/s: a saved state's, as fast as a run made it (a scene file's numbers stop at 1e9).
constexpr double kMostSavedSpeed = 1e9;

[[noreturn]] void fail(const std::string& what, const std::string& path) {
    throw SceneError(what, path);
}

std::string text(const glm::dvec3& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

std::string number(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

// m/s, without overflow (glm::length of 1e160 m/s is inf).
double speedOf(const glm::dvec3& v) { return std::hypot(v.x, std::hypot(v.y, v.z)); }

// Fails with `what` "speed ... is above 1000 m/s" when `speed` is above `most`.
void checkSpeed(double speed, const std::string& what, const std::string& path, double most = kMostSceneSpeed) {
    if (speed > most) fail(what + " " + number(speed) + " m/s is above " + number(most) + " m/s", path);
}

std::string sphereName(std::size_t i) { return "spheres[" + std::to_string(i) + "]"; }
std::string spherePath(std::size_t i, const char* key) {
    return "/spheres/" + std::to_string(i) + "/" + key;
}
std::string generatorName(std::size_t i) { return "generate[" + std::to_string(i) + "]"; }
std::string generatorPath(std::size_t i, const char* key) {
    return "/generate/" + std::to_string(i) + "/" + key;
}

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Right-handed rotation of v by `degrees` about the +y axis.
glm::dvec3 tiltAboutY(const glm::dvec3& v, double degrees) {
    const double a = degrees * kPi / 180.0;
    return {std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z};
}

void addBox(const Scene& scene, physics::World& world) {
    if (!scene.box) return;
    const Box& box = *scene.box;
    if (!isFinite(box.size) || box.size.x <= 0 || box.size.y <= 0 || box.size.z <= 0) {
        fail("box size " + text(box.size) + " must be positive in every direction", "/box/size");
    }
    if (!std::isfinite(box.tilt)) fail("box tilt must be a finite angle", "/box/tilt");
    world.planes = boxPlanes(box);
    world.boxPlaneCount = static_cast<int>(world.planes.size());
}

void addExtraPlanes(const Scene& scene, physics::World& world) {
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        const physics::Plane& plane = scene.planes[k];
        const std::string at = "/planes/" + std::to_string(k);
        if (!isFinite(plane.point)) {
            fail("planes[" + std::to_string(k) + "] point must be finite", at + "/point");
        }
        const auto normal = detail::unitNormal(plane.normal);
        if (!normal) fail("planes[" + std::to_string(k) + "] has a zero normal", at + "/normal");
        if (!(plane.thickness >= 0) || !std::isfinite(plane.thickness)) {
            fail("planes[" + std::to_string(k) + "] thickness must be finite and >= 0 (m), got " +
                     number(plane.thickness),
                 at + "/thickness");
        }
        world.planes.push_back({plane.point, *normal, plane.thickness});
    }
}

// A saved state's spheres may be as fast as the run made them (a fall of 25 s at 50 m/s²
// reaches 1250 m/s, and its save must load again); a scene's start may not.
void checkSphere(const Sphere& s, std::size_t i, bool snapshot) {
    if (!isFinite(s.p)) fail(sphereName(i) + " position must be finite", spherePath(i, "p"));
    if (!isFinite(s.v)) fail(sphereName(i) + " velocity must be finite", spherePath(i, "v"));
    checkSpeed(speedOf(s.v), sphereName(i) + " speed |v| =", spherePath(i, "v"), snapshot ? kMostSavedSpeed : kMostSceneSpeed);
    if (!(s.r > 0) || !std::isfinite(s.r)) {
        fail(sphereName(i) + " radius must be positive (m), got " + number(s.r),
             spherePath(i, "r"));
    }
    if (!(s.m > 0) || !std::isfinite(s.m)) {
        fail(sphereName(i) + " mass must be positive (kg), got " + number(s.m), spherePath(i, "m"));
    }
}

// A saved state (scene.snapshot) is built as it was saved, whatever its overlaps and
// wherever its spheres are: the velocity method sinks 09's column into itself (a sphere
// inside the one below), response-only lets 01's ball through the floor, and the file must
// still give the same future when loaded.
void addExplicitSpheres(const Scene& scene, detail::OccupancyGrid& grid, physics::World& world) {
    const double slack = kTouching;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        checkSphere(s, i, scene.snapshot);
        if (scene.snapshot) {
            world.addSphere(s.p, s.v, s.r, s.m);
            continue;
        }
        if (const auto k = detail::crossedPlane(world.planes, s.p, s.r, slack)) {
            const bool wall = *k < static_cast<std::size_t>(world.boxPlaneCount);
            fail(sphereName(i) + " at " + text(s.p) + " with radius " + number(s.r) + " m " +
                     (wall ? "is outside the box: it crosses " : "crosses ") +
                     detail::planeName(*k, world.boxPlaneCount),
                 spherePath(i, "p"));
        }
        if (const auto j = grid.overlapping(s.p, s.r, slack)) {
            fail(sphereName(i) + " at " + text(s.p) + " overlaps " + sphereName(*j) + " at " +
                     text(scene.spheres[*j].p),
                 spherePath(i, "p"));
        }
        grid.add(s.p, s.r);
        world.addSphere(s.p, s.v, s.r, s.m);
    }
}

void checkGeneratorValues(const Generator& g, std::size_t i) {
    const std::string name = generatorName(i);
    if (g.count < 0 || g.count > kMaxGeneratedCount) {
        fail(name + " count " + std::to_string(g.count) + " is out of range [0, " +
                 std::to_string(kMaxGeneratedCount) + "]",
             generatorPath(i, "count"));
    }
    if (!(g.radiusMin > 0) || !(g.radiusMin <= g.radiusMax) || !std::isfinite(g.radiusMax)) {
        fail(name + " radius must be positive with min <= max (m)", generatorPath(i, "radius"));
    }
    if (g.massRule == MassRule::Density && (!(g.density > 0) || !std::isfinite(g.density))) {
        fail(name + " density must be positive (kg/m^3)", generatorPath(i, "density"));
    }
    if (g.massRule == MassRule::Fixed && (!(g.mass > 0) || !std::isfinite(g.mass))) {
        fail(name + " mass must be positive (kg)", generatorPath(i, "mass"));
    }
    if (!isFinite(g.velocity)) {
        fail(name + " velocity must be finite", generatorPath(i, "velocity"));
    }
    if (!(g.velocitySpread >= 0) || !std::isfinite(g.velocitySpread)) {
        fail(name + " velocitySpread must be >= 0 (m/s)", generatorPath(i, "velocitySpread"));
    }
    checkSpeed(speedOf(g.velocity) + std::sqrt(3.0) * g.velocitySpread, name + " fastest speed",
               generatorPath(i, "velocity"));
}

void checkRegion(const Generator& g, std::size_t i, const physics::World& world) {
    const std::string name = generatorName(i);
    const glm::dvec3 extent = g.regionMax - g.regionMin;
    if (!isFinite(g.regionMin) || !isFinite(g.regionMax)) {
        fail(name + " region must be finite", generatorPath(i, "region"));
    }
    if (std::min({extent.x, extent.y, extent.z}) < 2.0 * g.radiusMax) {
        fail(name + " region " + text(g.regionMin) + " - " + text(g.regionMax) +
                 " is narrower than one sphere of radius " + number(g.radiusMax) + " m",
             generatorPath(i, "region"));
    }
    // The box is convex: the region is inside when its eight corners are (1e-9 m rounding).
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 c{corner & 1 ? g.regionMax.x : g.regionMin.x,
                           corner & 2 ? g.regionMax.y : g.regionMin.y,
                           corner & 4 ? g.regionMax.z : g.regionMin.z};
        for (int k = 0; k < world.boxPlaneCount; ++k) {
            const physics::Plane& wall = world.planes[static_cast<std::size_t>(k)];
            if (glm::dot(c - wall.point, wall.normal) >= -1e-9) continue;
            fail(name + " region corner " + text(c) + " is outside the box (beyond " +
                     detail::planeName(static_cast<std::size_t>(k), world.boxPlaneCount) + ")",
                 generatorPath(i, "region"));
        }
    }
}

std::string emitterName(std::size_t i) { return "emitters[" + std::to_string(i) + "]"; }
std::string emitterPath(std::size_t i, const char* key) {
    return "/emitters/" + std::to_string(i) + "/" + key;
}

// Every value in range, and the largest sphere it emits inside the box, clear of every plane.
void checkEmitter(const Emitter& e, std::size_t i, const physics::World& world) {
    const std::string name = emitterName(i);
    const Parameter& period = *findParameter("emit_period");
    if (!(e.period >= period.min && e.period <= period.max)) {
        fail(name + " period = " + number(e.period) + " is out of range [" +
                 formatNumber(period.min) + ", " + formatNumber(period.max) + "] s",
             emitterPath(i, "period"));
    }
    if (!isFinite(e.position)) fail(name + " position must be finite", emitterPath(i, "position"));
    if (!isFinite(e.velocity)) fail(name + " velocity must be finite", emitterPath(i, "velocity"));
    if (!(e.spread >= 0) || !std::isfinite(e.spread)) {
        fail(name + " spread must be >= 0 (m/s)", emitterPath(i, "spread"));
    }
    checkSpeed(speedOf(e.velocity) + std::sqrt(3.0) * e.spread, name + " fastest speed", emitterPath(i, "velocity"));
    if (!(e.radiusMin > 0) || !(e.radiusMin <= e.radiusMax) || !std::isfinite(e.radiusMax)) {
        fail(name + " radius must be positive with min <= max (m)", emitterPath(i, "radius"));
    }
    if (e.massRule == MassRule::Density && (!(e.density > 0) || !std::isfinite(e.density))) {
        fail(name + " density must be positive (kg/m^3)", emitterPath(i, "density"));
    }
    if (e.massRule == MassRule::Fixed && (!(e.mass > 0) || !std::isfinite(e.mass))) {
        fail(name + " mass must be positive (kg)", emitterPath(i, "mass"));
    }
    if (e.max < 0 || e.max > kMaxGeneratedCount) {
        fail(name + " max " + std::to_string(e.max) + " is out of range [0, " +
                 std::to_string(kMaxGeneratedCount) + "]",
             emitterPath(i, "max"));
    }
    if (e.emitted < 0 || e.emitted > e.max) {
        fail(name + " emitted " + std::to_string(e.emitted) +
                 " is out of range [0, max = " + std::to_string(e.max) + "]",
             emitterPath(i, "emitted"));
    }
    if (const auto k = detail::crossedPlane(world.planes, e.position, e.radiusMax, 0.0)) {
        fail(name + " at " + text(e.position) + " cannot hold a sphere of radius " +
                 number(e.radiusMax) + " m: it crosses " +
                 detail::planeName(*k, world.boxPlaneCount),
             emitterPath(i, "position"));
    }
}

// m: no two spheres of the scene overlap unless their centres are this close.
double largestDiameter(const Scene& scene) {
    double r = 0.0;
    for (const Sphere& s : scene.spheres) r = std::max(r, s.r);
    for (const Generator& g : scene.generators) r = std::max(r, g.radiusMax);
    for (const Emitter& e : scene.emitters) r = std::max(r, e.radiusMax);
    return std::max(2.0 * r, 1e-6);
}

}  // namespace

std::vector<physics::Plane> boxPlanes(const Box& box) {
    const glm::dvec3 half = 0.5 * box.size;  // m
    const glm::dvec3 centre{0.0, 0.0, half.z};
    const std::array<physics::Plane, 6> upright = {{
        {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}},          // floor
        {{0.0, 0.0, box.size.z}, {0.0, 0.0, -1.0}},  // ceiling
        {{-half.x, 0.0, half.z}, {1.0, 0.0, 0.0}},   // -x wall
        {{half.x, 0.0, half.z}, {-1.0, 0.0, 0.0}},   // +x wall
        {{0.0, -half.y, half.z}, {0.0, 1.0, 0.0}},   // -y wall
        {{0.0, half.y, half.z}, {0.0, -1.0, 0.0}},   // +y wall
    }};
    std::vector<physics::Plane> planes;
    for (const physics::Plane& plane : upright) {
        planes.push_back({centre + tiltAboutY(plane.point - centre, box.tilt),
                          tiltAboutY(plane.normal, box.tilt)});
    }
    return planes;
}

std::uint64_t generatorSeed(std::uint64_t sceneSeed, std::size_t index) {
    physics::Random mix(sceneSeed ^ (0xD1B54A32D192ED03ull * (index + 1)));
    return mix.next();
}

physics::World buildWorld(const Scene& scene) {
    physics::World world;
    addBox(scene, world);
    addExtraPlanes(scene, world);
    detail::OccupancyGrid grid(largestDiameter(scene));
    addExplicitSpheres(scene, grid, world);
    for (std::size_t i = 0; i < scene.generators.size(); ++i) {
        const Generator& g = scene.generators[i];
        checkGeneratorValues(g, i);
        checkRegion(g, i, world);
        detail::generate(g, i, g.seed ? *g.seed : generatorSeed(scene.seed, i), grid, world);
    }
    for (std::size_t i = 0; i < scene.emitters.size(); ++i) {
        checkEmitter(scene.emitters[i], i, world);
    }
    world.seed = scene.seed;
    for (const Emitter& e : scene.emitters) world.emitted.push_back(std::clamp(e.emitted, 0, e.max));
    world.time = scene.time;
    world.stepCount = scene.stepCount;
    return world;
}

std::size_t builtSphereCount(const Scene& scene) {
    std::size_t count = scene.spheres.size();
    for (const Generator& g : scene.generators)
        count += static_cast<std::size_t>(std::max(g.count, 0));
    return count;
}

namespace {

std::string replaceCount(std::string text, std::size_t spheres) {
    const std::string count = std::to_string(spheres);
    for (std::size_t at = text.find("{count}"); at != std::string::npos; at = text.find("{count}", at + count.size())) {
        text.replace(at, 7, count);
    }
    return text;
}

}  // namespace

std::string withCount(std::string text, const Scene& scene) { return replaceCount(std::move(text), builtSphereCount(scene)); }

std::string describedText(const Scene& scene) {
    const std::size_t now = builtSphereCount(scene);
    std::string text = replaceCount(scene.description, now);
    if (scene.textCount != 0 && now != scene.textCount && !text.empty()) {
        text += " (The figures in this text were measured with " + std::to_string(scene.textCount) +
                " spheres; this run has " + std::to_string(now) + ".)";
    }
    return text;
}

}  // namespace scenes
