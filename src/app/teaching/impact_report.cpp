#include "app/teaching/impact_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace app {

// A property's value where the continuous method leaves it unmeasured.
constexpr const char* kNotMeasuredUnderContinuous = "not measured under the continuous method";
namespace {

// Relative (momentum, energy) and absolute (m/s, m) slack of a kept property: rounding.
constexpr double kKeptSlack = 1e-9;

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

PropertyVerdict momentum(const ImpactRecord& r) {
    PropertyVerdict v{"momentum", "", Verdict::Untested,
                      "Total momentum of the colliding spheres is kept: |change| / \u03a3 m|v| of the clusters that "
                      "touch no wall (a wall takes momentum). The lecture's response (slide 12) and its static "
                      "contact (slide 13, v \u2190 \u03bc v) act on each sphere's own velocity and do not keep it in "
                      "general: a touching pair falling together is braked. response = momentum keeps it."};
    if (r.total.momentumScale <= 0.0) {
        v.value = "no free cluster struck";
        return v;
    }
    v.value = format("change %.1e of sum m|v|", r.worstMomentumChange);
    v.verdict = r.worstMomentumChange <= kKeptSlack ? Verdict::Kept : Verdict::Broken;
    return v;
}

PropertyVerdict energy(const ImpactRecord& r, const physics::Params& params) {
    PropertyVerdict v{"energy", "", Verdict::Untested,
                      "Kinetic energy of the struck clusters after / before the contacts of a step: never more, "
                      "and kept exactly when the contacts are elastic (\u03b2 = 1, \u03b1 = 1, \u03bc = 1 and \u03b5 = "
                      "0: no friction, no damped static contact)."};
    if (r.worstEnergyRatio < 0.0) {
        v.value = "nothing struck";
        return v;
    }
    v.value = r.leastEnergyRatio < r.worstEnergyRatio - kKeptSlack
                  ? format("after/before %.4f to %.4f", r.leastEnergyRatio, r.worstEnergyRatio)
                  : format("after/before %.6f", r.worstEnergyRatio);
    const bool gained = r.worstEnergyRatio > 1.0 + kKeptSlack;
    const bool elastic = params.beta >= 1.0 && params.alpha >= 1.0 && params.mu >= 1.0 && params.epsilon <= 0.0;
    const bool lostElastic = elastic && r.leastEnergyRatio < 1.0 - kKeptSlack;
    v.verdict = gained || lostElastic ? Verdict::Broken : Verdict::Kept;
    if (lostElastic) v.value += " (elastic: lost)";
    return v;
}

PropertyVerdict symmetry(const std::vector<physics::MirrorAsymmetry>& mirrors) {
    PropertyVerdict v{"symmetry", "", Verdict::Untested,
                      "A mirror-symmetric scene stays mirror-symmetric: the farthest any sphere's mirror partner "
                      "is from its reflected velocity (m/s) and place (m). The scene declares its mirrors."};
    if (mirrors.empty()) {
        v.value = "the scene declares no mirror";
        return v;
    }
    physics::MirrorAsymmetry worst;
    for (const physics::MirrorAsymmetry& m : mirrors) {
        if (m.velocity < 0.0) {
            v.value = "too many spheres to measure";
            return v;
        }
        worst.velocity = std::max(worst.velocity, m.velocity);
        worst.position = std::max(worst.position, m.position);
    }
    v.value = format("off by %.2g m/s, %.2g m", worst.velocity, worst.position);
    v.verdict = worst.velocity <= kKeptSlack && worst.position <= kKeptSlack ? Verdict::Kept : Verdict::Broken;
    return v;
}

PropertyVerdict breakAway(const ImpactRecord& r) {
    PropertyVerdict v{"break-away", "", Verdict::Untested,
                      "Touching spheres that did not approach may part, as a cradle's last ball does: resting "
                      "pairs of a cluster an impact struck (a contact faster than \u03b5) that separated. A "
                      "stack at rest tests nothing."};
    const auto& t = r.total;
    if (t.restingPairs == 0) {
        v.value = "no resting pair an impact struck";
        return v;
    }
    v.value = format("%.0f of %.0f resting pairs parted", double(t.brokeAway), double(t.restingPairs));
    v.verdict = t.brokeAway > 0 ? Verdict::Kept : Verdict::Broken;
    return v;
}

PropertyVerdict positivity(const ImpactRecord& r, const physics::Params& params) {
    PropertyVerdict v{"positivity", "", Verdict::Untested,
                      "Impulses only push, so no contact still approaches after the contacts of a step: the "
                      "fastest approach left (m/s), kept up to 10\u207b\u2076 of a solver step's gravity, g h / substeps "
                      "(rounding; at least 10\u207b\u2079 m/s)."};
    if (r.total.contacts == 0) {
        v.value = "no contact";
        return v;
    }
    v.value = format("fastest approach left %.2g m/s", r.total.fastestApproachAfter);
    const double slack = std::max(kKeptSlack, 1e-6 * glm::length(params.gravity) * params.solverStep());  // m/s
    v.verdict = r.total.fastestApproachAfter <= slack ? Verdict::Kept : Verdict::Broken;
    return v;
}

}  // namespace

void ImpactRecord::add(const physics::ImpactProperties& step) {
    total += step;
    if (step.momentumScale > 0.0) {
        worstMomentumChange = std::max(worstMomentumChange, step.momentumChange / step.momentumScale);
    }
    if (step.struck > 0 && step.kineticBefore > 0.0) {
        const double ratio = step.kineticAfter / step.kineticBefore;
        worstEnergyRatio = std::max(worstEnergyRatio, ratio);
        leastEnergyRatio = leastEnergyRatio < 0.0 ? ratio : std::min(leastEnergyRatio, ratio);
    }
}

std::vector<PropertyVerdict> judgeProperties(const ImpactRecord& record,
                                             const std::vector<physics::MirrorAsymmetry>& mirrors,
                                             const physics::Params& params) {
    std::vector<PropertyVerdict> verdicts{momentum(record), energy(record, params), symmetry(mirrors),
                                          breakAway(record), positivity(record, params)};
    // The contacts' properties are measured around the K passes of a step; the continuous
    // method meets its impacts one at a time within the step instead (symmetry is the state's).
    if (params.method == physics::Method::Continuous) {
        for (PropertyVerdict& v : verdicts) {
            if (v.name == "symmetry") continue;
            v.verdict = Verdict::Untested;
            v.value = kNotMeasuredUnderContinuous;
        }
    }
    return verdicts;
}

namespace {

const char* markOf(Verdict verdict) {
    return verdict == Verdict::Kept ? "\u2713" : verdict == Verdict::Broken ? "\u2717" : "\u2013";  // an en dash: a browser breaks a line after a hyphen
}

}  // namespace

std::string propertiesLine(const std::vector<PropertyVerdict>& verdicts) {
    std::string line;
    for (const PropertyVerdict& v : verdicts) {
        if (!line.empty()) line += " | ";
        line += v.name + " " + markOf(v.verdict) + " " + v.value;
    }
    return line;
}

std::string propertiesMarks(const std::vector<PropertyVerdict>& verdicts) {
    // Five dashes said nothing to a student: one line while no impact has tested any of them
    // ("yet" under the continuous method, whose contacts they are not measured on, was false
    // for a whole run).
    if (std::all_of(verdicts.begin(), verdicts.end(), [](const PropertyVerdict& v) { return v.verdict == Verdict::Untested; })) {
        const bool continuous = std::any_of(verdicts.begin(), verdicts.end(),
                                            [](const PropertyVerdict& v) { return v.value == kNotMeasuredUnderContinuous; });
        return continuous ? "properties: not measured under the continuous method" : "properties: none tested yet";
    }
    std::string line;
    for (std::size_t k = 0; k < verdicts.size(); ++k) {
        if (k > 0) line += k == 3 ? "\n" : "  ";  // two lines: a label stays narrow
        line += std::string(markOf(verdicts[k].verdict)) + "\u00a0" + verdicts[k].name;  // wraps between marks
    }
    // Under the continuous method only the symmetry is measured: its dashes say why (a
    // projector's short line read "nothing broken" from the symmetry alone).
    const bool continuous = std::any_of(verdicts.begin(), verdicts.end(),
                                        [](const PropertyVerdict& v) { return v.value == kNotMeasuredUnderContinuous; });
    if (continuous) line += std::string("\n") + kOthersNotMeasured;
    return line;
}

std::string propertiesTooltip(const std::vector<PropertyVerdict>& verdicts) {
    std::string tip = "Smith et al.'s five properties of the contacts since the restart (slide 14):";
    for (const PropertyVerdict& v : verdicts) {
        tip += std::string("\n\n") + markOf(v.verdict) + " " + v.name + (v.value.empty() ? "" : ": " + v.value) + "\n" + v.meaning;
    }
    return tip;
}

}  // namespace app
