#include "scenes/parameters.h"

#include "scenes/overrides.h"

#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <type_traits>

#include "scenes/suggest.h"

namespace scenes {

namespace {

const physics::Params kDefaults;
constexpr double kMaxSeed = 9007199254740992.0;  // 2^53: every seed up to it is exact in a double

// A get/set pair over one field of the scene's physics::Params; choices arrive as their index.
struct Access {
    double (*get)(const Scene&);
    std::string (*set)(Scene&, double);
};

template <auto Field>
double getParam(const Scene& s) {
    return static_cast<double>(s.params.*Field);
}

template <auto Field>
std::string setParam(Scene& s, double v) {
    using T = std::remove_reference_t<decltype(s.params.*Field)>;
    if constexpr (std::is_floating_point_v<T>) {
        s.params.*Field = v;
    } else {
        s.params.*Field = static_cast<T>(static_cast<int>(v));
    }
    return {};
}

template <auto Field>
constexpr Access param() {
    return {getParam<Field>, setParam<Field>};
}

// --- the entries, grouped by kind so that each reads as one line of the table ---

// The fields every entry has; the kind's builders below set the rest.
Parameter entry(std::string_view name, std::string_view label, std::string_view unit, ParameterKind kind,
                double min, double max, double defaultValue, std::string_view tooltip, Access access) {
    Parameter p;
    p.name = name;
    p.label = label;
    p.unit = unit;
    p.kind = kind;
    p.min = min;
    p.max = max;
    p.defaultValue = defaultValue;
    p.tooltip = tooltip;
    p.get = access.get;
    p.set = access.set;
    return p;
}

Parameter real(std::string_view name, std::string_view label, std::string_view unit, double min,
               double max, double defaultValue, std::string_view tooltip, Access access) {
    return entry(name, label, unit, ParameterKind::Real, min, max, defaultValue, tooltip, access);
}

Parameter integer(std::string_view name, std::string_view label, double min, double max,
                  double defaultValue, std::string_view tooltip, Access access) {
    return entry(name, label, "", ParameterKind::Integer, min, max, defaultValue, tooltip, access);
}

Parameter choice(std::string_view name, std::string_view label,
                 std::vector<std::string_view> choices, double defaultValue,
                 std::string_view tooltip, Access access) {
    const double last = static_cast<double>(choices.size()) - 1.0;
    Parameter p = entry(name, label, "", ParameterKind::Choice, 0.0, last, defaultValue, tooltip, access);
    p.choices = std::move(choices);
    return p;
}

Parameter restart(Parameter p) {
    p.applies = Applies::Restart;
    return p;
}

Parameter shownAsFraction(Parameter p) {
    p.shownAsFraction = true;
    return p;
}

Parameter zeroMeaning(std::string_view meaning, Parameter p) {
    p.zeroMeans = meaning;
    return p;
}

// `notes`: one per choice, "" for none.
Parameter withChoiceNotes(std::vector<std::string_view> notes, Parameter p) {
    p.choiceNotes = std::move(notes);
    return p;
}

Parameter onlyWith(bool (*available)(const Scene&), std::string_view when, Parameter p) {
    p.available = available;
    p.availableWhen = when;
    return p;
}

// What each condition of onlyWith says when a setting acts on nothing (settingsThatActOnNothing).
constexpr std::string_view kWithLevels = "acts only with the position, velocity or reflection method";
constexpr std::string_view kWithContinuous = "acts only with the continuous method";
constexpr std::string_view kWithEmitter = "acts only on a scene with an emitter";
constexpr std::string_view kWithGenerator = "acts only on a scene with generated spheres";

bool hasEmitter(const Scene& s) { return !s.emitters.empty(); }
bool hasGenerator(const Scene& s) { return !s.generators.empty(); }
bool isContinuous(const Scene& s) { return s.params.method == physics::Method::Continuous; }
bool sweepsLevels(const Scene& s) { return physics::sweepsLevels(s.params.method); }

double gravityOf(const Scene& s) { return glm::length(s.params.gravity); }
std::string setGravity(Scene& s, double g) {
    s.params.gravity = {0.0, 0.0, -g};  // m/s^2, pointing along -z
    return {};
}

const char* const kNoGenerators = "scene has no generated spheres";

double countOf(const Scene& s) { return s.generators.empty() ? 0.0 : s.generators[0].count; }
std::string setCount(Scene& s, double n) {
    if (s.generators.empty()) return kNoGenerators;
    s.generators[0].count = static_cast<int>(n);
    return {};
}

double radiusOf(const Scene& s) {
    return s.generators.empty() ? Generator{}.radiusMax : s.generators[0].radiusMax;
}
std::string setRadius(Scene& s, double r) {
    if (s.generators.empty()) return kNoGenerators;
    for (Generator& g : s.generators) g.radiusMin = g.radiusMax = r;  // m
    return {};
}

const char* const kNoEmitters = "scene has no emitter";

double emitPeriodOf(const Scene& s) {
    return s.emitters.empty() ? Emitter{}.period : s.emitters[0].period;
}
std::string setEmitPeriod(Scene& s, double period) {
    if (s.emitters.empty()) return kNoEmitters;
    s.emitters[0].period = period;  // s
    return {};
}

double seedOf(const Scene& s) { return static_cast<double>(s.seed); }
std::string setSeed(Scene& s, double seed) {
    s.seed = static_cast<std::uint64_t>(seed);
    return {};
}

std::vector<Parameter> makeTable() {
    using physics::Params;
    return {
        real("alpha", "\u03b1  tangential attenuation", "", 0.0, 1.0, kDefaults.alpha,
             "Slide 4: restitution coefficient in the \u2225 direction (friction). A bounce keeps "
             "\u03b1 v\u2225: 1 keeps the sliding speed, 0 stops it.",
             param<&Params::alpha>()),
        real("beta", "\u03b2  normal restitution", "", 0.0, 1.0, kDefaults.beta,
             "Slide 4: restitution coefficient in the \u22a5 direction (impact). A bounce sends "
             "back \u03b2 v\u22a5: 1 is elastic, 0 does not bounce; the apex height scales by "
             "\u03b2\u00b2.",
             param<&Params::beta>()),
        real("epsilon", "\u03b5  static-contact speed", "m/s", 0.0, 10.0, kDefaults.epsilon,
             "Slide 13: a contact whose relative normal speed is at or below \u03b5 is static: no "
             "bounce, friction v \u2190 \u03bc v instead, which avoids jittering. An \u03b5 above "
             "|g| h / substeps (the speed gravity adds in one solver step) catches a resting "
             "contact; below it one may keep bouncing in place (with the velocity method a "
             "ball may also settle into hops faster than \u03b5: 02 at \u03b2 = 0.8 rests only "
             "from \u03b5 = 0.16).",
             param<&Params::epsilon>()),
        real("mu", "\u03bc  static friction, v \u2190 \u03bc v", "", 0.0, 1.0, kDefaults.mu,
             "Slide 13: friction v \u2190 \u03bc v on both spheres of a static contact. A damping "
             "factor applied each time a static contact is handled (once per pass, and once more in "
             "the shock sweep), not Coulomb's "
             "friction coefficient: 1 keeps the velocity, 0 stops it. With the momentum-conserving "
             "response, a static sphere-sphere contact damps the relative tangential velocity "
             "instead (equal and opposite impulses), so momentum stays exact.",
             param<&Params::mu>()),
        shownAsFraction(real("h", "h  time step", "s", 1e-4, 0.1, kDefaults.timeStep,
             "Slide 2: v \u2190 v + h g, p \u2190 p + h v. One step of the fixed-step loop, run as "
             "`substeps` solver steps of h / substeps. A smaller step penetrates less.",
             param<&Params::timeStep>())),
        integer("substeps", "substeps per step", 1, 64, kDefaults.substeps,
                "Solver steps per time step h, each of h / substeps: reducing the time step "
                "helps (slide 14), at the cost of more work per frame.",
                param<&Params::substeps>()),
        integer("passes", "K  collision passes", 1, 100, kDefaults.passes,
                "Slide 14: correcting one collision may induce new collisions; iterating over "
                "multiple passes helps. K passes over the contacts in every solver step.",
                param<&Params::passes>()),
        real("gravity", "|g|  gravity", "m/s\u00b2", 0.0, 50.0, glm::length(kDefaults.gravity),
             "Slide 2: the single field force F = m g, pointing along -z. 9.81 on Earth; 0 "
             "for a gas or a billiard table seen from above.",
             {gravityOf, setGravity}),
        choice("method", "method", {"position", "velocity", "response-only", "reflection", "continuous"},
               static_cast<double>(kDefaults.method),
               "Summary with multiple particles. position: velocity + position response, "
               "walls last (the slide: good avoidance of the last constraints, jitter in "
               "stacked spheres; here a stack comes nearly to rest when \u03b5 > |g| h / "
               "substeps and \u03bc well below 1 (0.5 in 09-11), and a thin wall can still be tunnelled, 13). velocity: "
               "velocity response, cancel the velocity into a penetration, then move (the "
               "slide: smooth and stable, an existing collision persists; here piles sink "
               "into themselves and jitter, 10-11). response-only: slides 5-6, collision "
               "response on speed only, no position correction. reflection: slide 7's "
               "\"approximate the correct position\", as position but moved out by (1 + \u03b2) d, "
               "where it would be had it bounced at the instant of contact. continuous: slide 7's "
               "\"go backward in time\" (continuous collision detection): each impact is found "
               "at its instant within the step and answered there, in time order (physically "
               "correct, computationally heavy; one thread).",
               param<&Params::method>()),
        choice("solver", "solver (multiple collisions)", {"sequential", "until-converged", "simultaneous", "lcp",
                                                       "generalized-reflections"},
               static_cast<double>(kDefaults.solver),
               "Slide 14: how the contacts of a step are answered. sequential: K passes, one "
               "contact at a time in the pair order, each seeing what the previous ones did (the "
               "lecture's). until-converged: the same passes until no touching contact still "
               "approaches, K the cap (the passes used are in the readouts). simultaneous: "
               "pairwise Jacobi, each pass answers every contact from the velocities at its start "
               "and applies them together: the passes no longer depend on the order (the method's own "
               "steps in pair order still do: the position projection, the velocity method's cancelling "
               "C), but a sphere hit from several sides takes every change at once (one thread). lcp: "
               "the global approach, one "
               "complementarity problem over every touching contact (impulses only push, a bounce "
               "leaves at \u03b2 times its approach), solved by projected Gauss-Seidel to 1e-12 m/s; "
               "\u03b1 and \u03bc then act on each contact's tangential velocity (one thread). "
               "generalized-reflections: Smith et al. 2012, the contacts that approach solved together "
               "elastically (blended with the inelastic answer for \u03b2 < 1), again until none "
               "approaches: touching spheres may break away, as a cradle's last ball does (one thread). "
               "Both end each step with no touching contact approaching (positivity): the contacts "
               "\u03b1 and \u03bc or the shock sweep turned back into approach are answered once more, "
               "normal impulses only, never adding energy.",
               param<&Params::solver>()),
        onlyWith(sweepsLevels, kWithLevels, choice("shock", "shock propagation", {"off", "on"},
               static_cast<double>(kDefaults.shock),
               "Slide 14: \"precompute contact graph, explicit shock propagation management\" "
               "(Guendelman et al. 2003). on: after the K passes, the spheres that touch a plane are "
               "level 0, those touching level k and none lower level k + 1; the levels are swept from "
               "the floor up, each one's contacts answered with the level below frozen (infinitely "
               "heavy, it does not move), then frozen in turn. A stack's weight reaches the floor in "
               "one sweep: with the position and reflection methods a column stands as built at any "
               "K, a pyramid without overlap at K = 1. The sweep answers overlaps (position, "
               "reflection) and static contacts only: impacts stay with the passes, so a struck "
               "stack still moves. A level's own contacts are answered again, up to three more rounds, "
               "while one is deeper than 0.1 % of r. Last, each contact still deeper than 0.5 % of r (a sphere caged "
               "between frozen spheres below and beside it, which no round clears) is split between "
               "both spheres once more, as a pass splits it. With the velocity method it projects no "
               "sphere, so an existing "
               "overlap stays (21: 3.0 % of r at K = 1), but its answers to the static contacts "
               "still hold the column up (200 % of r without it). Spheres that reach no plane keep the "
               "passes' answer.",
               param<&Params::shock>())),
        onlyWith(isContinuous, kWithContinuous, choice("toi", "time of impact", {"closed-form", "bisection"},
               static_cast<double>(kDefaults.timeOfImpact),
               "Continuous method only: how the instant of contact is found. closed-form: the "
               "earliest root of the gap, a quadratic in time along the step's parabola. "
               "bisection: the slide's binary search on the same gap, halving the interval "
               "until it is 1e-12 s long (32 to 34 halvings per impact at h = 1/60 s; "
               "about log2(step / 1e-12 s)).",
               param<&Params::timeOfImpact>())),
        onlyWith(isContinuous, kWithContinuous,
                 integer("max_events", "most impacts per sphere", 1, 100000, kDefaults.maxEventsPerSphere,
                "Continuous method only: a solver step of N spheres handles at most N times "
                "this many impacts. Past it the rest of the step is projected as the position "
                "method would, and the alarms say so: a step never hangs. A sphere at rest "
                "makes one or two impacts a step; one bouncing in place with \u03b5 = 0 (never a "
                "static contact) reaches the cap in many solver steps: 40 % of them at "
                "\u03b2 = 0.8, 50 % at 0.5.",
                param<&Params::maxEventsPerSphere>())),
        choice("response", "sphere-sphere response", {"lecture", "momentum"},
               static_cast<double>(kDefaults.response),
               "lecture: slide 12, v1 \u2190 \u03b1 v1\u2225 + \u03b2 (v1\u22a5 + j/m1 u), which "
               "conserves momentum only when \u03b1 = \u03b2 = 1 and, at static contacts, \u03bc = 1. momentum: equal and opposite impulses, "
               "(1 + \u03b2) on the normal and \u03b1 on the tangential speed: momentum is exact.",
               param<&Params::response>()),
        choice("split", "position correction split", {"half", "mass"},
               static_cast<double>(kDefaults.split),
               "Slide 13: correct position p = p \u00b1 d/2 u, half of the collision depth d "
               "each. mass: the lighter sphere moves more (by d m2/(m1 + m2) and d m1/(m1 + m2)).",
               param<&Params::split>()),
        withChoiceNotes({"", "", "", "not the lecture's"},
                        choice("order", "pair order", {"index", "reversed", "shuffled", "colored"},
                               static_cast<double>(kDefaults.order),
                               "Slide 14: the order of correction does matter. Sphere pairs are "
                               "visited in index order, reversed, or shuffled with the scene's seed. "
                               "colored is not the lecture's: the pairs are coloured so that no two "
                               "of a colour share a sphere, and visited colour by colour. It is "
                               "another fixed order of correction (compare it with index: the order "
                               "still matters), chosen for speed: threads share a colour's pairs "
                               "without waiting.",
                               param<&Params::order>())),
        zeroMeaning("auto",
                    integer("threads", "solver threads", 0, physics::kMostSolverThreads,
                            kDefaults.threads,
                            "Threads the solver uses; 0 (auto): one per usable core (at most 8) from "
                            "8192 spheres, where a second thread starts to pay, and one below; "
                            "auto tries one thread now and then and keeps it while more were "
                            "slower (other programs busy on the cores). "
                            "The result is the same, bit for bit, for any thread count, in each pair order. "
                            "The position stages visit the pairs wavefront by wavefront (on CPUs with AVX2 or "
                            "AVX-512): no two pairs of a wavefront share a sphere, each sphere meets its "
                            "partners in the pair order, and each thread takes a run of strips across the pile "
                            "through every wavefront, waiting only for its neighbours to finish the wavefront "
                            "before (in the colored order, threads take whole blocks of 4096 spheres without "
                            "waiting, runs of sphere numbers, or from 40 960 spheres places of the world, then "
                            "the pairs between blocks by wavefronts and strips). Otherwise each thread takes the pairs of its "
                            "slab of the box, and waits where a sphere met another thread's pair last. "
                            "Scenes under 4096 spheres use one thread whatever the count, and while the contacts "
                            "are logged or the impacts measured (the window's and the page's scenes up to 2000 "
                            "spheres) the contacts are answered one pair at a time, in the pair order. "
                            "A count set by hand is kept when other programs take the cores: then each stage "
                            "waits for a thread that has no core (10k spheres beside a busy program: 2 threads "
                            "4.5 times one's time); auto falls back to one.",
                            param<&Params::threads>())),
        choice("broadphase", "broad phase", {"grid", "allpairs"},
               static_cast<double>(kDefaults.broadPhase),
               "Where candidate pairs come from: a uniform grid (fast) or the lecture's loop "
               "over all N\u00b2 pairs (slow). Both find the same contacts.",
               param<&Params::broadPhase>()),
        onlyWith(hasEmitter, kWithEmitter, real("emit_period", "T  emitter period", "s", 0.01, 60.0, Emitter{}.period,
             "The course's emitter: one sphere every T seconds (\"rain into the cube\"), "
             "placed only where it overlaps nothing, else at a later step. After t seconds it "
             "has emitted floor(t / T) spheres, fewer while its spot is taken or once it "
             "reaches its maximum. Acts on the scene's first emitter.",
             {emitPeriodOf, setEmitPeriod})),
        onlyWith(hasGenerator, kWithGenerator, restart(integer("count", "N  spheres", 0, kMaxGeneratedCount, 100,
                        "Number of spheres the scene's first generator places. Applies on "
                        "restart. The panel's slider reaches 100 000: Ctrl+click it and type, or "
                        "--set, for more.",
                        {countOf, setCount}))),
        onlyWith(hasGenerator, kWithGenerator,
                 restart(real("radius", "r  sphere radius", "m", 0.005, 0.5, Generator{}.radiusMax,
                     "The largest radius of the generated spheres (all generators); setting it gives every "
                     "generated sphere this one radius. Applies on restart.",
                     {radiusOf, setRadius}))),
        restart(integer("seed", "seed", 0, kMaxSeed, 1,
                        "Seed of our own random generator: the generated spheres' "
                        "positions, radii (so masses, where set by density) and velocities, "
                        "the emitted spheres' radii and velocities, and the shuffled pair "
                        "order (a generator given its own seed in the file keeps it). Same "
                        "seed, same run. Applies on restart. The panel's slider reaches 100 000: "
                        "Ctrl+click it and type, or --set, for more.",
                        {seedOf, setSeed})),
    };
}

std::vector<std::string_view> names() {
    std::vector<std::string_view> out;
    for (const Parameter& p : parameterTable()) out.push_back(p.name);
    return out;
}

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// A whole decimal number (optionally with a leading '+'), or nothing.
bool parseNumber(std::string_view text, double& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
#if defined(__cpp_lib_to_chars)
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size() && !text.empty();
#else
    // libc++ 14 (the browser build) has no from_chars for double: strtod reads the same
    // decimals as exactly, once what from_chars refuses (spaces, hexadecimal) is refused.
    if (text.empty() || text.front() == '+' || text.find_first_of(" \t\n\r\f\vxXpP") != std::string_view::npos) {
        return false;
    }
    const std::string copy(text);
    char* end = nullptr;
    errno = 0;
    value = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size() && errno != ERANGE;  // from_chars refuses what overflows, too
#endif
}

// The number a decimal text stands for: "" or why not ("value 'TEXT' for NAME ...").
std::string parseDecimal(const Parameter& p, std::string_view text, double& value) {
    if (!parseNumber(text, value) || !std::isfinite(value)) {
        // A decimal the whole text spells, too large or too small for a double (1e400):
        // strtod reads it, out of range.
        const std::string copy(text);
        char* end = nullptr;
        errno = 0;
        std::strtod(copy.c_str(), &end);
        const bool outOfRange = !copy.empty() && end == copy.c_str() + copy.size() && errno == ERANGE;
        const bool decimalComma = copy.find(',') != std::string::npos && copy.find('.') == std::string::npos;
        return "value '" + copy + "' for " + std::string(p.name) +
               (outOfRange     ? " is beyond what a number can hold (about 1e-308 to 1e308)"
                : decimalComma ? " is not a number: write decimals with a point (0.5, not 0,5)"
                               : " is not a number");
    }
    // A whole number past 2^53 reads as its nearest double (the seed's 9007199254740993 as
    // ...992, inside the range): the digits typed must be the value kept.
    if (p.kind == ParameterKind::Integer && std::abs(value) >= 9007199254740992.0) {
        const std::string copy(text);
        char* end = nullptr;
        errno = 0;
        const long long exact = std::strtoll(copy.c_str(), &end, 10);
        const bool digits = end == copy.c_str() + copy.size();  // written as a whole number
        // (9.007199254740992e15 is 2^53 itself; past a long long, the digits as written)
        if (digits && (errno == ERANGE || static_cast<long long>(value) != exact)) {
            return std::string(p.name) + " = " + copy + " is out of range [" + formatNumber(p.min) + ", " +
                   formatNumber(p.max) + "]";
        }
    }
    return {};
}

}  // namespace

std::string parseValue(const Parameter& p, std::string_view text, double& value) {
    text = trim(text);
    if (p.kind == ParameterKind::Choice) {
        value = choiceIndex(p, text);
        if (value >= 0) return {};
        return std::string(p.name) + " = '" + std::string(text) +
               "' is not a choice; choices: " + detail::joinNames(p.choices);
    }
    if (!p.zeroMeans.empty() && text == p.zeroMeans) {  // threads=auto, as its slider shows 0
        value = 0.0;
        return {};
    }
    const std::size_t slash = text.find('/');
    if (slash == std::string_view::npos) return parseDecimal(p, text, value);
    // A fraction, as the texts write h: two decimals around one slash, each read as one.
    // A side that does not read says why, of the whole text ("is beyond what a number can hold").
    const std::string whole = "value '" + std::string(text) + "' for " + std::string(p.name);
    const std::string notANumber = whole + " is not a number (a decimal, or a fraction such as 1/240)";
    const auto side = [&](std::string_view part, double& number) -> std::string {
        if (part.empty() || part.find('/') != std::string_view::npos) return notANumber;
        const std::string error = parseDecimal(p, part, number);
        if (error.empty()) return {};
        const std::size_t name = error.find(" for " + std::string(p.name));
        if (name == std::string::npos) return error;  // "seed = 9007199254740993 is out of range [...]"
        const std::string why = error.substr(name + 5 + p.name.size());
        return why == " is not a number" ? notANumber : whole + why;
    };
    double numerator = 0.0, denominator = 0.0;
    if (std::string error = side(trim(text.substr(0, slash)), numerator); !error.empty()) return error;
    if (std::string error = side(trim(text.substr(slash + 1)), denominator); !error.empty()) return error;
    value = numerator / denominator;
    if (denominator == 0.0 || !std::isfinite(value)) {
        return "value '" + std::string(text) + "' for " + std::string(p.name) + " divides by zero or overflows";
    }
    return {};
}

const std::vector<Parameter>& parameterTable() {
    static const std::vector<Parameter> table = makeTable();
    return table;
}

std::string Parameter::choiceShown(std::size_t k) const {
    std::string shown(choices.at(k));
    if (k < choiceNotes.size() && !choiceNotes[k].empty()) shown += " (" + std::string(choiceNotes[k]) + ")";
    return shown;
}

const Parameter* findParameter(std::string_view name) {
    for (const Parameter& p : parameterTable()) {
        if (p.name == name) return &p;
    }
    return nullptr;
}

std::string fractionShown(const Parameter& p, double value) {
    if (!p.shownAsFraction || !(value > 0.0)) return "";
    const double n = std::round(1.0 / value);
    if (n < 2.0 || n > 100000.0 || std::abs(1.0 / n - value) > 4e-16 * value) return "";
    return "1/" + std::to_string(static_cast<long>(n));
}

std::string formatNumber(double value) {
    // Plain decimals for the sizes people type (1000000, 0.0001), exponents beyond.
    const double size = std::abs(value);
    const bool plain = size == 0.0 || (size >= 1e-6 && size < 1e16);
    char buffer[400];
#if defined(__cpp_lib_to_chars)
    const auto result =
        plain ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
              : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
#else
    // libc++ 14 (the browser build): the fewest digits that read back as the same double,
    // as to_chars writes them.
    for (int digits = 0; digits <= 40; ++digits) {
        std::snprintf(buffer, sizeof buffer, plain ? "%.*f" : "%.*e", digits, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
#endif
}

std::string checkValue(const Parameter& p, double value) {
    const std::string unit = p.unit.empty() ? "" : " " + std::string(p.unit);
    if (!std::isfinite(value)) return std::string(p.name) + " must be a finite number";
    if (value < p.min || value > p.max) {
        return std::string(p.name) + " = " + formatNumber(value) + " is out of range [" +
               formatNumber(p.min) + ", " + formatNumber(p.max) + "]" + unit;
    }
    if (p.kind != ParameterKind::Real && value != std::floor(value)) {
        return std::string(p.name) + " = " + formatNumber(value) + " must be a whole number";
    }
    return {};
}

int choiceIndex(const Parameter& p, std::string_view name) {
    for (std::size_t i = 0; i < p.choices.size(); ++i) {
        if (p.choices[i] == name) return static_cast<int>(i);
    }
    return -1;
}

std::string setValue(const Parameter& p, Scene& scene, double value) {
    std::string error = checkValue(p, value);
    return error.empty() ? p.set(scene, value) : error;
}

namespace {

// The answer on one line whatever the input held: control characters quoted from it
// (a newline, found by the fuzzer) are shown as \xNN.
std::string oneLineAnswer(const std::string& text) {
    std::string line;
    for (const char c : text) {
        if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
            line += c;
            continue;
        }
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
        line += escaped;
    }
    return line;
}

std::string applyAssignment(Scene& scene, std::string_view assignment) {
    const auto equals = assignment.find('=');
    if (equals == std::string_view::npos) {
        return "expected name=value, got '" + std::string(assignment) + "'";
    }
    const std::string_view name = trim(assignment.substr(0, equals));
    const Parameter* p = findParameter(name);
    if (!p) return detail::unknownName("parameter", name, names());
    double value = 0.0;
    std::string error = parseValue(*p, trim(assignment.substr(equals + 1)), value);
    return error.empty() ? setValue(*p, scene, value) : error;
}

}  // namespace

std::string applySetting(Scene& scene, std::string_view assignment) {
    return oneLineAnswer(applyAssignment(scene, assignment));
}

std::string settingsThatActOnNothing(const Scene& scene, const std::vector<std::string>& settings) {
    for (const std::string& setting : settings) {
        const Parameter* p = findParameter(settingName(setting));
        if (!p || p->availableIn(scene)) continue;
        std::string why = setting + ": " + std::string(p->name) + " " + std::string(p->availableWhen);
        const Parameter* method = findParameter("method");
        if (method && (p->available == isContinuous || p->available == sweepsLevels)) {  // a method's: name the run's
            why += ", and this run's is " + formatValue(*method, scene);
        }
        return why;
    }
    return "";
}

std::string formatValue(const Parameter& p, const Scene& scene) {
    const double value = p.get(scene);
    if (p.kind == ParameterKind::Choice) {
        const auto i = static_cast<std::size_t>(value);
        return i < p.choices.size() ? std::string(p.choices[i]) : formatNumber(value);
    }
    if (p.kind == ParameterKind::Integer) return formatNumber(std::round(value));
    return formatNumber(value);
}

}  // namespace scenes
