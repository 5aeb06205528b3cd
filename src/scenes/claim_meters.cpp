#include "scenes/claim_meters.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "physics/diagnostics.h"
#include "scenes/parameters.h"

namespace scenes {

namespace {

using physics::World;

// The steps a claim measures: those whose time lies in [from, to] give or take half a
// step, so "from = to = 10" picks the one step at t = 10 s.
struct Stretch {
    double from = 0.0, to = 0.0, half = 0.0;  // s
    bool contains(double t) const { return t >= from - half && t < to + half; }
};

Stretch stretchOf(const Claim& claim, const Scene& variant) {
    return {claim.from, claim.to, 0.5 * variant.params.timeStep};
}

// The spheres a per-sphere meter watches: the claim's, or every sphere of the world.
std::vector<std::size_t> watched(const Claim& claim, const World& world) {
    std::vector<std::size_t> out;
    if (claim.spheres.empty()) {
        for (std::size_t i = 0; i < world.size(); ++i) out.push_back(i);
    }
    for (int i : claim.spheres) {
        if (static_cast<std::size_t>(i) < world.size()) out.push_back(static_cast<std::size_t>(i));
    }
    return out;
}

// Signed distance of sphere i's centre to the nearest box wall, m (< 0: outside).
double insideBoxBy(const World& world, std::size_t i) {
    double nearest = INFINITY;
    for (int k = 0; k < world.boxPlaneCount; ++k) {
        const physics::Plane& wall = world.planes[static_cast<std::size_t>(k)];
        nearest = std::min(nearest, glm::dot(world.position[i] - wall.point, wall.normal));
    }
    return nearest;
}

// Sphere i's deepest penetration into a plane, relative to its radius (<= 0: none).
double planeDepth(const World& world, std::size_t i) {
    double deepest = -INFINITY;
    for (const physics::Plane& plane : world.planes) {
        const physics::Plane face = physics::faceFor(plane, world.position[i]);
        const double gap = glm::dot(world.position[i] - face.point, face.normal) - world.radius[i];
        deepest = std::max(deepest, -gap / world.radius[i]);
    }
    return deepest;
}

// The smallest gap between two of `spheres` (m): their centres' distance less both radii,
// < 0 where they overlap; +inf for fewer than two. Every pair: for a layer of spheres, not a pile.
double closestGap(const World& world, const std::vector<std::size_t>& spheres) {
    double closest = INFINITY;
    for (std::size_t a = 0; a < spheres.size(); ++a) {
        for (std::size_t b = a + 1; b < spheres.size(); ++b) {
            const std::size_t i = spheres[a], j = spheres[b];
            closest = std::min(closest, glm::distance(world.position[i], world.position[j]) - world.radius[i] - world.radius[j]);
        }
    }
    return closest;
}

// --- instant meters: one sample per step in the stretch ---

using WorldReadout = std::function<double(const World&)>;

// The highest centre's z (m); -inf for an empty world.
double highestCentre(const World& world) {
    double top = -INFINITY;
    for (const glm::dvec3& p : world.position) top = std::max(top, p.z);
    return top;
}

class WorldMeter : public detail::Meter {
  public:
    WorldMeter(const Claim& claim, const Scene& variant, WorldReadout readout)
        : stretch_(stretchOf(claim, variant)), readout_(std::move(readout)) {}
    void measure(const World& world) override {
        if (stretch_.contains(world.time)) samples_.push_back(readout_(world));
    }

  private:
    Stretch stretch_;
    WorldReadout readout_;
};

using SphereReadout = std::function<double(const World&, std::size_t)>;

class SphereMeter : public detail::Meter {
  public:
    SphereMeter(const Claim& claim, const Scene& variant, SphereReadout readout)
        : claim_(claim), stretch_(stretchOf(claim, variant)), readout_(std::move(readout)) {}
    void measure(const World& world) override {
        if (!stretch_.contains(world.time)) return;
        for (std::size_t i : watched(claim_, world)) samples_.push_back(readout_(world, i));
    }

  private:
    const Claim& claim_;
    Stretch stretch_;
    SphereReadout readout_;
};

// How far each watched sphere has moved since the start of the stretch, m.
class DisplacementMeter : public detail::Meter {
  public:
    DisplacementMeter(const Claim& claim, const Scene& variant)
        : claim_(claim), stretch_(stretchOf(claim, variant)) {}
    void measure(const World& world) override {
        if (!stretch_.contains(world.time)) return;
        if (start_.empty()) start_ = world.position;
        for (std::size_t i : watched(claim_, world)) {
            if (i < start_.size()) samples_.push_back(glm::distance(world.position[i], start_[i]));
        }
    }

  private:
    const Claim& claim_;
    Stretch stretch_;
    std::vector<glm::dvec3> start_;
};

// How far each watched sphere's centre moved in the last time step, m: up (z), or
// the length of the move.
class StepMeter : public detail::Meter {
  public:
    StepMeter(const Claim& claim, const Scene& variant, bool upOnly)
        : claim_(claim), stretch_(stretchOf(claim, variant)), upOnly_(upOnly) {}
    void measure(const World& world) override {
        if (stretch_.contains(world.time) && !previous_.empty()) {
            for (std::size_t i : watched(claim_, world)) {
                if (i >= previous_.size()) continue;
                const glm::dvec3 move = world.position[i] - previous_[i];
                samples_.push_back(upOnly_ ? move.z : glm::length(move));
            }
        }
        previous_ = world.position;
    }

  private:
    const Claim& claim_;
    Stretch stretch_;
    bool upOnly_;
    std::vector<glm::dvec3> previous_;
};

// How many steps of the stretch changed the state (its hash): 0 when nothing moves.
class HashChangesMeter : public detail::Meter {
  public:
    HashChangesMeter(const Claim& claim, const Scene& variant)
        : stretch_(stretchOf(claim, variant)) {}
    void measure(const World& world) override {
        const std::uint64_t hash = physics::stateHash(world);
        if (stretch_.contains(world.time)) {
            if (samples_.empty()) samples_.push_back(0.0);
            if (hash != previous_) samples_[0] += 1.0;
        }
        previous_ = hash;
    }

  private:
    Stretch stretch_;
    std::uint64_t previous_ = 0;
};

// Relative to the value at the start of the run (momentum) or of the stretch (E~).
class ChangeMeter : public detail::Meter {
  public:
    using Readout = glm::dvec3 (*)(const World&, const physics::Params&);
    ChangeMeter(const Claim& claim, const Scene& variant, bool fromStretch, Readout readout)
        : stretch_(stretchOf(claim, variant)), params_(variant.params), fromStretch_(fromStretch), readout_(readout) {}
    void measure(const World& world) override {
        const glm::dvec3 now = readout_(world, params_);
        const bool in = stretch_.contains(world.time);
        if (!reference_ || (fromStretch_ && in && samples_.empty())) reference_ = now;
        if (in) samples_.push_back(glm::length(now - *reference_) / glm::length(*reference_));
    }

  private:
    Stretch stretch_;
    const physics::Params& params_;
    bool fromStretch_;
    Readout readout_;
    std::optional<glm::dvec3> reference_;
};

// What a property's mark (app/teaching/impact_report.h) judges, step by step, from the step's
// measured impacts: the readout's value for each step it applies to (none for the others, as
// the mark says "no free cluster struck" or "no contact"), so that a claim that a step never
// applied counts the samples.
class ImpactMeter : public detail::Meter {
  public:
    using Readout = std::optional<double> (*)(const physics::ImpactProperties&);
    ImpactMeter(const Claim& claim, const Scene& variant, Readout readout)
        : stretch_(stretchOf(claim, variant)), readout_(readout) {}
    bool needsImpacts() const override { return true; }
    void stepped(const physics::StepStats& stats) override { last_ = readout_(stats.impacts); }
    void measure(const World& world) override {
        if (last_ && stretch_.contains(world.time)) samples_.push_back(*last_);
        last_.reset();
    }

  private:
    Stretch stretch_;
    Readout readout_;
    std::optional<double> last_;  // the last step's, where it applied
};

// The kinetic energy relative to its value at t = 0.
class KineticRatioMeter : public detail::Meter {
  public:
    KineticRatioMeter(const Claim& claim, const Scene& variant)
        : stretch_(stretchOf(claim, variant)), params_(variant.params) {}
    void measure(const World& world) override {
        const double kinetic = physics::measure(world, params_).kinetic;
        if (!start_) start_ = kinetic;
        if (stretch_.contains(world.time)) samples_.push_back(kinetic / *start_);
    }

  private:
    Stretch stretch_;
    const physics::Params& params_;
    std::optional<double> start_;
};

// How far the highest centre is below the highest centre at t = 0 (m): "its top sinks 4.9
// cm" measured as a drop, not as two heights the reader subtracts.
class TopDropMeter : public detail::Meter {
  public:
    TopDropMeter(const Claim& claim, const Scene& variant) : stretch_(stretchOf(claim, variant)) {}
    void measure(const World& world) override {
        const double top = highestCentre(world);
        if (!start_) start_ = top;
        if (stretch_.contains(world.time)) samples_.push_back(*start_ - top);
    }

  private:
    Stretch stretch_;
    std::optional<double> start_;  // m
};

// --- event meters: one sample per apex or impact of each watched sphere ---

// Each apex (the centre's highest z in a flight, m), or its bounce ratio
// (apex - r) / (previous apex - r), the first counted from the height at t = 0, or the
// same ratio of the flight's height from E~ (the parabola's apex over the floor at
// z = 0: E~ / (m |g|) - r, as the panel's "beta^2 measured"), not sampled by the steps.
class ApexMeter : public detail::Meter {
  public:
    enum class Sample { Apex, Ratio, EnergyRatio };
    ApexMeter(const Claim& claim, const Scene& variant, Sample sample)
        : claim_(claim), stretch_(stretchOf(claim, variant)), params_(variant.params), sample_(sample) {}
    void measure(const World& world) override {
        if (last_.empty()) {
            for (std::size_t i = 0; i < world.size(); ++i) {
                last_.push_back({world.position[i].z, world.velocity[i].z, apexOf(world, i, world.position[i].z)});
            }
        }
        for (std::size_t i : watched(claim_, world)) {
            if (i >= last_.size()) continue;
            Track& t = last_[i];
            const double z = world.position[i].z, vz = world.velocity[i].z;
            if (t.vz > 0.0 && vz <= 0.0) {
                const double apex = apexOf(world, i, std::max(z, t.z));
                const double r = world.radius[i];
                if (stretch_.contains(world.time)) {
                    samples_.push_back(sample_ == Sample::Apex ? apex : (apex - r) / (t.apex - r));
                }
                t.apex = apex;
            }
            t.z = z;
            t.vz = vz;
        }
    }

  private:
    struct Track {
        double z, vz, apex;  // m, m/s, m
    };
    // m: the apex of sphere i's flight, `highest` its highest centre the steps saw.
    double apexOf(const World& world, std::size_t i, double highest) const {
        if (sample_ != Sample::EnergyRatio) return highest;
        const glm::dvec3 v = world.velocity[i] + (0.5 * params_.solverStep()) * params_.gravity;  // m/s
        return -glm::dot(params_.gravity, world.position[i]) / glm::length(params_.gravity) +
               0.5 * glm::dot(v, v) / glm::length(params_.gravity);
    }
    const Claim& claim_;
    Stretch stretch_;
    const physics::Params& params_;
    Sample sample_;
    std::vector<Track> last_;
};

// The deepest penetration into a plane (relative to r) of each impact, an impact being
// a contact deeper than 1 % of r; counted when the sphere leaves the plane.
class ImpactDepthMeter : public detail::Meter {
  public:
    ImpactDepthMeter(const Claim& claim, const Scene& variant, bool time)
        : claim_(claim), stretch_(stretchOf(claim, variant)), time_(time) {}
    void measure(const World& world) override {
        deepest_.resize(world.size(), 0.0);
        for (std::size_t i : watched(claim_, world)) {
            const double depth = planeDepth(world, i);
            if (depth > 0.0) {
                deepest_[i] = std::max(deepest_[i], depth);
                continue;
            }
            if (deepest_[i] > kImpact && stretch_.contains(world.time)) {
                samples_.push_back(time_ ? world.time : deepest_[i]);
            }
            deepest_[i] = 0.0;
        }
    }

  private:
    static constexpr double kImpact = 0.01;
    const Claim& claim_;
    Stretch stretch_;
    bool time_;  // sample the time the impact ends (s), not its depth
    std::vector<double> deepest_;
};

// The time (s) a watched sphere's centre first leaves the box, once per sphere.
class LeftTheBoxMeter : public detail::Meter {
  public:
    LeftTheBoxMeter(const Claim& claim, const Scene& variant)
        : claim_(claim), stretch_(stretchOf(claim, variant)) {}
    void measure(const World& world) override {
        left_.resize(world.size(), false);
        for (std::size_t i : watched(claim_, world)) {
            if (left_[i] || insideBoxBy(world, i) >= 0.0) continue;
            left_[i] = true;
            if (stretch_.contains(world.time)) samples_.push_back(world.time);
        }
    }

  private:
    const Claim& claim_;
    Stretch stretch_;
    std::vector<bool> left_;
};

// The time (s) a watched sphere first touches a plane, once per sphere: it ends a step
// within its radius of one, or its free flight from the previous step's state, one
// solver step after another, reached one in between (a bounce within a step, undone
// by the projection before the step ends).
class WallContactMeter : public detail::Meter {
  public:
    WallContactMeter(const Claim& claim, const Scene& variant)
        : claim_(claim), stretch_(stretchOf(claim, variant)), params_(variant.params) {}
    void measure(const World& world) override {
        touched_.resize(world.size(), false);
        for (std::size_t i : watched(claim_, world)) {
            if (touched_[i]) continue;
            bool touches = planeDepth(world, i) >= 0.0;
            if (!touches && i < previous_.size()) {
                glm::dvec3 p = previous_[i].first, v = previous_[i].second;
                const double h = params_.solverStep();
                for (int k = 0; k < params_.substeps && !touches; ++k) {
                    v += h * params_.gravity;
                    p += h * v;
                    touches = depthAt(world, p, world.radius[i]) >= 0.0;
                }
            }
            if (!touches) continue;
            touched_[i] = true;
            if (stretch_.contains(world.time)) samples_.push_back(world.time);
        }
        previous_.resize(world.size());
        for (std::size_t i = 0; i < world.size(); ++i) previous_[i] = {world.position[i], world.velocity[i]};
    }

  private:
    // The deepest penetration of a sphere of radius r centred at p into a plane, / r.
    static double depthAt(const World& world, const glm::dvec3& p, double r) {
        double deepest = -INFINITY;
        for (const physics::Plane& plane : world.planes) {
            const physics::Plane face = physics::faceFor(plane, p);
            deepest = std::max(deepest, (r - glm::dot(p - face.point, face.normal)) / r);
        }
        return deepest;
    }
    const Claim& claim_;
    Stretch stretch_;
    const physics::Params& params_;
    std::vector<bool> touched_;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> previous_;  // m, m/s
};

// Each step in which a watched sphere's E~ (its own: m (-g.p + 1/2 |v + (h/2) g|^2), h the
// solver step) falls, by more than 1e-9 m |g| r: the fall / (m |g| h |v|), v its velocity
// after the step. A velocity flip at speed V loses exactly m |g| h V: 1.
class BounceLossMeter : public detail::Meter {
  public:
    BounceLossMeter(const Claim& claim, const Scene& variant)
        : claim_(claim), stretch_(stretchOf(claim, variant)), params_(variant.params) {}
    void measure(const World& world) override {
        const double h = params_.solverStep(), g = glm::length(params_.gravity);
        const std::size_t known = energy_.size();
        energy_.resize(world.size(), NAN);
        for (std::size_t i : watched(claim_, world)) {
            const glm::dvec3 v = world.velocity[i] + (0.5 * h) * params_.gravity;
            const double now = world.mass[i] * (-glm::dot(params_.gravity, world.position[i]) + 0.5 * glm::dot(v, v));
            const double fall = energy_[i] - now;  // NaN for a sphere not seen before
            if (i < known && fall > 1e-9 * world.mass[i] * g * world.radius[i] && stretch_.contains(world.time)) {
                samples_.push_back(fall / (world.mass[i] * g * h * glm::length(world.velocity[i])));
            }
            energy_[i] = now;
        }
    }

  private:
    const Claim& claim_;
    Stretch stretch_;
    const physics::Params& params_;
    std::vector<double> energy_;  // J, each sphere's E~ at the last step
};

// --- the table ---

using Factory = std::function<std::unique_ptr<detail::Meter>(const Claim&, const Scene&)>;

struct MeterEntry {
    ClaimMeter meter;
    Factory make;
};

template <typename M, typename... Extra>
Factory make(Extra... extra) {
    return [=](const Claim& c, const Scene& s) { return std::make_unique<M>(c, s, extra...); };
}

Factory world(std::function<double(const World&, const Scene&)> readout) {
    return [readout](const Claim& c, const Scene& s) {
        return std::make_unique<WorldMeter>(c, s, [readout, &s](const World& w) { return readout(w, s); });
    };
}

Factory sphere(SphereReadout readout) {
    return [readout](const Claim& c, const Scene& s) { return std::make_unique<SphereMeter>(c, s, readout); };
}

// A readout of planes[claim.plane] (NaN when there is no such plane).
Factory planeReadout(double (*readout)(const physics::Plane&)) {
    return [readout](const Claim& c, const Scene& s) {
        const auto k = static_cast<std::size_t>(c.plane);
        return std::make_unique<WorldMeter>(c, s, [k, readout](const World& w) {
            return k < w.planes.size() ? readout(w.planes[k]) : double(NAN);
        });
    };
}

// A sphere's centre's signed distance to planes[claim.plane], less `radii` times its radius.
Factory planeMeter(double radii) {
    return [radii](const Claim& c, const Scene& s) {
        const auto k = static_cast<std::size_t>(c.plane);
        return std::make_unique<SphereMeter>(c, s, [k, radii](const World& w, std::size_t i) {
            if (k >= w.planes.size()) return double(NAN);
            return glm::dot(w.position[i] - w.planes[k].point, w.planes[k].normal) - radii * w.radius[i];
        });
    };
}

double shareIn(const World& w, physics::ContactState state) {
    if (w.size() == 0) return 0.0;
    const auto in = std::count(w.contactState.begin(), w.contactState.end(), state);
    return static_cast<double>(in) / static_cast<double>(w.size());
}

const std::vector<MeterEntry>& meterTable() {
    using D = physics::Diagnostics;
    const auto readout = [](double D::*field) {
        return world([field](const World& w, const Scene& s) { return physics::measure(w, s.params).*field; });
    };
    static const std::vector<MeterEntry> table = {
        {{"kinetic_energy", "J", "the kinetic energy readout"}, readout(&D::kinetic)},
        {{"kinetic_energy_ratio", "", "the kinetic energy / its value at t = 0"}, make<KineticRatioMeter>()},
        {{"potential_energy", "J", "the potential energy readout"}, readout(&D::potential)},
        {{"penetration", "r", "the penetration readout: deepest overlap / smaller radius"}, readout(&D::maxPenetration)},
        {{"modified_energy_change", "of |E~| at the stretch's start", "|E~ - E~ at the stretch's start| / |E~ at its start|"},
         make<ChangeMeter>(true, +[](const World& w, const physics::Params& p) {
             return glm::dvec3(physics::modifiedEnergy(w, p), 0.0, 0.0);
         })},
        {{"momentum", "kg m/s", "|P|, the length of the total momentum (the readouts show rounding below 1e-12 of sum m |v| as 0)"},
         world([](const World& w, const Scene& s) { return glm::length(physics::measure(w, s.params).momentum); })},
        {{"momentum_change", "of |P| at t = 0", "|P - P at t = 0| / |P at t = 0|, the momentum readout"},
         make<ChangeMeter>(false, +[](const World& w, const physics::Params& p) {
             return physics::measure(w, p).momentum;
         })},
        {{"struck_momentum_change", "of sum m|v|",
          "each step's |change| / sum m|v| of the clusters it struck that touch no plane (no sample where it "
          "struck none; the momentum mark shows the largest since the restart)"},
         make<ImpactMeter>(+[](const physics::ImpactProperties& p) {
             return p.momentumScale > 0.0 ? std::optional<double>(p.momentumChange / p.momentumScale) : std::nullopt;
         })},
        {{"approach_left", "m/s",
          "each step's fastest approach left between touching spheres or a sphere and a plane (no sample without a "
          "contact; the positivity mark shows the largest since the restart)"},
         make<ImpactMeter>(+[](const physics::ImpactProperties& p) {
             return p.contacts > 0 ? std::optional<double>(p.fastestApproachAfter) : std::nullopt;  // m/s
         })},
        {{"mean_speed", "m/s", "the spheres' mean speed"},
         world([](const World& w, const Scene&) {
             double sum = 0.0;
             for (const glm::dvec3& v : w.velocity) sum += glm::length(v);
             return w.size() ? sum / static_cast<double>(w.size()) : 0.0;
         })},
        {{"top", "m", "the highest centre's z"}, world([](const World& w, const Scene&) { return highestCentre(w); })},
        {{"top_drop", "m", "how far the highest centre is below the highest centre at t = 0"}, make<TopDropMeter>()},
        {{"sphere_count", "", "how many spheres the world holds"},
         world([](const World& w, const Scene&) { return static_cast<double>(w.size()); })},
        {{"outside_box", "", "spheres whose centre is outside the box (the escape alarm)"},
         world([](const World& w, const Scene&) { return static_cast<double>(physics::spheresOutsideBox(w, 0.0)); })},
        {{"static_share", "", "the share of spheres in static contact (green)"},
         world([](const World& w, const Scene&) { return shareIn(w, physics::ContactState::Static); })},
        {{"held_in_mid_air", "", "spheres at rest that nothing below carries (physics::spheresHeldInMidAir)"},
         world([](const World& w, const Scene& s) { return static_cast<double>(physics::spheresHeldInMidAir(w, s.params)); })},
        {{"colliding_share", "", "the share of spheres that bounced in the last step (orange)"},
         world([](const World& w, const Scene&) { return shareIn(w, physics::ContactState::Colliding); })},
        {{"shock_levels", "", "the contact graph's levels the last shock propagation sweep climbed (0: none)"},
         world([](const World& w, const Scene& s) {
             const std::size_t starts = w.workspace.contactGraph.levelStart.size();
             const bool swept = s.params.shock == physics::ShockPropagation::On && starts > 0;
             return swept ? static_cast<double>(starts - 1) : 0.0;
         })},
        {{"gravity_per_step", "m/s", "|g| h / substeps, the speed gravity adds in one solver step"},
         world([](const World&, const Scene& s) { return glm::length(s.params.gravity) * s.params.solverStep(); })},
        {{"mirror_asymmetry", "m/s", "the largest velocity asymmetry in the scene's mirror planes (0: symmetric)"},
         world([](const World& w, const Scene& s) {
             double worst = 0.0;
             for (const physics::Plane& m : s.mirrors) worst = std::max(worst, physics::mirrorAsymmetry(w, m).velocity);
             return worst;
         })},
        {{"setting", "", "the value of the parameter `name`"},
         [](const Claim& c, const Scene& s) {
             const Parameter* p = findParameter(c.parameter);
             return std::make_unique<WorldMeter>(c, s, [p, &s](const World&) { return p ? p->get(s) : NAN; });
         }},
        {{"hash_changes", "", "how many steps of the stretch changed the state: 0, nothing moves"}, make<HashChangesMeter>()},
        {{"x", "m", "a sphere's centre x"}, sphere([](const World& w, std::size_t i) { return w.position[i].x; })},
        {{"y", "m", "a sphere's centre y"}, sphere([](const World& w, std::size_t i) { return w.position[i].y; })},
        {{"z", "m", "a sphere's centre z"}, sphere([](const World& w, std::size_t i) { return w.position[i].z; })},
        {{"vx", "m/s", "a sphere's velocity x"}, sphere([](const World& w, std::size_t i) { return w.velocity[i].x; })},
        {{"mass", "kg", "a sphere's mass"}, sphere([](const World& w, std::size_t i) { return w.mass[i]; })},
        {{"vy", "m/s", "a sphere's velocity y"}, sphere([](const World& w, std::size_t i) { return w.velocity[i].y; })},
        {{"vz", "m/s", "a sphere's velocity z"}, sphere([](const World& w, std::size_t i) { return w.velocity[i].z; })},
        {{"speed", "m/s", "a sphere's speed"}, sphere([](const World& w, std::size_t i) { return glm::length(w.velocity[i]); })},
        {{"plane_distance", "m", "a sphere's centre's signed distance to planes[plane] (0: the floor)"},
         planeMeter(0.0)},
        {{"plane_tilt", "degrees", "the angle between planes[plane]'s normal and +z"},
         planeReadout([](const physics::Plane& p) { return glm::degrees(std::acos(p.normal.z)); })},
        {{"plane_thickness", "m", "planes[plane]'s thickness (0: a half-space)"},
         planeReadout([](const physics::Plane& p) { return p.thickness; })},
        {{"gap", "m", "a sphere's gap to planes[plane]: the distance less r (< 0: inside it)"}, planeMeter(1.0)},
        {{"displacement", "m", "how far a sphere has moved since the stretch's start"}, make<DisplacementMeter>()},
        {{"closest_gap", "m", "the smallest gap between two of the watched spheres: the distance less both radii (< 0: overlapping)"},
         [](const Claim& c, const Scene& s) {
             return std::make_unique<WorldMeter>(c, s, [&c](const World& w) { return closestGap(w, watched(c, w)); });
         }},
        {{"apex", "m", "each apex of a sphere: its centre's highest z in a flight"}, make<ApexMeter>(ApexMeter::Sample::Apex)},
        {{"bounce_ratio", "", "each apex's (apex - r) / (the previous one - r), the first from the drop"},
         make<ApexMeter>(ApexMeter::Sample::Ratio)},
        {{"energy_bounce_ratio", "", "the same from E~: each flight's E~ / (m |g|) - r over the previous one's"},
         make<ApexMeter>(ApexMeter::Sample::EnergyRatio)},
        {{"z_step", "m", "how far a sphere's centre moved up in one time step"}, make<StepMeter>(true)},
        {{"step_length", "m", "how far a sphere's centre moved in one time step"}, make<StepMeter>(false)},
        {{"impact_depth", "r", "each impact's deepest penetration into a plane / r (impacts deeper than 1 % of r)"},
         make<ImpactDepthMeter>(false)},
        {{"impact_end", "s", "the time each impact (as impact_depth counts them) ends"}, make<ImpactDepthMeter>(true)},
        {{"left_box_at", "s", "the time a sphere's centre first leaves the box"}, make<LeftTheBoxMeter>()},
        {{"wall_contact_at", "s", "the time a sphere first touches a plane (within a step's substeps too)"},
         make<WallContactMeter>()},
        {{"moving", "", "how many of the watched spheres move faster than 1 cm/s"},
         [](const Claim& c, const Scene& s) {
             return std::make_unique<WorldMeter>(c, s, [&c](const World& w) {
                 double count = 0.0;
                 for (std::size_t i : watched(c, w)) count += glm::length(w.velocity[i]) > 0.01 ? 1.0 : 0.0;
                 return count;
             });
         }},
        {{"contact_state", "(0 free, 1 bounced, 2 static)", "a sphere's state in the last step: 0 free, 1 bounced (orange), 2 static (green)"},
         sphere([](const World& w, std::size_t i) {
             switch (w.contactState[i]) {
                 case physics::ContactState::Colliding: return 1.0;
                 case physics::ContactState::Static: return 2.0;
                 default: return 0.0;
             }
         })},
        {{"bounce_loss", "", "each step a sphere's E~ falls: the fall / (m |g| h |v|), v its velocity after"},
         make<BounceLossMeter>()},
    };
    return table;
}

}  // namespace

const std::vector<ClaimMeter>& claimMeters() {
    static const std::vector<ClaimMeter> meters = [] {
        std::vector<ClaimMeter> out;
        for (const MeterEntry& e : meterTable()) out.push_back(e.meter);
        return out;
    }();
    return meters;
}

std::unique_ptr<detail::Meter> detail::makeMeter(const Claim& claim, const Scene& variant) {
    for (const MeterEntry& e : meterTable()) {
        if (e.meter.name == claim.measure) return e.make(claim, variant);
    }
    return nullptr;
}

}  // namespace scenes
