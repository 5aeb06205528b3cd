#include "app/teaching/alarms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace app {
namespace {

constexpr double kMinEnergyScale = 1e-12;  // J: a world at rest in zero gravity

// The text at any length (the impact-cap hint is over 256 bytes).
std::string formatted(const char* format, double a, double b = 0.0, double c = 0.0) {
    const int length = std::snprintf(nullptr, 0, format, a, b, c);
    std::string text(std::size_t(std::max(length, 0)) + 1, '\0');
    std::snprintf(text.data(), text.size(), format, a, b, c);
    text.pop_back();
    return text;
}

}  // namespace

std::optional<NonFinite> findNonFinite(const physics::World& world) {
    std::optional<NonFinite> found;
    const char* axes[] = {"x", "y", "z"};
    for (std::size_t i = 0; i < world.size(); ++i) {
        std::string field;
        double value = 0.0;
        for (int k = 0; k < 3 && field.empty(); ++k) {
            if (!std::isfinite(world.position[i][k])) {
                field = std::string("position.") + axes[k];
                value = world.position[i][k];
            }
        }
        for (int k = 0; k < 3 && field.empty(); ++k) {
            if (!std::isfinite(world.velocity[i][k])) {
                field = std::string("velocity.") + axes[k];
                value = world.velocity[i][k];
            }
        }
        if (field.empty() && !std::isfinite(world.radius[i])) {
            field = "radius";
            value = world.radius[i];
        }
        if (field.empty() && !std::isfinite(world.mass[i])) {
            field = "mass";
            value = world.mass[i];
        }
        if (field.empty()) continue;
        if (!found) found = NonFinite{i, field, value, 0};
        ++found->count;
    }
    return found;
}

double energyScale(const physics::World& world, const physics::Params& params, double modifiedEnergy) {
    const double g = glm::length(params.gravity);
    double resting = 0.0, kinetic = 0.0;
    for (std::size_t i = 0; i < world.size(); ++i) {
        resting += world.mass[i] * g * world.radius[i];
        kinetic += 0.5 * world.mass[i] * glm::dot(world.velocity[i], world.velocity[i]);
    }
    return std::max({std::abs(modifiedEnergy), resting, kinetic, kMinEnergyScale});
}

double energySlack(const physics::World& world, const physics::Params& params) {
    const double hg = params.solverStep() * glm::length(params.gravity);  // m/s
    double mass = 0.0;
    for (const double m : world.mass) mass += m;
    return 2.0 * mass * hg * hg / 8.0;
}

bool energyRuleApplies(const physics::Params& params) {
    return params.alpha <= 1.0 && params.beta <= 1.0 && params.mu <= 1.0;
}

double relativeEnergyRise(double before, double after, double scale) {
    return (after - before) / std::max(scale, kMinEnergyScale);
}

bool energyCreated(double before, double after, double scale, const physics::Params& params, double slack) {
    return energyRuleApplies(params) && after - before > kEnergyTolerance * std::max(scale, kMinEnergyScale) + slack;
}

// From this static-contact friction up, the position based projection can lift a stack
// within a step (21's column of 20 at K = 1: E~ rises at mu = 0.87, never at 0.86; 09's
// from 0.98; test_canonical_checks).
constexpr double kProjectionLiftsFromMu = 0.87;

// s: how long after a change of the settings a rise of E~ is put down to it (a column
// squashed by one pass stands up again within a few steps once shock propagation is on).
constexpr double kSettingsAftermath = 1.0;

std::string energyHint(const physics::Params& params, const SettingsChange& change, double now) {
    if (change.time >= 0.0 && now - change.time <= kSettingsAftermath) {
        return "the settings changed at t = " + formatted("%.3f", change.time) + " s (" + change.what +
               "): the new ones push apart the overlaps the old ones left, lifting the spheres that had sunk into "
               "each other, and E~ gets back the potential energy the sinking lost (R restarts with the new "
               "settings)";
    }
    if (params.solver == physics::Solver::Simultaneous) {
        return "the simultaneous solver answers each contact as if it were alone and sums the answers: a sphere "
               "hit from several sides at once can leave faster than it came (slide 14: the global approach "
               "solves the contacts together); switch solver to lcp or generalized-reflections (sequential keeps "
               "the energy but breaks the symmetry)";
    }
    if (params.method == physics::Method::VelocityBased) {
        return "velocity-based bounce reflects this step's gravity kick: the contact is found after "
               "v ← v + τ g, and the response sends that back too (about 2 g τ / s per bounce, τ = h / substeps "
               "the solver step, s the impact speed; smaller with more substeps or β < 1)";
    }
    if (params.method == physics::Method::Reflection) {
        return "reflection mirrors the velocity the step found, one gravity kick late (slide 7's "
               "approximation): a bounce that enters early in its step comes out up to 2 g τ / s "
               "too fast (τ = h / substeps); switch method to continuous for the instant of contact";
    }
    if (params.method == physics::Method::ResponseOnly) {
        return "response-only reflects this step's gravity kick too (slides 5–6: the contact is found "
               "after v ← v + τ g, inside the wall, τ = h / substeps): a floor bounce loses energy, a bounce "
               "off the ceiling gains about m g τ |v⊥|; smaller with more substeps";
    }
    if (params.mu >= kProjectionLiftsFromMu) {  // position based
        return "with little static damping (μ near 1) the projection of a stack can lift it within a step "
               "(the column of 09 from μ = 0.98: up to 0.07 J in a step at μ = 1; 21's at K = 1 starts rising "
               "at μ = 0.87, below this alarm); over a run it still loses; lower μ (0.5) or raise passes";
    }
    return "not expected from the lecture's rules with α, β ≤ 1: report the scene and its parameters";
}

bool penetrationTooDeep(const physics::Diagnostics& diagnostics) {
    return diagnostics.maxPenetration > kPenetrationTolerance;
}

std::string penetrationHint(const physics::Params& params) {
    switch (params.method) {
        case physics::Method::ResponseOnly:
            return "response-only has no position correction (slides 5–6): the contact is found inside "
                   "the floor and a resting sphere sinks by τ² g every solver step once its contact is static (τ = "
                   "h / substeps) "
                   "(every second step when ε < g h / substeps, as in 01); switch method to position";
        case physics::Method::VelocityBased:
            return "velocity based only cancels the approach, never pushes apart: an existing overlap "
                   "persists or grows; switch method to position to project it out";
        case physics::Method::Continuous:
            return "continuous: a resting contact is pressed in by g τ² / 2 within a solver step (τ = h / "
                   "substeps) and projected "
                   "at its end; a deeper overlap comes from a step that reached the impact cap "
                   "(raise max_events) or an overlap that was there before";
        case physics::Method::PositionBased:
        case physics::Method::Reflection:
            break;
    }
    return "the passes did not resolve every overlap, or spheres too fast for the step met deep inside each "
           "other: raise passes or substeps, lower h, or switch method to continuous (slide 7)";
}

// ---------------------------------------------------------------- the record

std::string escapeHint(const physics::Params& params) {
    if (params.method == physics::Method::Continuous) {
        return "continuous catches every wall at its instant of contact: a sphere got out in a step that "
               "reached the impact cap (raise max_events), or was outside already";
    }
    if (params.method == physics::Method::Reflection) {
        return "reflection moves a sphere back by (1 + β) d: a step that carried it deep past a wall throws it "
               "that far back, out through the opposite wall where the box is narrower; a thin wall crossed "
               "within a step is never met; lower h or raise substeps";
    }
    if (params.method == physics::Method::PositionBased) {
        return "the passes pushed a sphere through a wall (a crowd pressed against it), or it crossed a thin "
               "wall within one solver step: raise passes or substeps, or lower h";
    }
    return "without projection (slide 7) a wall only turns the velocity: a sphere pushed on by gravity "
           "or by its neighbours sinks through it, a fast one is outside for a step before the wall turns it "
           "back, and a thin wall it crosses within a step is never met; switch method to position (a lower h only "
           "slows the sinking: it goes on)";
}

std::string heldInMidAirHint(const physics::Params& params) {
    if (params.response != physics::ResponseModel::LectureAttenuation) {
        return "spheres rest where nothing below carries them: deep overlaps (the velocity method never "
               "pushes spheres apart) hold spheres inside each other; switch method to position";
    }
    return "slide 13's static contact brakes each sphere's own velocity, v ← μ v, so spheres that touch only "
           "each other stop wherever they are, as if glued; switch response to momentum (μ on the relative "
           "velocity) and they fall";
}

void Alarms::clear() {
    states_ = {};
    nonFinite_.reset();
    firstEscapeStep_ = 0;
    outsideNow_ = 0;
    heldNow_ = 0;
    lastRestCheck_.reset();
    heldSince_.reset();
}

void Alarms::fire(AlarmKind kind, double time, double amount, std::string hint) {
    State& s = state(kind);
    ++s.count;
    s.lastTime = time;
    s.worst = std::max(s.worst, amount);
    s.hint = std::move(hint);
}

bool Alarms::recordNonFinite(const physics::World& world) {
    std::optional<NonFinite> found = findNonFinite(world);
    if (!found) return true;
    if (!nonFinite_) fire(AlarmKind::NonFinite, world.time, 1.0, "");
    nonFinite_ = std::move(found);
    return false;
}

bool Alarms::checkFinite(const physics::World& world) { return recordNonFinite(world); }

bool Alarms::checkStep(const physics::World& world, const physics::Params& params, double before, double after,
                       const SettingsChange& change) {
    if (!std::isfinite(after) || !std::isfinite(before)) {
        // E~ sums every position, velocity and mass: the scan says which one.
        if (!recordNonFinite(world)) return false;
        return true;  // E~ overflowed on finite values: nothing to name
    }
    const double scale = energyScale(world, params, before);
    if (energyCreated(before, after, scale, params, energySlack(world, params))) {
        // Shown as a share of E~ before the step, as a student computes it from the plot
        // (the scale only decides whether it is a rise at all).
        fire(AlarmKind::EnergyCreated, world.time, relativeEnergyRise(before, after, std::abs(before)),
             energyHint(params, change, world.time));
    }
    // Fires when more spheres are outside than ever before (most stay there).
    outsideNow_ = physics::spheresOutsideBox(world, 0.0);
    if (double(outsideNow_) > state(AlarmKind::Escaped).worst) {
        if (!fired(AlarmKind::Escaped)) firstEscapeStep_ = world.stepCount;
        fire(AlarmKind::Escaped, world.time, double(outsideNow_), escapeHint(params));
    }
    return true;
}

void Alarms::checkMeasurement(const physics::Diagnostics& diagnostics, const physics::Params& params, double time) {
    if (penetrationTooDeep(diagnostics)) {
        fire(AlarmKind::Penetration, time, diagnostics.maxPenetration, penetrationHint(params));
    }
}

void Alarms::checkRest(const physics::World& world, const physics::Params& params) {
    if (lastRestCheck_ && world.time >= *lastRestCheck_ && world.time < *lastRestCheck_ + kHeldInMidAirPeriod) return;
    lastRestCheck_ = world.time;
    heldNow_ = physics::spheresHeldInMidAir(world, params);
    const double least = std::max(double(kHeldInMidAirMin), kHeldInMidAirShare * double(world.size()));
    if (double(heldNow_) < least) {
        heldSince_.reset();
        return;
    }
    if (!heldSince_) heldSince_ = world.time;
    if (world.time - *heldSince_ >= kHeldInMidAirFor) {
        fire(AlarmKind::HeldInMidAir, world.time, double(heldNow_), heldInMidAirHint(params));
    }
}

std::string eventCapHint(const physics::Params& params) {
    return formatted("the continuous method answers impacts one at a time, at most %.0f per sphere in a solver "
                     "step: a sphere at rest makes one or two, one bouncing in place with ε = 0 infinitely many "
                     "(until its speed rounds to 0). Raise ε (a little above 0 lets it rest); a larger max_events "
                     "only makes the cap rarer (1000: half as often), and a smaller h does not help",
                     double(params.maxEventsPerSphere));
}

void Alarms::checkEvents(const physics::StepStats& stats, const physics::Params& params, double time) {
    for (std::uint64_t k = 0; k < stats.cappedSteps; ++k) {  // each solver step counts
        fire(AlarmKind::EventCap, time, double(params.maxEventsPerSphere), eventCapHint(params));
    }
}

std::vector<AlarmLine> Alarms::lines(double now) const {
    std::vector<AlarmLine> lines;
    const auto lit = [&](AlarmKind kind) { return now - state(kind).lastTime <= kAlarmHoldSeconds; };
    if (nonFinite_) {
        const NonFinite& n = *nonFinite_;
        char text[256];
        std::snprintf(text, sizeof text, "NOT FINITE: sphere %zu, %s = %g%s. Paused: restart (R).", n.sphere,
                      n.field.c_str(), n.value,
                      n.count > 1 ? (" (" + std::to_string(n.count) + " spheres)").c_str() : "");
        lines.push_back({AlarmKind::NonFinite, text, "A value became NaN or infinite; the solver cannot go on.", true});
    }
    if (const State& s = state(AlarmKind::EnergyCreated); s.count > 0) {
        const std::string times = s.count == 1 ? "once" : std::to_string(s.count) + " times";
        lines.push_back({AlarmKind::EnergyCreated,
                         formatted("ENERGY CREATED (α, β ≤ 1): E~ rose by up to %.2g %% of itself in one time step h, ", 100.0 * s.worst) +
                             times + formatted(", last at t = %.3f s", s.lastTime),
                         s.hint, lit(AlarmKind::EnergyCreated)});
    }
    if (const State& s = state(AlarmKind::Penetration); s.count > 0) {
        lines.push_back({AlarmKind::Penetration,
                         // The deepest so far, which the views' labels (the deepest now) may no longer show.
                         formatted("PENETRATION: %.1f %% of r at the deepest so far (alarm above %.0f %%), last above it at t = %.3f s",
                                   100.0 * s.worst, 100.0 * kPenetrationTolerance, s.lastTime),
                         s.hint, lit(AlarmKind::Penetration)});
    }
    if (const State& s = state(AlarmKind::Escaped); s.count > 0) {
        char text[256];
        std::snprintf(text, sizeof text, "ESCAPED: %zu outside the box now, up to %.0f at once; the first had "
                      "left by solver step %llu", outsideNow_, s.worst, static_cast<unsigned long long>(firstEscapeStep_));
        lines.push_back({AlarmKind::Escaped, text, s.hint, lit(AlarmKind::Escaped)});
    }
    if (const State& s = state(AlarmKind::HeldInMidAir); s.count > 0) {
        char text[256];
        std::snprintf(text, sizeof text, "MID-AIR: %zu spheres at rest off the floor (up to %.0f), nothing below "
                      "carrying them", heldNow_, s.worst);
        lines.push_back({AlarmKind::HeldInMidAir, text, s.hint, lit(AlarmKind::HeldInMidAir)});
    }
    if (const State& s = state(AlarmKind::EventCap); s.count > 0) {
        lines.push_back({AlarmKind::EventCap,
                         formatted("IMPACT CAP: %.0f steps reached %.0f impacts per sphere and were projected from there, "
                                   "last at t = %.3f s",
                                   double(s.count), s.worst, s.lastTime),
                         s.hint, lit(AlarmKind::EventCap)});
    }
    return lines;
}

}  // namespace app
