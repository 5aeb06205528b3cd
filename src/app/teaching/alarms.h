#pragma once
// Invariant alarms, shown in the panel in red rather than hidden:
//   - energy created: E~ rose over one step by more than kEnergyTolerance of its
//     scale while alpha, beta <= 1 (nothing in the lecture adds energy then);
//   - penetration: the deepest overlap is more than kPenetrationTolerance of r;
//   - a value that is not finite (NaN, inf): the simulation pauses and names the
//     sphere and the field;
//   - spheres escaped: a centre left the box (crossed a wall within a step), with
//     how many are outside and the step the first one left;
//   - held in mid-air: spheres at rest that nothing below carries, stopped by slide
//     13's v <- mu v on their own velocity (physics::spheresHeldInMidAir);
//   - impact cap: a continuous step reached its most impacts (Params::maxEvents()) and
//     was projected from there.
// The rules are pure functions over the world, its parameters and diagnostics;
// Alarms keeps what the panel shows (when each fired last, how often, the worst).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/params.h"
#include "physics/step.h"
#include "physics/world.h"

namespace app {

// Relative rise of E~ over one step (of energyScale) above which energy was created.
// The shipped presets at their own settings stay below 1e-15 (position based never
// creates energy; an elastic gas keeps it to rounding); the velocity-based bounce at
// beta = 1 gains about 2 g h / s in the bounce's step: 1.5 % for a 1.4 m drop at
// h / substeps = 1/240 s, 6 % at 1/60 s. Small velocity-based bounces at beta < 1 gain
// up to 1e-4 just before they come to rest; they stay below it.
constexpr double kEnergyTolerance = 1e-3;
// Deepest penetration, relative to the smaller radius, above which it is an alarm.
// Half a radius: the shipped presets reach 23 % (the pile, once, as it lands) and 39 %
// (velocity response only, at each impact: slides 5-6, shown by its preset); a
// sphere sunk through half its radius, or one that tunnelled, is beyond any of them.
constexpr double kPenetrationTolerance = 0.5;
// Spheres held in mid-air, as a share of all, from which it is an alarm (and at least
// kHeldInMidAirMin): the position-based pile holds up to 39 of 1000 for a moment as it
// lands (counted at every step), the velocity-based one about 300 for good. Above the
// landing pile's most, whenever the frames count: at 1 % the page's coarser frames lit it
// on the landing position based pile.
constexpr double kHeldInMidAirShare = 0.05;
constexpr std::size_t kHeldInMidAirMin = 3;
// s of simulated time between two counts of the spheres held in mid-air (a broad phase),
// and how long the count must stay at the alarm's level: a landing pile holds a few for
// a moment (the position-based pile up to 39 of 1000, the rain up to 5).
constexpr double kHeldInMidAirPeriod = 0.25;
constexpr double kHeldInMidAirFor = 1.0;
// s of simulated time an alarm stays lit (red) after it last fired; then it is
// shown dimmed until restart, so that a one-step event can be read.
constexpr double kAlarmHoldSeconds = 2.0;

// The first sphere with a value that is not finite, and which.
struct NonFinite {
    std::size_t sphere = 0;
    std::string field;       // "position.z", "velocity.x", "radius", "mass"
    double value = 0.0;      // the offending value (nan or +-inf)
    std::size_t count = 0;   // spheres with a non-finite value
};
std::optional<NonFinite> findNonFinite(const physics::World& world);

// J: what a change of E~ is compared with: |E~|, or when larger the energy of the
// spheres resting on a floor at z = 0 (sum m |g| r), or the kinetic energy.
double energyScale(const physics::World& world, const physics::Params& params, double modifiedEnergy);

// J: how much E~ may rise in a step without any energy being created. E~ of a sphere
// at rest is m (-g.p + (h g / 2)^2 / 2), h the solver step, not its potential alone:
// a static contact (slide 13) that stops a sphere moving down at less than h g / 2
// raises E~ by up to m (h g)^2 / 8. The slack is twice that, summed over the spheres:
// 0.2 mJ per kg at h / substeps = 1/240 s, 3.3 mJ per kg at 1/60 s.
double energySlack(const physics::World& world, const physics::Params& params);

// Whether the rule applies: alpha, beta and mu are all at most 1.
bool energyRuleApplies(const physics::Params& params);

// Relative rise of E~ over a step, (after - before) / scale; <= 0 when it did not rise.
double relativeEnergyRise(double before, double after, double scale);

// Whether a step from E~ = before to after (J) created energy: a rise above
// kEnergyTolerance of `scale` plus `slack` (J, energySlack), with alpha, beta, mu <= 1.
bool energyCreated(double before, double after, double scale, const physics::Params& params, double slack = 0.0);

// Why energy may have been created, in the lecture's words ("" when there is no known cause).
std::string energyHint(const physics::Params& params);

bool penetrationTooDeep(const physics::Diagnostics& diagnostics);
std::string penetrationHint(const physics::Params& params);

// Why spheres left the box, for the method in use.
std::string escapeHint(const physics::Params& params);

// Why spheres rest in mid-air, and what lets them fall.
std::string heldInMidAirHint(const physics::Params& params);

// Why a continuous step met more impacts than its cap, and what to do.
std::string eventCapHint(const physics::Params& params);

enum class AlarmKind { NonFinite, EnergyCreated, Penetration, Escaped, HeldInMidAir, EventCap, Count };

// One line of the panel.
struct AlarmLine {
    AlarmKind kind = AlarmKind::NonFinite;
    std::string text;  // what and when
    std::string hint;  // why, for the tooltip and a second line
    bool lit = false;  // fired within kAlarmHoldSeconds (or still true)
};

// The last change of the live settings since the restart: when (s, simulated; negative:
// none) and what ("shock = on").
struct SettingsChange {
    double time = -1.0;
    std::string what;
};

class Alarms {
public:
    void clear();

    // Before a step: false (and the non-finite alarm set) when the world holds a
    // value that is not finite; the step must not run (the broad phase cannot place it).
    bool checkFinite(const physics::World& world);
    // After a step that took E~ from `before` to `after` (J, both with `params`); `change`:
    // the settings' last change, which may explain a rise. Returns false when the step
    // left a value that is not finite.
    bool checkStep(const physics::World& world, const physics::Params& params, double before, double after,
                   const SettingsChange& change = {});
    // On each new measurement (once per frame).
    void checkMeasurement(const physics::Diagnostics& diagnostics, const physics::Params& params, double time);
    // After a step: whether a continuous step reached the cap on impacts (StepStats::cappedSteps).
    void checkEvents(const physics::StepStats& stats, const physics::Params& params, double time);
    // Counts the spheres held in mid-air, at most every kHeldInMidAirPeriod of simulated time.
    void checkRest(const physics::World& world, const physics::Params& params);

    bool fired(AlarmKind kind) const { return state(kind).count > 0; }
    std::uint64_t count(AlarmKind kind) const { return state(kind).count; }
    double worst(AlarmKind kind) const { return state(kind).worst; }  // relative rise, depth / r, spheres outside
    bool nonFinite() const { return nonFinite_.has_value(); }
    const std::optional<NonFinite>& nonFiniteValue() const { return nonFinite_; }

    // What the panel shows, most serious first; empty when nothing ever fired.
    std::vector<AlarmLine> lines(double now) const;

private:
    struct State {
        std::uint64_t count = 0;
        double lastTime = 0.0;   // s, simulated
        double worst = 0.0;
        std::string hint;
    };
    State& state(AlarmKind kind) { return states_[static_cast<std::size_t>(kind)]; }
    const State& state(AlarmKind kind) const { return states_[static_cast<std::size_t>(kind)]; }
    void fire(AlarmKind kind, double time, double amount, std::string hint);
    bool recordNonFinite(const physics::World& world);

    std::array<State, static_cast<std::size_t>(AlarmKind::Count)> states_{};
    std::optional<NonFinite> nonFinite_;
    std::uint64_t firstEscapeStep_ = 0;  // the solver step after which a sphere was first outside
    std::size_t outsideNow_ = 0;         // spheres outside the box after the last step
    std::size_t heldNow_ = 0;            // spheres held in mid-air at the last count
    std::optional<double> lastRestCheck_;  // s, simulated
    std::optional<double> heldSince_;      // s: since when the count has stayed at the alarm's level
};

}  // namespace app
