#include "app/teaching/contact_explanation.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include <glm/geometric.hpp>

#include "physics/collision_response.h"

namespace app {
namespace {

using Line = ExplanationLine;

double reducedMass(double m1, double m2) { return 1.0 / (1.0 / m1 + 1.0 / m2); }  // kg

// Slide 4 and slide 13 for a plane of normal n.
glm::dvec3 predictPlane(const glm::dvec3& v, const glm::dvec3& n, bool isStatic, const physics::Params& params) {
    const VelocitySplit s = splitVelocity(v, n);
    if (!isStatic) return params.alpha * s.par - params.beta * s.perp;
    const glm::dvec3 stopped = s.normal < 0.0 ? v - s.perp : v;  // no bounce
    return params.mu * stopped;
}

// Slides 11-13 for two spheres, in the chosen response model.
// Whether a static pair's mu acts on the spheres' relative tangential velocity (equal and
// opposite impulses) rather than on each sphere's own velocity (slide 13's v <- mu v): the
// momentum response, the continuous method, and a contact slide 14's global solvers answered
// (their alpha and mu act on each contact's relative tangential velocity after the normal
// solve). The shock sweep answers its contacts pair by pair, in the chosen response.
bool relativeFriction(const physics::Params& params, bool solvedTogether) {
    return physics::frictionOnRelativeVelocity(params) || solvedTogether;
}

// Why: the name of what makes relativeFriction true.
const char* relativeFrictionCause(const physics::Params& params, bool solvedTogether) {
    if (solvedTogether && params.solver == physics::Solver::Lcp) return "lcp";
    if (solvedTogether && params.solver == physics::Solver::GeneralizedReflections) return "generalized reflections";
    if (params.response == physics::ResponseModel::MomentumConserving) return "the momentum-conserving response";
    return "the continuous method";
}

void predictPair(const glm::dvec3 v[2], const double m[2], const glm::dvec3& u, bool isStatic, bool undamped,
                 bool relative, const physics::Params& params, glm::dvec3 out[2]) {
    const double mass = reducedMass(m[0], m[1]);
    const double s = glm::dot(v[1] - v[0], u);  // m/s, approaching when > 0
    const bool lecture = params.response == physics::ResponseModel::LectureAttenuation;
    if (isStatic) {
        const double jc = s > 0.0 ? mass * s : 0.0;  // kg m/s, perfectly inelastic
        out[0] = v[0] + (jc / m[0]) * u;
        out[1] = v[1] - (jc / m[1]) * u;
        if (undamped) return;
        if (!relative) {
            out[0] *= params.mu;
            if (std::isfinite(m[1])) out[1] *= params.mu;  // a frozen sphere keeps its velocity
        } else {
            const glm::dvec3 slip = out[1] - out[0];  // m/s
            const glm::dvec3 impulse = (1.0 - params.mu) * mass * (slip - glm::dot(slip, u) * u);
            out[0] += impulse / m[0];
            out[1] -= impulse / m[1];
        }
        return;
    }
    if (lecture) {
        const double j = 2.0 * mass * s;  // slide 11
        const VelocitySplit a = splitVelocity(v[0], u), b = splitVelocity(v[1], u);
        out[0] = params.alpha * a.par + params.beta * (a.perp + (j / m[0]) * u);
        out[1] = params.alpha * b.par + params.beta * (b.perp - (j / m[1]) * u);
        return;
    }
    const glm::dvec3 tangential = (v[1] - v[0]) - s * u;
    const glm::dvec3 impulse = (1.0 + params.beta) * mass * s * u + (1.0 - params.alpha) * mass * tangential;
    out[0] = v[0] + impulse / m[0];
    out[1] = v[1] - impulse / m[1];
}

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...) {
    char text[320];
    va_list args;
    va_start(args, pattern);
    std::vsnprintf(text, sizeof text, pattern, args);
    va_end(args);
    return text;
}

// -0.000 reads as a sign error on a slide: print it as 0.000.
double clean(double x) { return std::abs(x) < 5e-4 ? 0.0 : x; }

// m: a depth as shown to %.4g; one at rounding's size (-1.4e-17 m where a continuous contact
// meets exactly) is 0.
double depthShown(double depth) { return std::abs(depth) < 1e-12 ? 0.0 : depth; }

std::string vec(const glm::dvec3& v) { return format("(%.3f, %.3f, %.3f)", clean(v.x), clean(v.y), clean(v.z)); }

void add(std::vector<Line>& lines, Line::Kind kind, std::string text) { lines.push_back({kind, std::move(text)}); }

// "v1⊥ = -2.000 u,  v1∥ = (...)" for sphere `k` ("₁" or "₂"), the normal named `n`.
std::string splitText(const char* name, const VelocitySplit& s, const char* n) {
    return format("%s⊥ = %.3f %s,   %s∥ = %s", name, clean(s.normal), n, name, vec(s.par).c_str());
}

// Why a method moves no sphere after the response.
const char* noCorrectionNote(const ContactExplanation& e, const physics::Params& p) {
    if (e.correction == PositionCorrection::VelocitiesOnly) {
        return "after the last pass: velocities only, no position correction (the last pass's projection came "
               "before this answer)";
    }
    switch (p.method) {
        case physics::Method::VelocityBased: return "velocity based: no projection; its last stage cancels what still approaches";
        case physics::Method::Continuous: return "continuous: answered at the instant of contact, nothing to correct";
        default: return "response only (slides 5-6): no position correction";
    }
}

// Slide 7, go back in time: when within the step the continuous method met the contact.
void instantLine(std::vector<Line>& lines, const ContactExplanation& e, const physics::Params& p) {
    if (e.timeOfImpact < 0.0) return;
    add(lines, Line::Kind::Heading, "Slide 7: back to the instant of collision");
    add(lines, Line::Kind::Formula,
        format("t* = %.6f s into the step of %.6f s; the velocities below are those at t*", e.timeOfImpact,
               p.solverStep()));
}

// Slide 14's global approach: the contact's impulse came from one problem over its cluster,
// so the slides' formula below (this contact alone) is a comparison, not the answer. Under
// lcp its numbers check complementarity: lambda >= 0, c+ + beta c >= 0, and one of them is
// 0. Generalized reflections blend an inelastic and an elastic solve (beta < 1), round after
// round, lambda summed over the rounds: no such line holds for their sum.
void globalSolveLines(std::vector<Line>& lines, const ContactExplanation& e, const physics::Params& p) {
    if (!e.solvedTogether) return;
    const bool lcp = p.solver == physics::Solver::Lcp;
    add(lines, Line::Kind::Heading,
        lcp ? "Slide 14, the global approach (lcp): every touching contact in one problem"
            : "Slide 14, generalized reflections (Smith et al. 2012): the approaching contacts together");
    const double c = e.plane ? e.before[0].normal : -e.normalSpeed;                              // m/s, < 0 approaching
    const double cAfter = e.plane ? e.after[0].normal : e.after[0].normal - e.after[1].normal;  // m/s
    add(lines, Line::Kind::Formula, format("%s = %.4f m/s before, c⁺ = %.4f m/s after",
                                           e.plane ? "c = v·n" : "c = (v₁ − v₂)·u", clean(c), clean(cAfter)));
    if (!lcp) {
        add(lines, Line::Kind::Formula, format("λ = %.4g kg m/s, summed over the rounds", e.lambda));
        add(lines, Line::Kind::Note,
            "each round solves the approaching contacts elastically, blended with the inelastic answer for β < 1 "
            "(λ = (1 − β) λ_inelastic + β λ_elastic); the rounds go on until none approaches");
    } else {
        // The target: a contact approaching faster than epsilon leaves at beta times its
        // approach; a static one, or the answer after the last pass (positivity), at none.
        const double beta = e.staticContact || e.pass >= p.passes ? 0.0 : p.beta;
        add(lines, Line::Kind::Formula,
            format("λ = %.4g kg m/s ≥ 0,   c⁺ + β c = %.4g m/s ≥ 0 (β = %.3g here)", e.lambda,
                   clean(cAfter + beta * c), beta));
        add(lines, Line::Kind::Result,
            e.lambda > 0.0 ? "it pushed (λ > 0), so it leaves at exactly c⁺ = −β c: complementarity, λ (c⁺ + β c) = 0"
                           : "it did not push (λ = 0): its spheres may leave it faster");
    }
    add(lines, Line::Kind::Note, "below, the slides' pairwise answer to this contact alone, for comparison");
}

void matchLine(std::vector<Line>& lines, const ContactExplanation& e, const physics::Params& p) {
    if (e.solvedTogether && p.solver == physics::Solver::Lcp) {
        add(lines, Line::Kind::Note,
            format("lcp (slide 14): solved together with every touching contact; the velocities after hold the "
                   "others' shares too (they differ by %.3g m/s from the formula for this contact alone)", e.mismatch));
        return;
    }
    if (e.solvedTogether && p.solver == physics::Solver::GeneralizedReflections) {
        add(lines, Line::Kind::Note,
            format("generalized reflections (slide 14, Smith et al. 2012): solved together with the other approaching "
                   "contacts, round after round; the velocities after hold their shares too (they differ by %.3g m/s "
                   "from the formula for this contact alone)", e.mismatch));
        return;
    }
    const bool simultaneous = p.solver == physics::Solver::Simultaneous && e.pass < p.passes;
    if (e.mismatch <= 1e-9 * std::max(1.0, glm::length(e.velocityBefore[0]) + glm::length(e.velocityBefore[1]))) {
        add(lines, Line::Kind::Result, simultaneous ? "the solver's answer to this contact: the same" : "the solver's result: the same");
        if (simultaneous) {
            add(lines, Line::Kind::Note,
                "simultaneous (slide 14): every contact of the pass is answered from the velocities at its start, and "
                "each sphere ends the pass with the changes of all its contacts added up: with two contacts or more, "
                "not the 'after' above (the next pass starts from that sum; the inspector shows the velocity after "
                "the whole step)");
        }
    } else {
        add(lines, Line::Kind::Note,
            format("the solver's result differs by %.3g m/s: a parameter changed since this step", e.mismatch));
    }
}

// The kinetic energy before and after this answer (the velocities logged): a bounce keeps
// β² of the normal part and α² of the tangential one (slide 4). A plane, and a frozen sphere
// of the shock sweep, take none. A contact slide 14's global solvers answered with others
// logs the velocities after the whole solve: the slides' answer to it alone is counted.
void energyLines(std::vector<Line>& lines, const ContactExplanation& e, const physics::Params& p) {
    const bool both = !e.plane && std::isfinite(e.mass[1]);
    const glm::dvec3* answered = e.solvedTogether ? e.predicted : e.velocityAfter;  // m/s
    double before = 0.0, after = 0.0;  // J
    for (int k = 0; k < (both ? 2 : 1); ++k) {
        before += 0.5 * e.mass[k] * glm::dot(e.velocityBefore[k], e.velocityBefore[k]);
        after += 0.5 * e.mass[k] * glm::dot(answered[k], answered[k]);
    }
    const char* counted = e.solvedTogether ? " (this contact alone)" : "";
    add(lines, Line::Kind::Heading, std::string(both ? "Kinetic energy, ½ m₁ |v₁|² + ½ m₂ |v₂|²" : "Kinetic energy, ½ m |v|²") + counted);
    std::string change = "kept";
    if (std::abs(after - before) > 1e-9 * std::max(before, 1e-12)) {
        change = format("%.4g J %s", std::abs(after - before), after < before ? "lost" : "gained");
        if (before > 1e-12) change += format(" (%.3g %%)", 100.0 * std::abs(after - before) / before);
    }
    add(lines, Line::Kind::Formula, format("before %.4g J, after %.4g J: %s", before, after, change.c_str()));
    if (e.plane && !e.staticContact) {
        add(lines, Line::Kind::Formula,
            format("slide 4 keeps β² = %.3g of ½ m v⊥² and α² = %.3g of ½ m v∥²", p.beta * p.beta, p.alpha * p.alpha));
    }
}

void planeLines(const ContactExplanation& e, const physics::Params& p, int boxPlaneCount, std::vector<Line>& lines) {
    add(lines, Line::Kind::Heading,
        format("Sphere #%u and the %s, %s", e.sphere, planeName(e.other, boxPlaneCount).c_str(),
               passName(e.pass, p.passes, e.solvedTogether, e.timeOfImpact).c_str()));
    instantLine(lines, e, p);
    globalSolveLines(lines, e, p);
    add(lines, Line::Kind::Heading, "Slide 3: detection, (p − a)·n ≤ r");
    add(lines, Line::Kind::Formula, "n = " + vec(e.normal) + "  (unit, into the free side)");
    add(lines, Line::Kind::Formula, format("d = r − (p − a)·n = %.4g m  (distance of penetration, slide 8)", depthShown(e.depth)));
    add(lines, Line::Kind::Heading, "Slide 13: bounce or static contact?");
    if (e.staticContact) {
        add(lines, Line::Kind::Formula,
            format("|v·n| = %.3f m/s ≤ ε = %.3g m/s: static contact (2-b)", std::abs(e.normalSpeed), e.epsilon));
    } else {
        add(lines, Line::Kind::Formula,
            format("v·n = %.3f m/s, |v·n| > ε = %.3g m/s: a bounce (2-a)", clean(e.normalSpeed), e.epsilon));
    }
    add(lines, Line::Kind::Heading, "Slide 4: split v = v∥ + v⊥, v⊥ = (v·n) n");
    add(lines, Line::Kind::Formula, "before:  " + splitText("v", e.before[0], "n"));
    if (e.staticContact) {
        add(lines, Line::Kind::Heading, format("Slide 13, 2-b: no bounce, then friction v ← μ v, μ = %.3g", p.mu));
        add(lines, Line::Kind::Formula, "v ← μ (v − min(v·n, 0) n) = " + vec(e.predicted[0]));
    } else {
        add(lines, Line::Kind::Heading, format("Slide 4: v ← α v∥ − β v⊥,  α = %.3g, β = %.3g", p.alpha, p.beta));
        add(lines, Line::Kind::Formula,
            format("v ← %.3g × %s − %.3g × %.3f n = %s", p.alpha, vec(e.before[0].par).c_str(), p.beta,
                   clean(e.before[0].normal), vec(e.predicted[0]).c_str()));
    }
    add(lines, Line::Kind::Formula, "after:   " + splitText("v", e.after[0], "n"));
    matchLine(lines, e, p);
    energyLines(lines, e, p);
    add(lines, Line::Kind::Heading, "Position correction");
    if (e.correction == PositionCorrection::Projection && e.reflected) {
        add(lines, Line::Kind::Formula,
            format("slide 7, reflection: p ← p + (1 + β) d n: the sphere moves %.4g m along n", e.shift[0]));
    } else if (e.correction == PositionCorrection::Projection) {
        add(lines, Line::Kind::Formula, format("slide 8: p ← p + d n: the sphere moves %.4g m along n", e.shift[0]));
    } else {
        add(lines, Line::Kind::Note, noCorrectionNote(e, p));
    }
}

void pairLines(const ContactExplanation& e, const physics::Params& p, std::vector<Line>& lines) {
    const bool lecture = p.response == physics::ResponseModel::LectureAttenuation;
    add(lines, Line::Kind::Heading,
        format("Sphere 1 = #%u and sphere 2 = #%d, %s", e.sphere, e.other,
               passName(e.pass, p.passes, e.solvedTogether, e.timeOfImpact).c_str()));
    instantLine(lines, e, p);
    globalSolveLines(lines, e, p);
    if (!std::isfinite(e.mass[1])) {
        add(lines, Line::Kind::Note,
            format("slide 14's shock propagation: #%d is in the level below, frozen (m₂ = ∞, 1/m₂ = 0): only "
                   "sphere 1 changes", e.other));
    }
    add(lines, Line::Kind::Heading, "Slides 9 and 11: ‖p₁ − p₂‖ ≤ r₁ + r₂, u = (p₁ − p₂) / ‖p₁ − p₂‖");
    add(lines, Line::Kind::Formula, "u = " + vec(e.normal) + "  (from 2 to 1)");
    add(lines, Line::Kind::Formula, format("d = r₁ + r₂ − ‖p₁ − p₂‖ = %.4g m  (collision depth, slide 13)", depthShown(e.depth)));
    add(lines, Line::Kind::Heading, "Slide 13: bounce or static contact?");
    if (e.staticContact) {
        add(lines, Line::Kind::Formula,
            format("|(v₂ − v₁)·u| = %.3f m/s ≤ ε = %.3g m/s: static contact (2-b)", std::abs(e.normalSpeed),
                   e.epsilon));
    } else {
        add(lines, Line::Kind::Formula,
            format("(v₂ − v₁)·u = %.3f m/s > ε = %.3g m/s: they approach, a bounce (2-a)", e.normalSpeed, e.epsilon));
    }
    if (e.solvedTogether && e.recordedBounce && e.staticContact) {
        add(lines, Line::Kind::Note,
            "the solver answered it as a bounce: it approached only in a later round, once the others' impulses "
            "reached it (generalized reflections); the lines below use the velocities at the pass's start");
    }
    if (!e.staticContact) {
        add(lines, Line::Kind::Heading, "Slide 11: the elastic impulse");
        add(lines, Line::Kind::Formula,
            format("j = 2/(1/m₁ + 1/m₂) (v₂ − v₁)·u = 2/(1/%.4g + 1/%.4g) × %.3f = %.4g kg m/s", e.mass[0], e.mass[1],
                   clean(e.normalSpeed), e.impulse));
    }
    add(lines, Line::Kind::Heading, "Split along u: v⊥ = (v·u) u, v∥ = v − v⊥");
    add(lines, Line::Kind::Formula, "before:  " + splitText("v₁", e.before[0], "u"));
    add(lines, Line::Kind::Formula, "         " + splitText("v₂", e.before[1], "u"));
    if (e.staticContact) {
        if (relativeFriction(p, e.solvedTogether)) {
            add(lines, Line::Kind::Heading,
                format("Slide 13, 2-b: no bounce, then μ damps the relative tangential velocity, μ = %.3g", p.mu));
        } else {
            add(lines, Line::Kind::Heading, format("Slide 13, 2-b: no bounce, then friction v ← μ v, μ = %.3g", p.mu));
        }
        add(lines, Line::Kind::Formula,
            format("approach removed (perfectly inelastic): j/2 = (v₂ − v₁)·u / (1/m₁ + 1/m₂) = %.4g kg m/s",
                   e.normalSpeed > 0.0 ? 0.5 * e.impulse : 0.0));
        if (e.undamped) {
            add(lines, Line::Kind::Note,
                std::string(relativeFrictionCause(p, true)) + ": it did not push (λ = 0), so μ does not act on it");
        } else if (relativeFriction(p, e.solvedTogether)) {
            add(lines, Line::Kind::Note,
                std::string(relativeFrictionCause(p, e.solvedTogether)) +
                    ": equal and opposite impulses scale (v₂ − v₁)∥ by μ, so momentum is kept (slide 13's v ← μ v "
                    "would scale each sphere's own velocity)");
        }
    } else if (lecture) {
        add(lines, Line::Kind::Heading, format("Slide 12: with α = %.3g, β = %.3g", p.alpha, p.beta));
        add(lines, Line::Kind::Formula, "v₁ ← α v₁∥ + β (v₁⊥ + j/m₁ u),   v₂ ← α v₂∥ + β (v₂⊥ − j/m₂ u)");
        if (e.mass[0] == e.mass[1]) add(lines, Line::Kind::Formula, "equal masses: v₁ ← α v₁∥ + β v₂⊥, v₂ ← α v₂∥ + β v₁⊥");
    } else {
        add(lines, Line::Kind::Heading, format("Momentum-conserving restitution, α = %.3g, β = %.3g", p.alpha, p.beta));
        add(lines, Line::Kind::Formula, "J = (1 + β) j/2 u + (1 − α) m* (v₂ − v₁)∥,  v₁ ← v₁ + J/m₁,  v₂ ← v₂ − J/m₂");
        add(lines, Line::Kind::Formula, "m* = 1/(1/m₁ + 1/m₂), the reduced mass");
    }
    add(lines, Line::Kind::Formula, "v₁ ← " + vec(e.predicted[0]) + ",   v₂ ← " + vec(e.predicted[1]));
    add(lines, Line::Kind::Formula, "after:   " + splitText("v₁", e.after[0], "u"));
    add(lines, Line::Kind::Formula, "         " + splitText("v₂", e.after[1], "u"));
    matchLine(lines, e, p);
    energyLines(lines, e, p);
    add(lines, Line::Kind::Heading,
        e.reflected ? "Slide 7, reflection: position correction by (1 + β) d" : "Slide 13, step 3: position correction");
    if (e.reflected) {
        add(lines, Line::Kind::Formula,
            format("p₁ ← p₁ + (1 + β) d s₁ u,  p₂ ← p₂ − (1 + β) d s₂ u  (s: the split): sphere 1 moves %.4g m "
                   "along u, sphere 2 %.4g m along −u", e.shift[0], e.shift[1]));
    } else if (e.correction == PositionCorrection::OffFrozen) {
        add(lines, Line::Kind::Formula,
            format("p₁ ← p₁ + d u: %.4g m; sphere 2 is frozen and does not move", e.shift[0]));
    } else if (e.correction == PositionCorrection::HalfHalf) {
        add(lines, Line::Kind::Formula,
            format("p₁ ← p₁ + d/2 u,  p₂ ← p₂ − d/2 u: %.4g m each", e.shift[0]));
    } else if (e.correction == PositionCorrection::MassWeighted) {
        add(lines, Line::Kind::Formula,
            format("p₁ ← p₁ + d m₂/(m₁ + m₂) u,  p₂ ← p₂ − d m₁/(m₁ + m₂) u: sphere 1 moves %.4g m along u, "
                   "sphere 2 %.4g m along −u", e.shift[0], e.shift[1]));
    } else {
        add(lines, Line::Kind::Note, noCorrectionNote(e, p));
    }
}

}  // namespace

VelocitySplit splitVelocity(const glm::dvec3& v, const glm::dvec3& n) {
    VelocitySplit s;
    s.normal = glm::dot(v, n);
    s.perp = s.normal * n;
    s.par = v - s.perp;
    return s;
}

ContactExplanation explainContact(const physics::ContactEvent& event, const physics::Params& params) {
    ContactExplanation e;
    e.plane = event.isPlane();
    e.sphere = event.i;
    e.other = e.plane ? -1 - event.other : event.other;
    e.pass = event.pass;
    e.normal = event.normal;
    e.depth = event.depth;
    e.epsilon = params.epsilon;
    e.recordedBounce = event.bounce;
    e.solvedTogether = event.solvedImpulse >= 0.0;
    e.lambda = event.solvedImpulse;
    e.timeOfImpact = event.timeOfImpact;
    const bool velocitiesOnly = e.solvedTogether && event.pass >= params.passes;
    e.reflected = params.method == physics::Method::Reflection && !velocitiesOnly;
    const bool corrects = (params.method == physics::Method::PositionBased || e.reflected) && !velocitiesOnly;
    const double moved = e.reflected ? (1.0 + params.beta) * event.depth : event.depth;  // m
    for (int k = 0; k < 2; ++k) {
        e.mass[k] = event.massOf[k];
        e.velocityBefore[k] = event.velocityBefore[k];
        e.velocityAfter[k] = event.velocityAfter[k];
        e.before[k] = splitVelocity(event.velocityBefore[k], event.normal);
        e.after[k] = splitVelocity(event.velocityAfter[k], event.normal);
    }
    if (e.plane) {
        e.normalSpeed = e.before[0].normal;
        e.staticContact = std::abs(e.normalSpeed) <= params.epsilon;
        e.predicted[0] = predictPlane(event.velocityBefore[0], event.normal, e.staticContact, params);
        e.correction = corrects ? PositionCorrection::Projection : PositionCorrection::None;
        e.shift[0] = corrects ? moved : 0.0;
        if (velocitiesOnly) e.correction = PositionCorrection::VelocitiesOnly;
    } else {
        e.normalSpeed = e.before[1].normal - e.before[0].normal;
        e.staticContact = std::abs(e.normalSpeed) <= params.epsilon;
        e.impulse = 2.0 * reducedMass(e.mass[0], e.mass[1]) * e.normalSpeed;
        e.undamped = e.solvedTogether && e.staticContact && !(event.solvedImpulse > 0.0);
        predictPair(event.velocityBefore, e.mass, event.normal, e.staticContact, e.undamped,
                    relativeFriction(params, e.solvedTogether), params, e.predicted);
        if (!std::isfinite(e.mass[1])) {  // the shock sweep against a frozen sphere: projected by d, also
            e.reflected = false;            // under reflection (a resting contact does not bounce)
            e.predicted[1] = event.velocityBefore[1];
            e.correction = corrects ? PositionCorrection::OffFrozen : PositionCorrection::None;
            e.shift[0] = corrects ? event.depth : 0.0;
        } else if (velocitiesOnly) {
            e.correction = PositionCorrection::VelocitiesOnly;
        } else if (!corrects) {
            e.correction = PositionCorrection::None;
        } else if (params.split == physics::PositionSplit::HalfHalf) {
            e.correction = PositionCorrection::HalfHalf;
            e.shift[0] = e.shift[1] = 0.5 * moved;
        } else {
            e.correction = PositionCorrection::MassWeighted;
            e.shift[0] = moved * e.mass[1] / (e.mass[0] + e.mass[1]);
            e.shift[1] = moved * e.mass[0] / (e.mass[0] + e.mass[1]);
        }
    }
    for (int k = 0; k < (e.plane ? 1 : 2); ++k) {
        e.mismatch = std::max(e.mismatch, glm::length(e.predicted[k] - e.velocityAfter[k]));
    }
    return e;
}

std::string passName(int pass, int passes, bool solvedTogether, double timeOfImpact) {
    if (timeOfImpact >= 0.0) return format("at its instant, %.3f ms into the step", 1e3 * timeOfImpact);
    // A global solver's answer in a pass: one problem for the touching contacts, not one of
    // the pairwise passes (a student read "pass 1 of 4" on lcp as a sequential pass).
    if (pass < passes) return format(solvedTogether ? "solved together in pass %d of %d" : "pass %d of %d", pass + 1, passes);
    // After the K passes: a global solver's last answer (the position and reflection methods
    // answer the velocities once more after the last projection), or the shock sweep.
    return solvedTogether ? "after the last pass, velocities only" : "the shock propagation sweep";
}

std::string planeName(int planeIndex, int boxPlaneCount) {
    static const char* const kBox[] = {"floor", "ceiling", "wall −x", "wall +x", "wall −y", "wall +y"};
    if (planeIndex >= 0 && planeIndex < boxPlaneCount && planeIndex < 6) return kBox[planeIndex];
    return format("plane %d", planeIndex - boxPlaneCount);
}

std::vector<ExplanationLine> explanationLines(const ContactExplanation& e, const physics::Params& params,
                                              int boxPlaneCount) {
    std::vector<Line> lines;
    if (e.plane) {
        planeLines(e, params, boxPlaneCount, lines);
    } else {
        pairLines(e, params, lines);
    }
    return lines;
}

namespace {

bool touchesAny(const physics::ContactEvent& e, const std::vector<std::int64_t>& spheres) {
    for (std::int64_t s : spheres) {
        if (s == std::int64_t(e.i) || s == std::int64_t(e.other)) return true;
    }
    return false;
}

// The events of `event`'s pass joined to it through shared spheres (a plane joins nothing).
std::vector<physics::ContactEvent> clusterOf(const physics::ContactEvent& event,
                                             const std::vector<physics::ContactEvent>& solved) {
    std::vector<std::int64_t> spheres{event.i};
    if (!event.isPlane()) spheres.push_back(event.other);
    std::vector<physics::ContactEvent> cluster;
    std::vector<bool> taken(solved.size(), false);
    for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t k = 0; k < solved.size(); ++k) {
            const physics::ContactEvent& e = solved[k];
            const bool sameSolve = e.pass == event.pass && e.solverStep == event.solverStep;
            if (taken[k] || !sameSolve || !touchesAny(e, spheres)) continue;
            taken[k] = grew = true;
            cluster.push_back(e);
            spheres.push_back(e.i);
            if (!e.isPlane()) spheres.push_back(e.other);
        }
    }
    return cluster;
}

std::string contactName(const physics::ContactEvent& e, int boxPlaneCount) {
    return "#" + std::to_string(e.i) + " with " +
           (e.isPlane() ? planeName(-1 - e.other, boxPlaneCount) : "#" + std::to_string(e.other));
}

}  // namespace

std::vector<ExplanationLine> solvedWithLines(const physics::ContactEvent& event,
                                             const std::vector<physics::ContactEvent>& solved, int boxPlaneCount) {
    std::vector<ExplanationLine> lines;
    if (event.solvedImpulse < 0.0) return lines;
    const std::vector<physics::ContactEvent> cluster = clusterOf(event, solved);
    add(lines, Line::Kind::Heading, "Slide 14: solved together, the impulse each received");
    add(lines, Line::Kind::Result, format("this contact: \u03bb = %.4g kg m/s", event.solvedImpulse));
    std::size_t listed = 0;
    for (const physics::ContactEvent& e : cluster) {
        if (e.i == event.i && e.other == event.other) continue;
        if (++listed > kMostSolvedWithLines) continue;
        add(lines, Line::Kind::Formula,
            format("%s: \u03bb = %.4g kg m/s", contactName(e, boxPlaneCount).c_str(), e.solvedImpulse));
    }
    if (listed == 0) add(lines, Line::Kind::Note, "no other contact touched these spheres in this pass");
    if (listed > kMostSolvedWithLines) {
        add(lines, Line::Kind::Note, format("and %.0f more", double(listed - kMostSolvedWithLines)));
    }
    return lines;
}

const char* contactStateName(physics::ContactState state) {
    switch (state) {
        case physics::ContactState::Free: return "free";
        case physics::ContactState::Colliding: return "colliding (bounce)";
        case physics::ContactState::Static: return "static contact";
    }
    return "";
}

int contactPartner(const physics::ContactEvent& event, int selected) {
    if (event.isPlane()) return -1;
    return static_cast<int>(event.i) == selected ? event.other : static_cast<int>(event.i);
}

std::string contactTitle(const physics::ContactEvent& event, int selected, int boxPlaneCount, int passes) {
    char text[128];
    const char* kind = event.bounce ? "bounce" : "static";
    const std::string pass = passName(event.pass, passes, event.solvedImpulse >= 0.0, event.timeOfImpact);
    if (event.isPlane()) {
        std::snprintf(text, sizeof text, "%s, %s, %s", planeName(-1 - event.other, boxPlaneCount).c_str(), pass.c_str(),
                      kind);
    } else {
        std::snprintf(text, sizeof text, "vs #%d, %s, %s", contactPartner(event, selected), pass.c_str(), kind);
    }
    return text;
}

}  // namespace app
