#pragma once
// The lecture's parameters, in SI units. The table that gives each one its
// label, range, tooltip and JSON / --set name lives in scenes/parameters.h.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace physics {

// The simulation models deck, "Summary with multiple particles".
enum class Method {
    PositionBased,  // "position projection": velocity + position response, walls last
    VelocityBased,  // "velocity correction": velocity response, cancel penetrating velocity
    ResponseOnly,   // first deck, slides 5-6: move, then velocity response only, no correction
    Reflection,     // slide 7, option 2: position based, moved out by (1 + beta) d ("approximate")
    Continuous,     // slide 7, option 3: back to the instant of contact, impacts in time order
};

// Slide 14, "multiple collisions": how the velocity stage treats the contacts of a step.
enum class Solver {
    Sequential,      // K passes, one contact at a time in the pair order (the lecture's)
    UntilConverged,  // sequential passes until no touching contact approaches, K the cap
    Simultaneous,    // pairwise Jacobi: each pass answers every contact from the same velocities
    Lcp,             // global: one complementarity problem over every touching contact (lcp.cpp)
    GeneralizedReflections,  // Smith et al. 2012: the approaching contacts only, until none approaches
};

// Whether the solver answers a pass's contacts together, from contacts found first
// (simultaneous, lcp, generalized reflections), rather than one pair at a time.
constexpr bool solvesTogether(Solver solver) {
    return solver == Solver::Simultaneous || solver == Solver::Lcp || solver == Solver::GeneralizedReflections;
}

// Whether the solver is slide 14's global approach: one complementarity problem a cluster
// (lcp, generalized reflections), its lambdas logged, alpha and mu after the normal solve.
constexpr bool solvesGlobally(Solver solver) {
    return solver == Solver::Lcp || solver == Solver::GeneralizedReflections;
}

// Slide 14's first global answer (shock_propagation.cpp): after the passes, the contact
// graph's levels are swept from the floor up, each level frozen once answered.
enum class ShockPropagation { Off, On };

// Whether a method runs the sweep: those with passes over the contacts (position,
// velocity, reflection). Response-only and the continuous method have none to follow.
constexpr bool sweepsLevels(Method method) {
    return method == Method::PositionBased || method == Method::VelocityBased || method == Method::Reflection;
}

// m/s: until-converged stops once no touching contact approaches faster than this.
constexpr double kConvergedApproachSpeed = 1e-9;

// How the continuous method finds the instant of contact (slide 7: "binary search, etc.").
enum class TimeOfImpact {
    ClosedForm,  // the earliest root of the distance function (a quadratic)
    Bisection,   // the slide's binary search on the same function, to kBisectionTolerance
};

// s: where the bisection stops halving the interval that holds the instant of contact.
constexpr double kBisectionTolerance = 1e-12;

// How two spheres exchange velocity when they bounce.
enum class ResponseModel {
    LectureAttenuation,  // slide 12: v1 <- alpha v1par + beta (v1perp + j/m1 u)
    MomentumConserving,  // equal and opposite impulses: (1 + beta) normal, alpha on tangential
};

// How the overlap d is split between the two spheres (slide 13: d/2 each).
enum class PositionSplit { HalfHalf, MassWeighted };

// The order in which sphere pairs are visited in each pass (slide 14: order matters).
// Index, reversed and shuffled are the lecture's. Colored is not: the pairs are coloured so
// that no two of one colour share a sphere, and visited colour by colour (colored_order.cpp).
// It is a different, fixed order of correction, chosen because a colour's pairs can be
// answered in any order, so threads share them without waiting.
enum class PairOrder { Index, Reversed, Shuffled, Colored };

// Where candidate pairs come from: a uniform grid, or the lecture's O(N^2) loop.
enum class BroadPhase { Grid, AllPairs };

// The most threads the solver takes, whatever Params::threads asks.
constexpr int kMostSolverThreads = 64;

struct Params {
    double alpha = 1.0;     // tangential attenuation ("friction" in slide 4), in [0, 1]
    double beta = 0.8;      // normal restitution ("impact" in slide 4), in [0, 1]
    double epsilon = 0.1;   // m/s: relative normal speed at or below which a contact is static
    double mu = 0.5;        // static-contact damping v <- mu v (slide 13), in [0, 1]
    double timeStep = 1.0 / 60.0;  // s: h, one step of the fixed-step loop
    int substeps = 4;       // solver steps per time step; each advances h / substeps
    int passes = 4;         // K: collision passes per solver step (slide 14)
    glm::dvec3 gravity{0.0, 0.0, -9.81};  // m/s^2, z is up
    Method method = Method::PositionBased;
    ResponseModel response = ResponseModel::LectureAttenuation;
    PositionSplit split = PositionSplit::HalfHalf;
    PairOrder order = PairOrder::Index;
    BroadPhase broadPhase = BroadPhase::Grid;
    Solver solver = Solver::Sequential;
    ShockPropagation shock = ShockPropagation::Off;
    TimeOfImpact timeOfImpact = TimeOfImpact::ClosedForm;
    // The continuous method's most impacts per sphere in a solver step: past N times it,
    // the rest of the step is projected (and counted, StepStats::cappedSteps), so a step
    // never hangs. A sphere at rest makes one or two a step, one bouncing in place with
    // epsilon = 0 reaches the cap in every solver step (its speed never rounds to 0).
    int maxEventsPerSphere = 50;

    // The most impacts a continuous solver step of `spheres` spheres handles.
    std::uint64_t maxEvents(std::size_t spheres) const {
        return std::uint64_t(maxEventsPerSphere) * std::max<std::uint64_t>(spheres, 1);
    }
    // Threads the solver may use, 0: one per usable core (at most 8) from 8192 spheres,
    // one below, and one while more were measured slower (AutomaticThreads). Any count gives the same result, bit for bit, in every order: a thread
    // waits before a pair until the pair that met one of its spheres before is done.
    // Small worlds (under 4096 spheres) use one whatever the count.
    int threads = 0;

    // s: the step every formula of the lecture uses (its h).
    double solverStep() const { return timeStep / substeps; }
};

}  // namespace physics
