#pragma once
// What a preset's text tells the class, as data a test can run (the lab sheet).
//
// Each claim quotes a phrase of the preset's description (or of the README's
// teaching-table row for the preset), and says how to check it: the settings to
// run the preset with (its own, or the variant the text suggests, as --set
// takes them), which readout to measure over which stretch of time, and the
// value it must have. checkClaims runs the preset as the app does (a time step,
// then the emitters) once per variant and measures every claim of that variant.
//
// In a scene file:
//   "claims": [{"says": "each apex is about 6 % lower",   required: a verbatim quote
//               "in": "README",                          where the quote is: "description"
//                                                        (default) or "README" (the table)
//               "set": ["method=position"],              --set assignments, default none
//               "measure": "bounce_ratio",               required: a meter of claimMeters()
//               "sphere": 0,                             an index or [indices]; default: the
//                                                        meter's own (every sphere, or 0)
//               "plane": 6,                              for plane_distance: world.planes index
//               "name": "epsilon",                       for setting: a parameter's name
//               "from": 0, "to": 10,                     s, the stretch measured, default 0
//                                                        and `from`; a step counts when its
//                                                        time is within half a step of it
//               "take": "each",                          each (default: every sample must
//                                                        hold), min, max, mean, first, last,
//                                                        count (how many samples)
//               "nth": 2,                                the nth sample (1-based), not take
//               "ratio_to": ["mu=0.5"],                  divide by the same measurement of
//                                                        the preset with these settings
//               "near": 0.94, "within": 0.02,            the value, or a bound:
//               "min": 0.9, "max": 1.0}]                 inclusive; at least one of these
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace physics {
struct World;
struct StepStats;
}

namespace scenes {

struct Scene;

// Where a claim's quote is.
enum class ClaimSource {
    Description,  // the preset's description (what the panel shows)
    Readme,       // the preset's row of the README's teaching table
};

struct Claim {
    std::string says;
    ClaimSource in = ClaimSource::Description;
    std::vector<std::string> settings;  // "name=value", applied to the preset in order
    std::string measure;                // a name of claimMeters()
    std::vector<int> spheres;           // empty: the meter's default
    int plane = 0;                      // plane_distance: index in world.planes
    std::string parameter;              // setting: the parameter's name
    double from = 0.0;                  // s
    double to = 0.0;                    // s, >= from
    std::string take = "each";
    int nth = 0;  // > 0: the nth sample instead of `take`
    std::optional<std::vector<std::string>> ratioTo;
    std::optional<double> near, within, min, max;
    // The parameters (tableValues) of the preset with `settings`, stamped when the
    // preset is loaded: a run whose parameters are these is the claim's run.
    std::vector<double> variant;
    // How many of the world's planes the box makes (stamped with the variant): `plane`
    // counts them, the lines name the others as the explainer does, "plane 0" and up.
    int boxPlanes = 0;
};

// A meter: a readout the demo has, sampled at every step of a claim's stretch
// (an instant meter) or once per event (an apex, an impact) within it.
struct ClaimMeter {
    std::string_view name;
    std::string_view unit;
    std::string_view what;  // one line, for the scene format's documentation and errors
};

// Every meter a claim may name.
const std::vector<ClaimMeter>& claimMeters();

// The longest stretch a claim may measure, s (a preset's claims run in a test).
constexpr double kMaxClaimTime = 120.0;

// One claim, checked.
struct ClaimCheck {
    const Claim* claim = nullptr;
    std::vector<double> samples;  // what the meter gave, in its unit
    std::optional<double> value;  // after take / nth / ratio_to; none: nothing measured
    bool holds = false;
    std::string measured;  // one line: the quantity named, its value (or the samples' range)
                           // and, if not held, what was expected
};

// Every parameter's value in `scene`, in the table's order (-inf for one it has not).
std::vector<double> tableValues(const Scene& scene);

// Stamps each claim of a scene as loaded with its variant's parameters (Claim::variant).
void stampClaimVariants(Scene& scene);

namespace detail {
class Meter;
}

// The claims of the scene's text that a run checks as it goes, for the panel: those
// quoting the description, with no ratio_to, whose variant is the scene as it runs
// (Claim::variant equals its parameters at the start). Feed it the world as built and
// after every time step (the app's emitters included), from the same run, untouched.
class LiveClaims {
  public:
    LiveClaims();
    explicit LiveClaims(const Scene& scene);
    ~LiveClaims();
    LiveClaims(LiveClaims&&) noexcept;
    LiveClaims& operator=(LiveClaims&&) noexcept;
    // A copy measures nothing: its meters would have to have seen the run from its start.
    LiveClaims(const LiveClaims&);
    LiveClaims& operator=(const LiveClaims&);

    bool empty() const { return size() == 0; }
    std::size_t size() const;
    // Whether a claim measures what the steps' contacts did (World::measureImpacts).
    bool needsImpacts() const;
    // The world as built (no `stepped`), then after each time step with what it did.
    void observe(const physics::World& world, const physics::StepStats* stepped = nullptr);
    // The claims whose stretch has passed at `time` (s), judged, in the scene's order.
    std::vector<ClaimCheck> judged(double time) const;
    // s: when the last stretch ends (0 without claims): every claim is judged from then on.
    double lastMoment() const;

  private:
    // The scene and the claims the meters watch for (they keep references to both: kept
    // in one place, whatever moves the LiveClaims).
    struct Watch;
    std::unique_ptr<Watch> watch_;
};

// Runs `preset` once per distinct variant of its claims and checks each claim.
std::vector<ClaimCheck> checkClaims(const Scene& preset);

// "" when the claim is well formed for `preset` (settings apply, the meter exists,
// take is known, a value or a bound is given), else one line saying what is wrong.
std::string checkClaimForm(const Claim& claim, const Scene& preset);

}  // namespace scenes
