// Our solver against the engines users would pick instead: Bullet (btDiscreteDynamicsWorld,
// btDbvtBroadphase, sequential impulses) and ODE (hash space, contact joints,
// dWorldQuickStep). Every engine gets the same spheres (positions, velocities, radii,
// masses), the same six walls, the same time step and as many solver iterations as
// we make passes K, and only stepping is timed. A pile starts, for every engine, from
// the lattice after `--settle` seconds of our position method, at rest; each engine
// then runs `--warm-up` seconds on its own. Runs are interleaved (ours, ours, Bullet,
// ODE, ours, ...), and each row is the median of the repetitions. Quality columns,
// measured with our own diagnostics on every engine's final state, show that nobody
// wins by doing less: spheres outside the box, the deepest overlap / r and the kinetic
// energy left per sphere.
//
// Scenes (the shipped presets found by name, so a renumbering does not break this):
//   pile   the pile preset, one radius 5 cm x (1000/N)^(1/3): the pile keeps its volume
//   gas    the gas preset (no gravity, elastic), one radius 5 cm x (300/N)^(1/3)
//   mixed  the pile preset with radii uniform in [r, 4r], r = 1.5 cm x (1000/N)^(1/3);
//          Bullet and ODE get one sphere shape per body
// Our spheres do not rotate (point masses with a radius): the peers' spheres are
// locked against rotation too, so that friction acts on the same thing.
//
//   usage: spheres_bench_peers --help
#include <btBulletDynamicsCommon.h>
#include <ode/ode.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench/bench_common.h"
#include "physics/diagnostics.h"
#include "physics/step.h"

namespace {

constexpr double kMaxStepSeconds = 5.0;  // s: a step slower than this drops the engine
// ODE's spheres get this many times a solid sphere's moment of inertia (and no
// angular speed at all), so that contacts cannot spin them: our spheres do not rotate.
constexpr double kLockedInertiaFactor = 1e6;
// ODE's hash space marks the pairs it has tested in an N x N bit matrix that it
// allocates and clears at every step (N^2 / 8 bytes: 512 MB at 64k). At 256k, 8 GB,
// ODE 0.16 aborts the process on an assertion (collision_space.cpp:566): no more.
constexpr int kOdeHashMaxCount = 131072;

// ------------------------------------------------------------------ options

struct SceneChoice {
    std::string name;  // pile, gas, mixed
    int maxCount = 0;  // 0: no cap of its own
};

struct Options {
    // The full run: the main figure up to 256k, the gas to 64k, the mixed radii to 16k.
    std::vector<SceneChoice> scenes{{"pile", 0}, {"gas", 64000}, {"mixed", 16000}};
    std::vector<int> counts{1000, 4000, 16000, 64000, 256000};
    int maxCount = 0;  // 0: no cap
    std::vector<int> passes{4};
    std::vector<std::string> engines{"position", "colored", "shock", "velocity", "allpairs", "bullet", "ode"};
    int repetitions = 5;
    double settle = 2.0;     // s our position method runs first (pile, mixed; not the gas)
    double warmUp = 0.5;     // s every engine runs on its own before timing
    bool ownSettle = false;  // every engine settles from the lattice itself (warm-up = settle)
    double block = 0.2;      // s of wall time per timed block (at least one step)
    int allPairsMaxCount = 16000;
    double budget = 300.0;        // s: an engine whose warm-up would take longer is skipped
    double bulletScale = 0.0;     // Bullet's units per metre; 0: the largest radius is 0.5
    bool bulletBoxWalls = false;  // Bullet's walls are slabs (btBoxShape), not planes
    double stepSeconds = 0.0;     // s per step of every engine; 0: the preset's h / substeps
};

const bench::Usage kUsage{"spheres_bench_peers",
    "usage: spheres_bench_peers [options]\n"
    "Times one step of our solver, Bullet and ODE on the same scenes; prints markdown tables.\n"
    "  --quick            N = 1k,4k, 3 repetitions, settle 1 s (well under a minute)\n"
    "  --scenes LIST      of pile, gas, mixed; 'gas:64k' caps one scene's N\n"
    "                     (default pile,gas:64k,mixed:16k)\n"
    "  --n LIST           sphere counts (default 1k,4k,16k,64k,256k)\n"
    "  --max-n N          leave out larger counts\n"
    "  --k LIST           passes K = solver iterations of the peers (default 4; e.g. 4,10)\n"
    "  --engines LIST     position,colored,shock,velocity,allpairs,bullet,ode (default all;\n"
    "                     colored: ours, position, in the colored pair order, not the\n"
    "                     lecture's; shock: ours, position, with slide 14's shock propagation)\n"
    "  --reps R           timed repetitions, interleaved between engines (default 5)\n"
    "  --settle S         simulated seconds our position method runs on the pile and the\n"
    "                     mixed pile to make the start every engine shares (default 2;\n"
    "                     the gas starts as generated)\n"
    "  --warm-up S        simulated seconds every engine then runs before timing (0.5)\n"
    "  --own-settle       every engine settles from the lattice itself (warm-up = settle)\n"
    "  --block S          wall seconds per timed repetition, at least one step (default 0.2)\n"
    "  --allpairs-max-n N largest N for our O(N^2) loop (default 16k)\n"
    "  --budget S         skip an engine whose warm-up would take longer (default 300)\n"
    "  --bullet-scale S   Bullet's units per metre (default: the largest radius is 0.5;\n"
    "                     1 gives it metres, where its absolute margins make it slow)\n"
    "  --bullet-box-walls Bullet's walls as slabs (btBoxShape) instead of static planes\n"
    "  --h S              seconds per step of every engine, e.g. 1/60 (default: the\n"
    "                     preset's h / substeps, 1/240: the steps the demo takes)\n"
    "An engine whose step takes more than 5 s is dropped at that N and above.\n"};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        parts.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return parts;
}

[[noreturn]] void usageError(const std::string& why) { bench::usageError(kUsage, why); }

double parsePositive(const std::string& option, const char* text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (*end != '\0' || !(value > 0.0) || !std::isfinite(value))
        usageError(option + " " + text + ": expected a positive number");
    return value;
}

double simulatedSeconds(const std::string& option, const char* text) {
    double seconds = 0.0;
    if (!bench::parseSimulatedSeconds(text, seconds))
        usageError(option + " " + text + ": expected simulated seconds from 0 to 600");
    return seconds;
}

// s: a time step written as seconds (0.004) or as a fraction (1/60), from 1 us to 1 s.
double parseStep(const std::string& text) {
    const auto number = [](const std::string& part) {
        char* end = nullptr;
        const double value = std::strtod(part.c_str(), &end);
        return !part.empty() && *end == '\0' ? value : NAN;
    };
    const std::size_t slash = text.find('/');
    const double h = slash == std::string::npos
                         ? number(text)
                         : number(text.substr(0, slash)) / number(text.substr(slash + 1));
    if (!(h >= 1e-6 && h <= 1.0))
        usageError("--h " + text + ": expected seconds from 1e-6 to 1, such as 0.004 or 1/60");
    return h;
}

int parseCount(const std::string& option, const char* text) {
    std::vector<int> counts;
    if (!bench::parseCounts(text, counts) || counts.size() != 1)
        usageError(option + " " + text + ": expected a whole number such as 16000 or 16k");
    return counts[0];
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string option = argv[k];
        bench::helpIfAsked(kUsage, option);
        if (option == "--quick") {
            o.counts = {1000, 4000};
            o.repetitions = 3;
            o.settle = 1.0;
            continue;
        }
        if (option == "--bullet-box-walls") {
            o.bulletBoxWalls = true;
            continue;
        }
        if (option == "--own-settle") {
            o.ownSettle = true;
            continue;
        }
        if (k + 1 >= argc) usageError(option + ": missing value (or unknown option)");
        const char* value = argv[++k];
        if (option == "--scenes") {
            o.scenes.clear();
            for (const std::string& part : splitList(value)) {
                SceneChoice choice;
                const std::size_t colon = part.find(':');
                choice.name = part.substr(0, colon);
                if (colon != std::string::npos)
                    choice.maxCount = parseCount("--scenes", part.substr(colon + 1).c_str());
                if (choice.name != "pile" && choice.name != "gas" && choice.name != "mixed")
                    usageError("--scenes: unknown scene '" + choice.name + "' (pile, gas, mixed)");
                o.scenes.push_back(choice);
            }
        } else if (option == "--n") {
            if (!bench::parseCounts(value, o.counts)) usageError("--n: expected e.g. 1k,4k,16k");
            std::sort(o.counts.begin(), o.counts.end());
        } else if (option == "--max-n") {
            o.maxCount = parseCount(option, value);
        } else if (option == "--k") {
            if (!bench::parseCounts(value, o.passes)) usageError("--k: expected e.g. 4,10");
            for (int passes : o.passes) {
                if (passes > 100) usageError("--k: at most 100 passes");
            }
        } else if (option == "--engines") {
            o.engines = splitList(value);
            for (const std::string& e : o.engines) {
                if (e != "position" && e != "colored" && e != "shock" && e != "velocity" && e != "allpairs" && e != "bullet" &&
                    e != "ode")
                    usageError("--engines: unknown engine '" + e +
                               "' (position, colored, shock, velocity, allpairs, bullet, ode)");
            }
        } else if (option == "--reps") {
            o.repetitions = int(parsePositive(option, value));
            if (o.repetitions < 1) usageError("--reps: at least 1");
        } else if (option == "--settle") {
            o.settle = simulatedSeconds(option, value);
        } else if (option == "--warm-up") {
            o.warmUp = simulatedSeconds(option, value);
        } else if (option == "--block") {
            o.block = parsePositive(option, value);
        } else if (option == "--allpairs-max-n") {
            o.allPairsMaxCount = parseCount(option, value);
        } else if (option == "--budget") {
            o.budget = parsePositive(option, value);
        } else if (option == "--h") {
            o.stepSeconds = parseStep(value);
        } else if (option == "--bullet-scale") {
            o.bulletScale = parsePositive(option, value);
        } else {
            usageError("unknown option " + option);
        }
    }
    return o;
}

bool wanted(const Options& o, const char* engine) {
    return std::find(o.engines.begin(), o.engines.end(), engine) != o.engines.end();
}

// ------------------------------------------------------------------ scenes

// One step of every engine advances this much: the preset's h / substeps (or --h), as one
// solver step of ours (substeps = 1), one stepSimulation(h, 0), one dWorldQuickStep.
struct Setup {
    scenes::Scene scene;
    physics::World world;  // the initial state every engine starts from
    std::string radii;     // for the table's title
    bool oneRadius = true;
    bool settles = true;  // a pile: the start is settled first (--settle)
};

Setup makeSetup(const std::string& kind, int count, double stepSeconds) {
    Setup s;
    if (kind == "gas") {
        s.scene = bench::loadPreset(bench::presetContaining("gas"));
        bench::set(s.scene, "count=" + std::to_string(count));
        const double r = bench::scaledRadius(0.05, 300, count);
        bench::set(s.scene, "radius=" + scenes::formatNumber(r));
        s.radii = "r = 5 cm × (300/N)^(1/3)";
        s.settles = false;
    } else {
        s.scene = bench::pileOf(count);
        s.radii = "r = 5 cm × (1000/N)^(1/3)";
        if (kind == "mixed") {
            const double rMax = 0.06 * std::cbrt(1000.0 / count);  // m
            for (scenes::Generator& g : s.scene.generators) {
                g.radiusMin = 0.25 * rMax;
                g.radiusMax = rMax;
            }
            s.radii = "r uniform in [1.5, 6] cm × (1000/N)^(1/3)";
            s.oneRadius = false;
        }
    }
    s.scene.params.timeStep = stepSeconds > 0.0 ? stepSeconds : s.scene.params.solverStep();
    s.scene.params.substeps = 1;
    try {
        s.world = scenes::buildWorld(s.scene);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench: %s at N = %d: %s\n", kind.c_str(), count, error.what());
        std::exit(2);
    }
    return s;
}

// How the lecture's coefficients map onto Coulomb contacts (see the README).
struct PeerMaterial {
    double restitution = 0.0;  // beta: the normal restitution of every contact
    double threshold = 0.0;    // epsilon, m/s: below this approach speed, no bounce
    double friction = 0.0;     // Coulomb coefficient: 1 - min(alpha, mu)
};

PeerMaterial materialOf(const physics::Params& p) {
    return {p.beta, p.epsilon, 1.0 - std::min(p.alpha, p.mu)};
}

// ------------------------------------------------------------------ engines

class Engine {
  public:
    virtual ~Engine() = default;
    virtual void step() = 0;
    // Writes positions and velocities into `world`, which holds the same spheres.
    virtual void exportState(physics::World& world) const = 0;
};

class Ours : public Engine {
  public:
    Ours(physics::World world, const physics::Params& params)
        : world_(std::move(world)), params_(params) {}
    void step() override { physics::step(world_, params_); }
    void exportState(physics::World& world) const override {
        world.position = world_.position;
        world.velocity = world_.velocity;
    }
    const physics::World& world() const { return world_; }

  private:
    physics::World world_;
    physics::Params params_;
};

btVector3 toBullet(const glm::dvec3& v) { return {btScalar(v.x), btScalar(v.y), btScalar(v.z)}; }

// Bullet pads every box of its broad phase by absolute lengths (0.05 for the dynamic
// tree, gContactBreakingThreshold = 0.02), made for bodies of about a unit: around
// spheres of 8 mm it would test thousands of pairs per sphere. As its manual
// advises, it gets the scene in units where the largest sphere has radius 0.5
// (lengths, velocities, gravity and epsilon times `scale`; masses and time as they are).
class Bullet : public Engine {
  public:
    Bullet(const physics::World& world, const physics::Params& params, int iterations,
           bool oneRadius, double scale, bool boxWalls)
        : timeStep_(params.timeStep), scale_(scale), count_(world.size()) {
        config_ = std::make_unique<btDefaultCollisionConfiguration>();
        dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
        broadphase_ = std::make_unique<btDbvtBroadphase>();
        solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
        world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                           solver_.get(), config_.get());
        world_->setGravity(toBullet(scale * params.gravity));
        btContactSolverInfo& info = world_->getSolverInfo();
        info.m_numIterations = iterations;
        const PeerMaterial material = materialOf(params);
        info.m_restitutionVelocityThreshold = btScalar(scale * material.threshold);
        // Bullet multiplies the two bodies' coefficients: the square roots give
        // beta and the Coulomb coefficient on every sphere-sphere and sphere-wall contact.
        const auto restitution = btScalar(std::sqrt(material.restitution));
        const auto friction = btScalar(std::sqrt(material.friction));

        bodies_.reserve(world.size() + world.planes.size());
        btCollisionShape* shared = nullptr;
        if (oneRadius && world.size() > 0) {
            shapes_.push_back(std::make_unique<btSphereShape>(btScalar(scale * world.radius[0])));
            shared = shapes_.back().get();
        }
        for (std::size_t i = 0; i < world.size(); ++i) {
            btCollisionShape* shape = shared;
            if (!shape) {
                shapes_.push_back(
                    std::make_unique<btSphereShape>(btScalar(scale * world.radius[i])));
                shape = shapes_.back().get();
            }
            const auto mass = btScalar(world.mass[i]);
            btVector3 inertia(0, 0, 0);
            shape->calculateLocalInertia(mass, inertia);
            btRigidBody::btRigidBodyConstructionInfo body(mass, nullptr, shape, inertia);
            body.m_startWorldTransform.setIdentity();
            body.m_startWorldTransform.setOrigin(toBullet(scale * world.position[i]));
            body.m_restitution = restitution;
            body.m_friction = friction;
            add(body);
            bodies_.back()->setLinearVelocity(toBullet(scale * world.velocity[i]));
            bodies_.back()->setAngularFactor(0);  // our spheres do not rotate
        }
        for (const physics::Plane& plane : world.planes) {
            btRigidBody::btRigidBodyConstructionInfo body(0, nullptr, nullptr);
            body.m_startWorldTransform.setIdentity();
            if (boxWalls) {
                // A slab 1 m thick behind the wall, 20 m wide: a finite box.
                const btVector3 normal = toBullet(plane.normal);
                shapes_.push_back(std::make_unique<btBoxShape>(
                    btVector3(btScalar(scale * 10), btScalar(scale * 10), btScalar(scale * 0.5))));
                body.m_startWorldTransform.setRotation(shortestArcQuat(btVector3(0, 0, 1), normal));
                body.m_startWorldTransform.setOrigin(
                    toBullet(scale * (plane.point - 0.5 * plane.normal)));
            } else {
                shapes_.push_back(std::make_unique<btStaticPlaneShape>(
                    toBullet(plane.normal), btScalar(scale * glm::dot(plane.normal, plane.point))));
            }
            body.m_collisionShape = shapes_.back().get();
            body.m_restitution = restitution;
            body.m_friction = friction;
            add(body);
        }
    }

    ~Bullet() override {
        // Removing bodies one by one costs O(N) each (a linear search, and a sweep
        // of every pair per proxy): empty the pair cache from its end first, O(1) a
        // pair, so that the world's destructor then finds no pairs to sweep.
        btOverlappingPairCache* cache = world_->getPairCache();
        while (cache->getNumOverlappingPairs() > 0) {
            btBroadphasePair& pair =
                cache->getOverlappingPairArray()[cache->getNumOverlappingPairs() - 1];
            cache->removeOverlappingPair(pair.m_pProxy0, pair.m_pProxy1, dispatcher_.get());
        }
        world_.reset();
        bodies_.clear();
        shapes_.clear();
        solver_.reset();
        broadphase_.reset();
        dispatcher_.reset();
        config_.reset();
    }

    void step() override { world_->stepSimulation(btScalar(timeStep_), 0); }

    void exportState(physics::World& world) const override {
        for (std::size_t i = 0; i < count_; ++i) {
            const btVector3& p = bodies_[i]->getWorldTransform().getOrigin();
            const btVector3& v = bodies_[i]->getLinearVelocity();
            world.position[i] = glm::dvec3(p.x(), p.y(), p.z()) / scale_;
            world.velocity[i] = glm::dvec3(v.x(), v.y(), v.z()) / scale_;
        }
    }

  private:
    void add(const btRigidBody::btRigidBodyConstructionInfo& info) {
        bodies_.push_back(std::make_unique<btRigidBody>(info));
        bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
        world_->addRigidBody(bodies_.back().get());
    }

    double timeStep_;
    double scale_;  // Bullet's units per metre
    std::size_t count_;
    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;  // the spheres, then the walls
};

class Ode : public Engine {
  public:
    Ode(const physics::World& world, const physics::Params& params, int iterations)
        : timeStep_(params.timeStep) {
        world_ = dWorldCreate();
        dWorldSetGravity(world_, params.gravity.x, params.gravity.y, params.gravity.z);
        dWorldSetQuickStepNumIterations(world_, iterations);
        space_ = dHashSpaceCreate(nullptr);
        // Cells of 2^level m: the smallest level that holds the smallest sphere's
        // box, up to the largest one's; the walls (infinite) are tested against all.
        double rMin = 1.0, rMax = 0.0;
        for (double r : world.radius) {
            rMin = std::min(rMin, r);
            rMax = std::max(rMax, r);
        }
        const int high = int(std::ceil(std::log2(2.0 * std::max(rMax, 1e-6))));
        const int low = std::min(high, int(std::floor(std::log2(2.0 * rMin))));
        dHashSpaceSetLevels(space_, low, high);
        contacts_ = dJointGroupCreate(0);

        const PeerMaterial material = materialOf(params);
        surface_.mode = dContactBounce | (material.friction > 0.0 ? dContactApprox1 : 0);
        surface_.mu = material.friction;  // Coulomb (dContactApprox1: times the normal force)
        surface_.bounce = material.restitution;
        surface_.bounce_vel = material.threshold;

        bodies_.reserve(world.size());
        for (std::size_t i = 0; i < world.size(); ++i) {
            const dBodyID body = dBodyCreate(world_);
            const double m = world.mass[i];
            const double inertia =
                kLockedInertiaFactor * 0.4 * m * world.radius[i] * world.radius[i];
            dMass mass;
            dMassSetParameters(&mass, m, 0, 0, 0, inertia, inertia, inertia, 0, 0, 0);
            dBodySetMass(body, &mass);
            dBodySetMaxAngularSpeed(body, 0);  // our spheres do not rotate
            dBodySetPosition(body, world.position[i].x, world.position[i].y, world.position[i].z);
            dBodySetLinearVel(body, world.velocity[i].x, world.velocity[i].y, world.velocity[i].z);
            const dGeomID geom = dCreateSphere(space_, world.radius[i]);
            dGeomSetBody(geom, body);
            bodies_.push_back(body);
        }
        for (const physics::Plane& plane : world.planes) {
            dCreatePlane(space_, plane.normal.x, plane.normal.y, plane.normal.z,
                         glm::dot(plane.normal, plane.point));
        }
    }

    ~Ode() override {
        dJointGroupDestroy(contacts_);
        dSpaceDestroy(space_);  // and its geoms
        dWorldDestroy(world_);  // and its bodies
    }

    void step() override {
        dSpaceCollide(space_, this, &Ode::nearCallback);
        dWorldQuickStep(world_, timeStep_);
        dJointGroupEmpty(contacts_);
    }

    void exportState(physics::World& world) const override {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const dReal* p = dBodyGetPosition(bodies_[i]);
            const dReal* v = dBodyGetLinearVel(bodies_[i]);
            world.position[i] = {p[0], p[1], p[2]};
            world.velocity[i] = {v[0], v[1], v[2]};
        }
    }

  private:
    static void nearCallback(void* data, dGeomID a, dGeomID b) {
        auto* self = static_cast<Ode*>(data);
        const dBodyID bodyA = dGeomGetBody(a);
        const dBodyID bodyB = dGeomGetBody(b);
        if (!bodyA && !bodyB) return;  // two walls
        dContact contact;
        std::memset(&contact, 0, sizeof contact);
        contact.surface = self->surface_;
        if (dCollide(a, b, 1, &contact.geom, sizeof contact) < 1) return;
        const dJointID joint = dJointCreateContact(self->world_, self->contacts_, &contact);
        dJointAttach(joint, bodyA, bodyB);
    }

    double timeStep_;
    dWorldID world_ = nullptr;
    dSpaceID space_ = nullptr;
    dJointGroupID contacts_ = nullptr;
    dSurfaceParameters surface_{};
    std::vector<dBodyID> bodies_;
};

// ------------------------------------------------------------------ measuring

struct Result {
    std::string engine;  // the key: position, velocity, allpairs, bullet, ode
    int passes = 0;
    int count = 0;
    bool measured = false;
    std::string note;          // why not measured
    double msPerStep = 0.0;    // median over the repetitions
    std::size_t outside = 0;   // spheres whose centre left the box
    double penetration = 0.0;  // deepest overlap / the smaller radius
    double kinetic = 0.0;      // J per sphere, after the timed steps
    double speed = 0.0;        // m/s, root mean square
};

struct Slot {
    std::string engine;
    std::unique_ptr<Engine> instance;
    double stepSeconds = 0.0;  // estimate, for the block size
    int blockSteps = 1;
    std::vector<double> samples;  // s per step, one per repetition
};

const char* displayName(const std::string& engine) {
    if (engine == "position") return "ours, position";
    if (engine == "colored") return "ours, position, colored order (not the lecture's)";
    if (engine == "shock") return "ours, position, shock propagation";
    if (engine == "velocity") return "ours, velocity";
    if (engine == "allpairs") return "ours, position, O(N²) loop";
    if (engine == "bullet") return "Bullet";
    if (engine == "ode") return "ODE";
    return "?";
}

std::unique_ptr<Engine> makeEngine(const Options& o, const std::string& engine, const Setup& setup,
                                   int passes) {
    physics::Params params = setup.scene.params;
    params.passes = passes;
    if (engine == "position" || engine == "colored" || engine == "shock" || engine == "velocity") {
        params.method =
            engine == "velocity" ? physics::Method::VelocityBased : physics::Method::PositionBased;
        params.shock = engine == "shock" ? physics::ShockPropagation::On : physics::ShockPropagation::Off;
        if (engine == "colored") params.order = physics::PairOrder::Colored;
        params.broadPhase = physics::BroadPhase::Grid;
        return std::make_unique<Ours>(setup.world, params);
    }
    if (engine == "bullet") {
        double scale = o.bulletScale;
        if (scale <= 0.0) {
            const double rMax =
                *std::max_element(setup.world.radius.begin(), setup.world.radius.end());
            scale = 0.5 / rMax;
        }
        return std::make_unique<Bullet>(setup.world, params, passes, setup.oneRadius, scale,
                                        o.bulletBoxWalls);
    }
    return std::make_unique<Ode>(setup.world, params, passes);
}

double timeSteps(Engine& engine, int steps) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) engine.step();
    return bench::secondsSince(start);
}

// Runs the warm-up of `steps` steps; "" when done, else why the engine was dropped.
std::string warmUp(Slot& slot, int steps, const Options& o) {
    double spent = 0.0;
    int done = 0;
    char why[160];
    while (done < std::max(steps, 1)) {
        const double seconds = timeSteps(*slot.instance, 1);
        spent += seconds;
        ++done;
        if (seconds > kMaxStepSeconds) {
            std::snprintf(why, sizeof why, "skipped: one step took %.1f s (> %.0f s)", seconds,
                          kMaxStepSeconds);
            return why;
        }
        const double estimate = spent / done * (steps + o.repetitions);
        if (done == 3 && estimate > o.budget) {
            std::snprintf(why, sizeof why,
                          "skipped: its warm-up would take about %.0f s (budget %.0f s)", estimate,
                          o.budget);
            return why;
        }
        if (done <= 3) slot.stepSeconds = spent / done;
    }
    return {};
}

Result qualityOf(const Slot& slot, const Setup& setup, int passes, double ms) {
    physics::World world = setup.world;
    slot.instance->exportState(world);
    const physics::Diagnostics d = physics::measure(world, setup.scene.params);
    double totalMass = 0.0;
    for (double m : world.mass) totalMass += m;
    Result r;
    r.engine = slot.engine;
    r.passes = passes;
    r.count = int(world.size());
    r.measured = true;
    r.msPerStep = ms;
    r.outside = physics::spheresOutsideBox(world, 0.0);
    r.penetration = d.maxPenetration;
    r.kinetic = d.kinetic / double(world.size());
    r.speed = std::sqrt(2.0 * d.kinetic / totalMass);
    return r;
}

// What the smaller N of one scene and K said about each engine.
struct History {
    std::map<std::string, std::string> dropped;          // engine -> why it stays out
    std::map<std::string, std::pair<int, double>> last;  // engine -> (N, s per step)
};

// Every engine on one scene at one N and one K: build, warm up, time interleaved.
std::vector<Result> runOne(const Options& o, const std::string& scene, int count, int passes,
                           History& history) {
    std::map<std::string, std::string>& dropped = history.dropped;
    const auto built = std::chrono::steady_clock::now();
    Setup setup = makeSetup(scene, count, o.stepSeconds);
    const double h = setup.scene.params.timeStep;
    const int settleSteps = setup.settles ? int(std::lround(o.settle / h)) : 0;
    const int warmUpSteps =
        o.ownSettle && settleSteps > 0 ? settleSteps : int(std::lround(o.warmUp / h));
    std::fprintf(stderr, "%s N=%d K=%d: scene built in %.1f s\n", scene.c_str(), count, passes,
                 bench::secondsSince(built));
    if (!o.ownSettle && settleSteps > 0) {
        // The shared start: our position method settles the lattice (the fastest of
        // the engines here); every engine, ours included, starts from its state.
        const auto start = std::chrono::steady_clock::now();
        physics::Params params = setup.scene.params;
        params.passes = passes;
        Ours settler(setup.world, params);
        for (int k = 0; k < settleSteps; ++k) settler.step();
        settler.exportState(setup.world);
        // At rest: what ours jitters with would otherwise kick the peers' first steps.
        std::fill(setup.world.velocity.begin(), setup.world.velocity.end(), glm::dvec3(0.0));
        std::fprintf(stderr, "  shared start: %d steps of ours, position, in %.1f s\n", settleSteps,
                     bench::secondsSince(start));
    }

    std::vector<Result> results;
    std::vector<Slot> slots;
    // `dropped` says why an engine was left out at a smaller N: it stays out.
    auto drop = [&](const std::string& engine, const std::string& why) {
        Result r;
        r.engine = engine;
        r.passes = passes;
        r.count = count;
        r.note = why;
        results.push_back(r);
        if (!dropped.count(engine)) dropped[engine] = why + " at N = " + bench::grouped(count);
        std::fprintf(stderr, "  %-9s %s\n", engine.c_str(), why.c_str());
    };
    for (const char* engine : {"position", "colored", "shock", "velocity", "bullet", "ode"}) {
        if (!wanted(o, engine)) continue;
        if (dropped.count(engine)) {
            drop(engine, dropped[engine]);
            continue;
        }
        // No engine here is faster than linear in N: extrapolating linearly from the
        // last N gives a lower bound, enough to skip a step that cannot stay under 5 s.
        if (const auto last = history.last.find(engine); last != history.last.end()) {
            const double atLeast = last->second.second * count / last->second.first;
            if (atLeast > kMaxStepSeconds) {
                char why[160];
                std::snprintf(why, sizeof why,
                              "skipped: one step would take over %.0f s (%.1f s at N = %s)",
                              kMaxStepSeconds, last->second.second,
                              bench::grouped(last->second.first).c_str());
                drop(engine, why);
                continue;
            }
        }
        if (std::string(engine) == "ode" && count > kOdeHashMaxCount) {
            char why[200];
            std::snprintf(why, sizeof why,
                          "skipped: ODE's hash space would clear an N × N bit matrix (%.0f GB) "
                          "every step; ODE 0.16 aborts at N = 256 000",
                          double(count) * count / 8e9);
            drop(engine, why);
            continue;
        }
        Slot slot;
        slot.engine = engine;
        const auto start = std::chrono::steady_clock::now();
        slot.instance = makeEngine(o, engine, setup, passes);
        const double buildSeconds = bench::secondsSince(start);
        const auto warm = std::chrono::steady_clock::now();
        const std::string why = warmUp(slot, warmUpSteps, o);
        if (!why.empty()) {
            drop(engine, why);
            continue;
        }
        std::fprintf(stderr, "  %-9s built in %.1f s, warmed up in %.1f s\n", engine, buildSeconds,
                     bench::secondsSince(warm));
        slots.push_back(std::move(slot));
    }
    // Our O(N^2) loop starts from our position method's warmed-up state: it finds
    // the same contacts as the grid, only slower, and a warm-up of its own would
    // cost minutes.
    if (wanted(o, "allpairs") && count <= o.allPairsMaxCount) {
        const auto position = std::find_if(slots.begin(), slots.end(),
                                           [](const Slot& s) { return s.engine == "position"; });
        if (position != slots.end()) {
            physics::Params params = setup.scene.params;
            params.passes = passes;
            params.broadPhase = physics::BroadPhase::AllPairs;
            Slot slot;
            slot.engine = "allpairs";
            slot.instance = std::make_unique<Ours>(
                static_cast<const Ours&>(*position->instance).world(), params);
            const std::string why = warmUp(slot, 1, o);
            if (why.empty()) {
                slots.push_back(std::move(slot));
            } else {
                drop("allpairs", why);
            }
        }
    }
    for (Slot& slot : slots) {
        slot.blockSteps =
            std::clamp(int(std::lround(o.block / std::max(slot.stepSeconds, 1e-6))), 1, 200);
    }
    for (int repetition = 0; repetition < o.repetitions; ++repetition) {
        for (Slot& slot : slots) {
            slot.samples.push_back(timeSteps(*slot.instance, slot.blockSteps) / slot.blockSteps);
        }
    }
    for (Slot& slot : slots) {
        const double seconds = bench::median(slot.samples);
        if (seconds > kMaxStepSeconds) {
            char why[120];
            std::snprintf(why, sizeof why, "skipped: one step took %.1f s (> %.0f s) at N = %s",
                          seconds, kMaxStepSeconds, bench::grouped(count).c_str());
            dropped.emplace(slot.engine, why);
        }
        history.last[slot.engine] = {count, seconds};
        results.push_back(qualityOf(slot, setup, passes, 1e3 * seconds));
        std::fprintf(stderr, "  %-9s %10.3f ms per step (%d x %d steps)\n", slot.engine.c_str(),
                     1e3 * seconds, o.repetitions, slot.blockSteps);
    }
    const auto order = [](const std::string& engine) {
        const char* const engines[] = {"position", "colored", "shock", "velocity", "allpairs", "bullet", "ode"};
        return int(std::find(std::begin(engines), std::end(engines), engine) - std::begin(engines));
    };
    std::stable_sort(results.begin(), results.end(), [&](const Result& a, const Result& b) {
        return order(a.engine) < order(b.engine);
    });
    return results;
}

std::string number(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

// Three significant digits, fixed notation; "0" for zero.
std::string significant(double value) {
    if (value == 0.0) return "0";
    const int magnitude = int(std::floor(std::log10(std::abs(value))));
    if (magnitude < -3) {
        char text[64];
        std::snprintf(text, sizeof text, "%.2e", value);
        return text;
    }
    return number(value, std::max(0, 2 - magnitude));
}

void printRow(const Result& r, double oursMs) {
    if (!r.measured) {
        std::printf("| %s | %d | %s | %s | | | | | | |\n", displayName(r.engine), r.passes,
                    bench::grouped(r.count).c_str(), r.note.c_str());
        return;
    }
    const std::string ratio = oursMs > 0.0 ? number(r.msPerStep / oursMs, 2) : "";
    std::printf("| %s | %d | %s | %s | %s | %s | %zu | %s | %s | %s |\n", displayName(r.engine),
                r.passes, bench::grouped(r.count).c_str(), significant(r.msPerStep).c_str(),
                bench::grouped(std::lround(1e6 * r.msPerStep / r.count)).c_str(), ratio.c_str(),
                r.outside, number(r.penetration, 3).c_str(), significant(r.kinetic).c_str(),
                significant(r.speed).c_str());
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    const bool odeDouble = dCheckConfiguration("ODE_double_precision") == 1;
    if (odeDouble != (sizeof(dReal) == sizeof(double))) {
        std::fprintf(stderr,
                     "spheres_bench_peers: ODE was built in %s precision, its headers "
                     "say otherwise\n",
                     odeDouble ? "double" : "single");
        return 2;
    }
    const auto started = std::chrono::steady_clock::now();
    std::printf("Machine: %s, %u hardware threads; load average (1, 5, 15 min) at start: %s\n",
                bench::cpuModel().c_str(), std::thread::hardware_concurrency(),
                bench::loadAverage().c_str());
    std::printf("Bullet %d.%02d (btScalar: %s), ODE %s (%s)\n\n", btGetVersion() / 100,
                btGetVersion() % 100, sizeof(btScalar) == sizeof(double) ? "double" : "float",
                dGetConfiguration(), odeDouble ? "dReal: double" : "dReal: float");

    // scene -> engine -> N -> ms per step (for the slopes)
    std::map<std::string,
             std::map<std::string, std::pair<std::vector<double>, std::vector<double>>>>
        curves;
    std::vector<std::string> curveOrder;
    for (const SceneChoice& scene : o.scenes) {
        const Setup sample = makeSetup(scene.name, 1000, o.stepSeconds);
        const physics::Params& p = sample.scene.params;
        std::printf(
            "### %s (%s): %s, h = 1/%.0f s per step, α = %s, β = %s, ε = %s m/s, μ = %s, "
            "|g| = %s m/s²\n\n",
            scene.name.c_str(),
            bench::presetContaining(scene.name == "gas" ? "gas" : "pile").c_str(),
            sample.radii.c_str(), 1.0 / p.timeStep, scenes::formatNumber(p.alpha).c_str(),
            scenes::formatNumber(p.beta).c_str(), scenes::formatNumber(p.epsilon).c_str(),
            scenes::formatNumber(p.mu).c_str(),
            scenes::formatNumber(glm::length(p.gravity)).c_str());
        const double settle = sample.settles ? o.settle : 0.0;
        if (o.ownSettle || settle <= 0.0) {
            std::printf(
                "Every engine starts from the generated spheres and runs %s s before "
                "timing.\n\n",
                scenes::formatNumber(settle > 0.0 ? settle : o.warmUp).c_str());
        } else {
            std::printf(
                "Every engine starts from the same state, the generated spheres after %s s "
                "of ours (position, same K), and runs %s s of its own before timing.\n\n",
                scenes::formatNumber(settle).c_str(), scenes::formatNumber(o.warmUp).c_str());
        }
        std::printf(
            "| engine | K | N | ms per step | ns per sphere-step | × ours | outside | "
            "deepest overlap / r | KE per sphere (J) | v rms (m/s) |\n");
        std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        std::fflush(stdout);
        for (int passes : o.passes) {
            History history;
            for (int count : o.counts) {
                if ((o.maxCount > 0 && count > o.maxCount) ||
                    (scene.maxCount > 0 && count > scene.maxCount))
                    continue;
                const std::vector<Result> results = runOne(o, scene.name, count, passes, history);
                double oursMs = 0.0;
                for (const Result& r : results) {
                    if (r.engine == "position" && r.measured) oursMs = r.msPerStep;
                }
                for (const Result& r : results) {
                    printRow(r, oursMs);
                    if (!r.measured) continue;
                    const std::string key = r.engine + " K=" + std::to_string(passes);
                    auto& curve = curves[scene.name][key];
                    if (curve.first.empty() &&
                        std::find(curveOrder.begin(), curveOrder.end(), key) == curveOrder.end())
                        curveOrder.push_back(key);
                    curve.first.push_back(count);
                    curve.second.push_back(r.msPerStep);
                }
            }
        }
        std::printf("\n");
    }

    std::printf("Scaling: log-log slope of the time per step against N (least squares)\n\n");
    std::printf("| scene | engine | K | N from | N to | slope |\n|---|---|---:|---:|---:|---:|\n");
    for (const SceneChoice& scene : o.scenes) {
        for (const std::string& key : curveOrder) {
            const auto found = curves[scene.name].find(key);
            if (found == curves[scene.name].end() || found->second.first.size() < 2) continue;
            const auto& [counts, times] = found->second;
            const std::string engine = key.substr(0, key.find(' '));
            std::printf(
                "| %s | %s | %s | %s | %s | %.2f |\n", scene.name.c_str(), displayName(engine),
                key.substr(key.find('=') + 1).c_str(), bench::grouped(long(counts.front())).c_str(),
                bench::grouped(long(counts.back())).c_str(), bench::logLogSlope(counts, times));
        }
    }
    std::printf("\nWall time %.0f s; load average (1, 5, 15 min) at the end: %s\n",
                bench::secondsSince(started), bench::loadAverage().c_str());
    dCloseODE();
    return 0;
}
