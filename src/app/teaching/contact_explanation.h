#pragma once
// "Explain this contact": one recorded velocity response (physics::ContactEvent)
// taken apart with the slides' formulas and the current parameters, number by
// number: the normal u (or the plane's n), the depth d, the relative normal speed
// against epsilon (slide 13), the elastic impulse j (slide 11), v-parallel and
// v-perpendicular before and after, the alpha/beta result (slide 4 for a plane,
// slide 12 for two spheres) and the position correction. Pure: the window only
// prints what this computes, and the tests check it against hand computations.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "physics/params.h"
#include "physics/world.h"

namespace app {

// A velocity split along a unit normal: v = par + perp, perp = (v.n) n.
struct VelocitySplit {
    double normal = 0.0;     // m/s, v.n (perp = normal * n)
    glm::dvec3 perp{0.0};    // m/s
    glm::dvec3 par{0.0};     // m/s
};
VelocitySplit splitVelocity(const glm::dvec3& v, const glm::dvec3& n);

enum class PositionCorrection {
    Projection,    // a plane: p <- p + d n (slide 8)
    HalfHalf,      // two spheres: p1 <- p1 + d/2 u, p2 <- p2 - d/2 u (slide 13)
    MassWeighted,  // two spheres: the lighter one moves more
    OffFrozen,     // the shock sweep: sphere 1 moves d off the frozen sphere 2 (slide 14)
    VelocitiesOnly,  // a global solver's answer after the last pass: the last projection came before
    None,          // velocity based, response only or continuous: no projection
};

struct ContactExplanation {
    bool plane = false;           // sphere-plane (slides 3-8) or sphere-sphere (slides 9-13)
    std::uint32_t sphere = 0;     // sphere 1 (the event's i)
    int other = -1;               // sphere 2's index, or the plane's index for a plane
    int pass = 0;                 // which of the K passes
    glm::dvec3 normal{0.0};       // unit: u = (p1 - p2)/|p1 - p2|, or the plane's n
    double depth = 0.0;           // m, d when detected
    // Sphere pair: (v2 - v1).u, positive while approaching. Plane: v.n, negative while approaching.
    double normalSpeed = 0.0;     // m/s
    double epsilon = 0.0;         // m/s
    bool staticContact = false;   // |normalSpeed| <= epsilon (slide 13, 2-b)
    bool recordedBounce = false;  // what the solver did
    // Slide 14's global solvers damp a contact's tangential velocity only where it pushed
    // (lambda > 0): a static contact that did not is left undamped.
    bool undamped = false;
    bool solvedTogether = false;  // by slide 14's lcp or generalized reflections (its lambda logged)
    double lambda = -1.0;         // kg m/s, the impulse they gave it; -1: answered pairwise
    double mass[2]{0.0, 0.0};     // kg (0 for a plane)
    double impulse = 0.0;         // kg m/s, slide 11: j = 2/(1/m1 + 1/m2) (v2 - v1).u; 0 for a plane
    VelocitySplit before[2];      // of sphere 1 and sphere 2, along `normal`
    VelocitySplit after[2];       // recorded
    glm::dvec3 velocityBefore[2]{};  // m/s
    glm::dvec3 velocityAfter[2]{};   // m/s, recorded
    glm::dvec3 predicted[2]{};       // m/s, the formula with the current parameters
    double mismatch = 0.0;           // m/s, largest |predicted - recorded|
    PositionCorrection correction = PositionCorrection::None;
    bool reflected = false;     // slide 7's reflection: the correction moves (1 + beta) d, not d
    double shift[2]{0.0, 0.0};  // m: sphere 1 moves shift[0] along normal, sphere 2 shift[1] against it
    double timeOfImpact = -1.0;  // s into the solver step: continuous method; -1 otherwise
};

ContactExplanation explainContact(const physics::ContactEvent& event, const physics::Params& params);

// "pass 2 of 4"; for a contact logged with pass = K, after the K passes: "after the last
// pass, velocities only" for a global solver's last answer (`solvedTogether`), else "the
// shock propagation sweep".
// `timeOfImpact` (s, the continuous method's instant; -1 none): such a contact has no pass.
std::string passName(int pass, int passes, bool solvedTogether = false, double timeOfImpact = -1.0);

// The plane's name: floor, ceiling, wall -x ... for the box (in scenes::boxPlanes'
// order), "plane k" for the extra ones.
std::string planeName(int planeIndex, int boxPlaneCount);

// "free", "colliding (bounce)" or "static contact", as the inspector says it.
const char* contactStateName(physics::ContactState state);

// The other sphere of a contact of `selected`; -1 for a plane.
int contactPartner(const physics::ContactEvent& event, int selected);

// "vs #40, pass 2 of 4, bounce" or "floor, pass 1 of 4, static" for a contact of `selected`.
std::string contactTitle(const physics::ContactEvent& event, int selected, int boxPlaneCount, int passes);

// One line of the explanation as the window shows it.
struct ExplanationLine {
    enum class Kind { Heading, Formula, Result, Note };
    Kind kind = Kind::Formula;
    std::string text;
};

// The explanation in the slides' words with the numbers: a heading per slide,
// the formula, then its value.
std::vector<ExplanationLine> explanationLines(const ContactExplanation& e, const physics::Params& params,
                                              int boxPlaneCount);

// Slide 14's global solvers (lcp, generalized reflections): the contacts of `solved` (one
// step's) that were solved with `event` in its pass, linked to it through shared spheres,
// each with the impulse it received (ContactEvent::solvedImpulse); none for the pairwise
// responses. At most kMostSolvedWithLines contacts are listed, then how many more.
constexpr std::size_t kMostSolvedWithLines = 10;
std::vector<ExplanationLine> solvedWithLines(const physics::ContactEvent& event,
                                             const std::vector<physics::ContactEvent>& solved, int boxPlaneCount);

}  // namespace app
