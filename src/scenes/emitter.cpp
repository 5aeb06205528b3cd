// The course's emitter ("rain into the cube"): one sphere every T seconds. The
// emitter keeps no state of its own: how many spheres it has emitted is read from
// the world (the spheres after those buildWorld placed), so the window, the capture,
// `spheres simulate`, a restart and a saved state all emit the same way.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "physics/random.h"
#include "scenes/scene.h"

namespace scenes {

namespace {

constexpr double kPi = 3.14159265358979323846;
// s: an emission due at (k + 1) T happens at the step whose time reaches it, even
// when the sum of the steps falls short of it by rounding.
constexpr double kDueSlack = 1e-9;

// s: when emission `next` of emitter `e` falls due.
double dueTime(const Emitter& e, int next) { return (static_cast<double>(next) + 1.0) * e.period; }

// The emitter whose next emission falls due first (ties: the lower index), or -1.
int nextEmitter(const std::vector<Emitter>& emitters, const std::vector<int>& counts) {
    int best = -1;
    double bestTime = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < emitters.size(); ++e) {
        if (counts[e] >= emitters[e].max) continue;
        const double t = dueTime(emitters[e], counts[e]);
        if (t < bestTime) {
            bestTime = t;
            best = static_cast<int>(e);
        }
    }
    return best;
}

// The seed of emission k of emitter e: the same scene, the same rain.
std::uint64_t emissionSeed(std::uint64_t sceneSeed, std::size_t e, int k) {
    physics::Random mix(sceneSeed ^ (0xA24BAED4963EE407ull * (e + 1)));
    physics::Random again(mix.next() ^
                          (0x9FB21C651E98DF25ull * (static_cast<std::uint64_t>(k) + 1)));
    return again.next();
}

struct NewSphere {
    glm::dvec3 v;  // m/s
    double r;      // m
    double m;      // kg
};

NewSphere draw(const Emitter& e, std::uint64_t seed) {
    physics::Random random(seed);
    NewSphere s{};
    s.r = random.uniform(e.radiusMin, e.radiusMax);
    const double x = random.uniform(-e.spread, e.spread);
    const double y = random.uniform(-e.spread, e.spread);
    const double z = random.uniform(-e.spread, e.spread);
    s.v = e.velocity + glm::dvec3(x, y, z);
    s.m = e.massRule == MassRule::Density ? e.density * 4.0 / 3.0 * kPi * s.r * s.r * s.r : e.mass;
    return s;
}

// True when a sphere (p, r) overlaps no plane (a thin wall: its near face) and no sphere.
bool isClear(const physics::World& world, const glm::dvec3& p, double r) {
    for (const physics::Plane& plane : world.planes) {
        const physics::Plane face = physics::faceFor(plane, p);
        if (glm::dot(p - face.point, face.normal) < r) return false;
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        const double reach = r + world.radius[i];  // m
        const glm::dvec3 d = p - world.position[i];
        if (glm::dot(d, d) < reach * reach) return false;
    }
    return true;
}

}  // namespace

std::vector<int> emittedCounts(const Scene& scene, const physics::World& world) {
    if (world.emitted.size() == scene.emitters.size()) return world.emitted;
    std::vector<int> counts;  // a world not built from this scene: start from the file's counts
    for (const Emitter& e : scene.emitters) counts.push_back(std::clamp(e.emitted, 0, e.max));
    return counts;
}

int emitDue(const Scene& scene, physics::World& world) {
    if (scene.emitters.empty()) return 0;
    world.emitted = emittedCounts(scene, world);
    std::vector<int>& counts = world.emitted;
    int added = 0;
    // Each emitter places at most one sphere per call: a second one at the same spot
    // would overlap the first.
    for (std::size_t round = 0; round < scene.emitters.size(); ++round) {
        const int e = nextEmitter(scene.emitters, counts);
        if (e < 0) break;
        const auto index = static_cast<std::size_t>(e);
        const Emitter& emitter = scene.emitters[index];
        if (dueTime(emitter, counts[index]) > world.time + kDueSlack) break;
        const NewSphere s = draw(emitter, emissionSeed(scene.seed, index, counts[index]));
        if (!isClear(world, emitter.position, s.r)) break;  // wait for a later step
        world.addSphere(emitter.position, s.v, s.r, s.m);
        ++counts[index];
        ++added;
    }
    return added;
}

}  // namespace scenes
