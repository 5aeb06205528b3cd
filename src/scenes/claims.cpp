#include "scenes/claims.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "physics/step.h"
#include "scenes/claim_meters.h"
#include "scenes/parameters.h"
#include "scenes/scene.h"
#include "scenes/suggest.h"

namespace scenes {

namespace {

const std::vector<std::string_view> kTakes = {"each", "min", "max", "mean", "first", "last", "count"};

// The preset after `settings`; "" or why one does not apply.
std::string applyAll(Scene& scene, const std::vector<std::string>& settings) {
    for (const std::string& s : settings) {
        const std::string error = applySetting(scene, s);
        if (!error.empty()) return error;
    }
    return "";
}

std::string key(const std::vector<std::string>& settings) {
    std::string out;
    for (const std::string& s : settings) out += s + "\n";
    return out;
}

// One scalar from the samples, or none when there are none (or take is "each").
std::optional<double> taken(const Claim& claim, const std::vector<double>& s) {
    if (claim.take == "count") return static_cast<double>(s.size());
    if (claim.nth > 0) {
        if (s.size() < static_cast<std::size_t>(claim.nth)) return std::nullopt;
        return s[static_cast<std::size_t>(claim.nth) - 1];
    }
    if (s.empty() || claim.take == "each") return std::nullopt;
    if (claim.take == "min") return *std::min_element(s.begin(), s.end());
    if (claim.take == "max") return *std::max_element(s.begin(), s.end());
    if (claim.take == "first") return s.front();
    if (claim.take == "last") return s.back();
    double sum = 0.0;
    for (double x : s) sum += x;
    return sum / static_cast<double>(s.size());
}

bool meets(const Claim& c, double x) {
    if (!std::isfinite(x)) return false;
    if (c.near && std::abs(x - *c.near) > c.within.value_or(0.0)) return false;
    if (c.min && x < *c.min) return false;
    if (c.max && x > *c.max) return false;
    return true;
}

// A fraction of r is shown as the texts say it, a percentage: the factor for `unit`.
double shownScale(const std::string& unit) { return unit == " r" ? 100.0 : 1.0; }

// What the claim asks, in the unit its value is shown in (a fraction of r as a percentage),
// six digits: "0.2616 ± 0.001 m/s", "≥ 0.1", "≤ 1e-07 % of r". Without the unit after a
// value that has it: "= 0 % of r (≤ 1e-07)".
std::string expected(const Claim& c, const std::string& unit, bool withUnit) {
    const double scale = shownScale(unit);
    std::ostringstream out;
    out.precision(6);
    if (c.near) out << scale * *c.near << " \u00b1 " << scale * c.within.value_or(0.0);
    if (c.min) out << (c.near ? ", " : "") << "\u2265 " << scale * *c.min;
    if (c.max) out << (c.near || c.min ? ", " : "") << "\u2264 " << scale * *c.max;
    if (withUnit) out << (unit == " r" ? std::string(" % of r") : unit);
    return out.str();
}

// " m", " J", or "" for a ratio or a count: the unit of the claim's meter.
std::string unitOf(const Claim& c) {
    if (c.take == "count") return "";
    for (const ClaimMeter& m : claimMeters()) {
        if (m.name == c.measure) return m.unit.empty() ? "" : " " + std::string(m.unit);
    }
    return "";
}

// A value (or two, "lo to hi") in the claim's unit, four digits; a fraction of r as the
// texts say it, "19.27 % of r".
std::string valueShown(double lo, double hi, const std::string& unit) {
    const double scale = shownScale(unit);
    std::ostringstream out;
    out.precision(4);
    out << scale * lo;
    if (hi != lo) out << " to " << scale * hi;
    out << (unit == " r" ? std::string(" % of r") : unit);
    return out.str();
}

std::string range(const std::vector<double>& s, const std::string& unit) {
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    std::string text = valueShown(*lo, *hi, unit);
    if (s.size() > 1) text += " (" + std::to_string(s.size()) + " samples)";
    return text;
}

// Whether a meter needs the steps' contacts measured (World::measureImpacts).
bool anyNeedsImpacts(const std::vector<std::unique_ptr<detail::Meter>>& meters) {
    return std::any_of(meters.begin(), meters.end(), [](const auto& m) { return m && m->needsImpacts(); });
}

// One run of one variant: every meter watches it until the last stretch ends.
class VariantRun {
  public:
    explicit VariantRun(Scene variant) : variant_(std::move(variant)) {}

    detail::Meter* add(const Claim& claim) {
        meters_.push_back(detail::makeMeter(claim, variant_));
        end_ = std::max(end_, claim.to);
        return meters_.back().get();
    }

    void run() {
        physics::World world = buildWorld(variant_);
        world.measureImpacts = anyNeedsImpacts(meters_);
        const double half = 0.5 * variant_.params.timeStep;
        observe(world);
        while (world.time < end_ - half) {
            const physics::StepStats stats = physics::step(world, variant_.params);
            for (const auto& meter : meters_) {
                if (meter) meter->stepped(stats);
            }
            emitDue(variant_, world);
            observe(world);
        }
    }

  private:
    void observe(const physics::World& world) {
        for (const auto& meter : meters_) {
            if (meter) meter->observe(world);
        }
    }

    Scene variant_;
    std::vector<std::unique_ptr<detail::Meter>> meters_;
    double end_ = 0.0;
};

// A setting claim's value as the panel names it: "method = position", not "0".
std::string settingShown(const Claim& c, const ClaimCheck& check) {
    const Parameter* p = findParameter(c.parameter);
    const auto shown = [&](double value) {
        if (p->kind == ParameterKind::Choice && value >= 0.0 && value < double(p->choices.size())) {
            return p->choiceShown(std::size_t(value));
        }
        std::ostringstream out;  // four digits and the unit: "h = 0.03333 s"
        out.precision(4);
        out << value << (p->unit.empty() ? "" : " ") << p->unit;
        return out.str();
    };
    std::optional<double> value = check.value;  // a setting holds throughout: any sample is it
    if (!value && !check.samples.empty()) value = check.samples.back();
    std::string text = std::string(p->name) + " = " + (value ? shown(*value) : "nothing measured");
    if (!check.holds && c.near) text += ", expected " + shown(*c.near);
    return text;
}

// " of spheres #0, #1, #5–#9" (or " among #1–#15", for a count of them), as the inspector
// names a sphere; "" for the meter's own.
std::string spheresShown(const std::vector<int>& spheres, bool among) {
    if (spheres.empty()) return "";
    std::string text = among ? " among " : spheres.size() == 1 ? " of sphere " : " of spheres ";
    for (std::size_t k = 0; k < spheres.size();) {  // runs of numbers as "#1–#15"
        std::size_t end = k + 1;
        while (end < spheres.size() && spheres[end] == spheres[end - 1] + 1) ++end;
        text += (k ? ", #" : "#") + std::to_string(spheres[k]);
        if (end - k > 2) text += "\u2013#" + std::to_string(spheres[end - 1]);
        else if (end - k == 2) text += ", #" + std::to_string(spheres[end - 1]);
        k = end;
    }
    return text;
}

// " to the floor", " of plane 0": which plane a plane meter reads, named as the explainer
// names it (the box's walls by their place, the scene's own planes from 0); "" for other
// meters.
std::string planeShown(const Claim& c) {
    const bool to = c.measure == "plane_distance" || c.measure == "gap";
    if (!to && c.measure.rfind("plane_", 0) != 0) return "";
    static const char* const kBox[] = {"the floor", "the ceiling", "wall \u2212x", "wall +x", "wall \u2212y", "wall +y"};
    const std::string plane = c.plane < c.boxPlanes && c.plane < 6 ? kBox[c.plane]
                                                                   : "plane " + std::to_string(c.plane - c.boxPlanes);
    return (to ? " to " : " of ") + plane;
}

// The meter's name in words: "wall_contact_at" as "time of the first wall contact",
// "plane_tilt" as "tilt" (planeShown names the plane), else its name without underscores.
std::string meterShown(const Claim& c) {
    static const std::pair<const char*, const char*> kWords[] = {
        {"hash_changes", "steps that changed the state"},  // the hash is the panel's word, not a student's
        {"wall_contact_at", "time of the first wall contact"},
        {"left_box_at", "time the centre first left the box"},
        {"impact_end", "time each impact ended"},
        {"moving", "spheres moving faster than 1 cm/s"},
    };
    for (const auto& [measure, words] : kWords) {
        if (c.measure == measure) return words;
    }
    std::string name = planeShown(c).empty() ? c.measure : c.measure.substr(c.measure.rfind("plane_", 0) == 0 ? 6 : 0);
    std::replace(name.begin(), name.end(), '_', ' ');
    return name;
}

// The quantity a claim measures, named as a reader of the panel needs it beside a bare
// number: "max bounce ratio of sphere #0", "bounce loss, samples", "distance to plane 0 at
// t = 0.15 s", "steps that changed the state over t = 1.2–10 s", "speed / the same with
// mu=0.5".
std::string quantityShown(const Claim& c) {
    std::string name = meterShown(c);
    if (c.nth > 0) name = "sample " + std::to_string(c.nth) + " of " + name;
    else if (c.take == "count") name += ", samples";
    else if (c.take != "each") name = c.take + " " + name;
    name += spheresShown(c.spheres, c.measure == "moving") + planeShown(c);
    std::ostringstream when;  // an instant, "at t = 0.25 s", or a stretch, "over t = 1.2–10 s"
    when.precision(4);
    // At t = 0 too ("stays under" measured at the start only passed unsaid), but for what a
    // run never changes.
    static const std::vector<std::string> kFixed = {"mass", "plane_tilt", "plane_thickness", "gravity_per_step"};
    const bool fixed = std::find(kFixed.begin(), kFixed.end(), c.measure) != kFixed.end();
    if (c.from == c.to && (c.to > 0.0 || !fixed)) when << " at t = " << c.to << " s";
    if (c.from < c.to) when << " over t = " << c.from << "\u2013" << c.to << " s";
    name += when.str();
    if (c.ratioTo) {
        name += c.ratioTo->empty() ? " / the same at the preset's own settings" : " / the same with";
        for (const std::string& s : *c.ratioTo) name += " " + s;
    }
    return name;
}

// No sample: an event (an apex, a bounce) that did not happen in the stretch, which at one
// instant (a claim without "to") is almost sure.
std::string nothingMeasured(const Claim& c) {
    return c.from == c.to ? "nothing measured (at one instant: an event needs a stretch, \"from\" and \"to\")"
                          : "nothing measured";
}

void judge(ClaimCheck& check, const std::vector<double>* ratioSamples, std::size_t spheresInRun) {
    const Claim& c = *check.claim;
    const int highest = c.spheres.empty() ? -1 : *std::max_element(c.spheres.begin(), c.spheres.end());
    if (highest >= 0 && std::size_t(highest) >= spheresInRun) {
        check.holds = false;
        check.measured = quantityShown(c) + ": no sphere #" + std::to_string(highest) + " in the run (it had " +
                         std::to_string(spheresInRun) + ", numbered from 0)";
        return;
    }
    check.value = taken(c, check.samples);
    if (ratioSamples && check.value) {
        const std::optional<double> below = taken(c, *ratioSamples);
        check.value = below ? std::optional<double>(*check.value / *below) : std::nullopt;
    }
    const std::string unit = ratioSamples ? std::string() : unitOf(c);  // a ratio has none
    std::ostringstream out;
    out.precision(4);
    if (c.take == "each" && c.nth == 0 && !ratioSamples) {
        check.holds = !check.samples.empty() &&
                      std::all_of(check.samples.begin(), check.samples.end(), [&](double x) { return meets(c, x); });
        out << (check.samples.empty() ? nothingMeasured(c) : range(check.samples, unit));
    } else {
        check.holds = check.value && meets(c, *check.value);
        if (check.value) out << valueShown(*check.value, *check.value, unit);
        else out << nothingMeasured(c);
    }
    if (!check.holds) out << ", expected " << expected(c, unit, true);
    else if (!c.near) out << " (" << expected(c, unit, unit == " r") << ")";  // a bound: what was checked (in % of r, its unit: 4 meant 400 %)
    check.measured = c.measure == "setting" ? settingShown(c, check) : quantityShown(c) + " = " + out.str();
}

}  // namespace

std::string checkClaimForm(const Claim& c, const Scene& preset) {
    Scene variant = preset;
    if (std::string e = applyAll(variant, c.settings); !e.empty()) return "set: " + e;
    if (c.ratioTo) {
        Scene other = preset;
        if (std::string e = applyAll(other, *c.ratioTo); !e.empty()) return "ratio_to: " + e;
    }
    // A quote the description does not hold would be shown to the class as the text's.
    if (c.in == ClaimSource::Description && preset.description.find(c.says) == std::string::npos) {
        return "says \"" + c.says + "\", which the description does not (a claim quotes it word for word)";
    }
    const auto& meters = claimMeters();
    if (std::none_of(meters.begin(), meters.end(), [&](const ClaimMeter& m) { return m.name == c.measure; })) {
        std::vector<std::string_view> names;
        for (const ClaimMeter& m : meters) names.push_back(m.name);
        return detail::unknownName("measure", c.measure, names) + " (`spheres claims --measures` says what each is)";
    }
    if (c.measure == "setting") {
        if (c.parameter.empty()) return "setting needs \"name\": a parameter's name";
        if (!findParameter(c.parameter)) {
            std::vector<std::string_view> names;
            for (const Parameter& p : parameterTable()) names.push_back(p.name);
            return detail::unknownName("parameter", c.parameter, names);
        }
    }
    if (std::find(kTakes.begin(), kTakes.end(), c.take) == kTakes.end()) {
        return "unknown take '" + c.take + "' (each, min, max, mean, first, last or count)";
    }
    if (!(c.from >= 0.0 && c.to >= c.from && c.to <= kMaxClaimTime)) {
        return "from " + formatNumber(c.from) + " s and to " + formatNumber(c.to) + " s: they must satisfy 0 <= from <= to <= " +
               formatNumber(kMaxClaimTime) + " s";
    }
    if (c.near.has_value() != c.within.has_value()) return "near and within go together";
    if (!c.near && !c.min && !c.max) return "a claim needs near and within, min or max";
    if (c.within && !(*c.within >= 0.0)) return "within must be at least 0";
    if (c.min && c.max && *c.min > *c.max) return "min is above max: no value meets both";
    const std::size_t planes = (variant.box ? boxPlanes(*variant.box).size() : 0) + variant.planes.size();
    if (!planeShown(c).empty() && std::size_t(c.plane) >= planes) {
        return "plane " + std::to_string(c.plane) + " is not one of the scene's " + std::to_string(planes) +
               " planes (the box's first, numbered from 0)";
    }
    if (c.ratioTo && c.take == "each" && c.nth == 0) return "ratio_to needs one value: a take other than each, or nth";
    // Without an emitter the spheres are known before the run (with one, the run says it).
    if (!c.spheres.empty() && variant.emitters.empty()) {
        const int highest = *std::max_element(c.spheres.begin(), c.spheres.end());
        const std::size_t count = builtSphereCount(variant);
        if (std::size_t(highest) >= count) {
            return "no sphere #" + std::to_string(highest) + " in the scene (it has " + std::to_string(count) + ", numbered from 0)";
        }
    }
    return "";
}

std::vector<ClaimCheck> checkClaims(const Scene& preset) {
    // One run per distinct settings list; a ratio's denominator runs in its own variant.
    std::map<std::string, std::unique_ptr<VariantRun>> runs;
    const auto runFor = [&](const std::vector<std::string>& settings) -> VariantRun& {
        auto& run = runs[key(settings)];
        if (!run) {
            Scene variant = preset;
            applyAll(variant, settings);
            run = std::make_unique<VariantRun>(std::move(variant));
        }
        return *run;
    };
    std::vector<ClaimCheck> checks(preset.claims.size());
    std::vector<const detail::Meter*> meters(checks.size()), ratioMeters(checks.size());
    for (std::size_t k = 0; k < checks.size(); ++k) {
        const Claim& c = preset.claims[k];
        checks[k].claim = &c;
        meters[k] = runFor(c.settings).add(c);
        if (c.ratioTo) ratioMeters[k] = runFor(*c.ratioTo).add(c);
    }
    for (auto& entry : runs) entry.second->run();
    for (std::size_t k = 0; k < checks.size(); ++k) {
        if (meters[k]) checks[k].samples = meters[k]->samples();
        judge(checks[k], ratioMeters[k] ? &ratioMeters[k]->samples() : nullptr, meters[k] ? meters[k]->mostSpheres() : 0);
    }
    return checks;
}

std::vector<double> tableValues(const Scene& scene) {
    std::vector<double> values;
    for (const Parameter& p : parameterTable()) values.push_back(p.availableIn(scene) ? p.get(scene) : -INFINITY);
    return values;
}

void stampClaimVariants(Scene& scene) {
    for (Claim& claim : scene.claims) {
        Scene variant = scene;
        variant.claims.clear();
        applyAll(variant, claim.settings);
        claim.variant = tableValues(variant);
        claim.boxPlanes = variant.box ? static_cast<int>(boxPlanes(*variant.box).size()) : 0;
    }
}

struct LiveClaims::Watch {
    Scene scene;
    std::vector<Claim> claims;
    std::vector<std::unique_ptr<detail::Meter>> meters;
    double halfStep = 0.0;  // s: a sample counts for its stretch within half a step
};

LiveClaims::LiveClaims() = default;
LiveClaims::~LiveClaims() = default;
LiveClaims::LiveClaims(LiveClaims&&) noexcept = default;
LiveClaims& LiveClaims::operator=(LiveClaims&&) noexcept = default;
LiveClaims::LiveClaims(const LiveClaims&) : LiveClaims() {}
LiveClaims& LiveClaims::operator=(const LiveClaims& other) {
    if (this != &other) watch_.reset();
    return *this;
}

LiveClaims::LiveClaims(const Scene& scene) : watch_(std::make_unique<Watch>()) {
    Watch& w = *watch_;
    w.scene = scene;
    w.scene.claims.clear();
    w.halfStep = 0.5 * scene.params.timeStep;
    const std::vector<double> now = tableValues(scene);
    for (const Claim& claim : scene.claims) {
        if (claim.in == ClaimSource::Description && !claim.ratioTo && claim.variant == now) w.claims.push_back(claim);
    }
    // The claims stay where they are now: each meter keeps a reference to its own.
    for (const Claim& claim : w.claims) w.meters.push_back(detail::makeMeter(claim, w.scene));
}

std::size_t LiveClaims::size() const { return watch_ ? watch_->claims.size() : 0; }

bool LiveClaims::needsImpacts() const { return watch_ && anyNeedsImpacts(watch_->meters); }

double LiveClaims::lastMoment() const {
    double last = 0.0;
    if (watch_) {
        for (const Claim& c : watch_->claims) last = std::max(last, c.to);
    }
    return last;
}

void LiveClaims::observe(const physics::World& world, const physics::StepStats* stepped) {
    if (!watch_) return;
    for (const auto& meter : watch_->meters) {
        if (!meter) continue;
        if (stepped) meter->stepped(*stepped);
        meter->observe(world);
    }
}

std::vector<ClaimCheck> LiveClaims::judged(double time) const {
    std::vector<ClaimCheck> checks;
    if (!watch_) return checks;
    const Watch& w = *watch_;
    for (std::size_t k = 0; k < w.claims.size(); ++k) {
        if (time < w.claims[k].to - w.halfStep) continue;
        ClaimCheck check;
        check.claim = &w.claims[k];
        if (w.meters[k]) check.samples = w.meters[k]->samples();
        judge(check, nullptr, w.meters[k] ? w.meters[k]->mostSpheres() : 0);
        checks.push_back(std::move(check));
    }
    return checks;
}

}  // namespace scenes
