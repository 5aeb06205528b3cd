#pragma once
// The one verb of the solver: advance the world by one time step h.
#include <cstdint>

#include "physics/impact_properties.h"
#include "physics/params.h"
#include "physics/world.h"

namespace physics {

// What one step did, summed over its solver steps.
struct StepStats {
    std::uint64_t pairTests = 0;       // distance tests made by the broad phase
    std::uint64_t broadPhaseBuilds = 0;  // solver steps that rebuilt the candidate pairs
    std::uint64_t candidatePairs = 0;  // pairs within reach, handed to the passes
    std::uint64_t sphereContacts = 0;  // overlapping pairs found in the first pass
    std::uint64_t wallContacts = 0;    // sphere-plane contacts found in the first pass
    std::uint64_t collisions = 0;      // contacts that bounced (speed above epsilon), all passes
    std::uint64_t staticContacts = 0;  // contacts handled as static (slide 13), all passes
    // Spheres whose contact a solver step answered (a bounce or a static contact: their
    // contact state not free), the most of the substeps (max, not summed). Set by step().
    std::uint64_t mostSpheresInContact = 0;
    // The continuous method: impacts handled at their instant (bounces and static
    // contacts), bisection iterations spent finding those instants, and solver steps that
    // reached Params::maxEvents() and were projected from there.
    // Slide 14's solvers: passes run (all solver steps), and the solver steps whose
    // until-converged passes reached K with a contact still approaching.
    std::uint64_t passesUsed = 0;
    std::uint64_t passCapHits = 0;
    // The global solves (lcp, generalized reflections), each cluster of touching spheres a
    // problem of its own: projected Gauss-Seidel sweeps of the cluster that took most,
    // summed over the passes, and the largest residual left (m/s, the most a contact ended
    // off its target; max, not summed).
    std::uint64_t lcpSweeps = 0;
    double lcpResidual = 0.0;
    // Generalized reflections: rounds of { active set, solve } of the cluster that took
    // most, summed over the passes, and the clusters that stopped at a cap with a contact
    // still approaching (theirs, and those of lcp's and their last, positivity solve).
    std::uint64_t reflectionRounds = 0;
    std::uint64_t reflectionCapHits = 0;
    // Shock propagation: the most levels of the contact graph a solver step swept (max).
    std::uint64_t shockLevels = 0;
    std::uint64_t shockRounds = 0;  // position rounds of the levels, summed
    std::uint64_t events = 0;
    std::uint64_t toiIterations = 0;
    std::uint64_t cappedSteps = 0;
    // s of wall time (a profile, not part of the result): finding the candidate pairs
    // (grid or all pairs, then their order), and the collision passes (with what they
    // find first: contacts, wall clearances, and the velocity method's cancelling).
    double broadPhaseSeconds = 0.0;
    double passesSeconds = 0.0;
    // The threads the last solver step used, and with automatic threads a count that
    // was measured slower than it (AutomaticThreads), 0 none. Set by step(), not summed.
    int threads = 1;
    int slowerThreads = 0;
    // With World::measureImpacts: what the velocity stages did (not the continuous method).
    ImpactProperties impacts;
    StepStats& operator+=(const StepStats& o);
};

// Runs params.substeps solver steps of h / substeps with the chosen method.
StepStats step(World& world, const Params& params);

// Slide 14's contact graph of the current positions into `graph`: the candidate pairs of
// the last solver step (visited in `order`: the pairs' order in Workspace::visitOrder), all
// within the margin of touching, and each sphere's level (shock_propagation.cpp). The
// shock sweep finds it into world.workspace.contactGraph; the overlay into its own.
void findContactGraph(const World& world, PairOrder order, ContactGraph& graph);

// One solver step of length h (s), as the second deck's summary writes it.
StepStats stepPositionBased(World& world, const Params& params, double h);
StepStats stepVelocityBased(World& world, const Params& params, double h);
StepStats stepResponseOnly(World& world, const Params& params, double h);
StepStats stepReflection(World& world, const Params& params, double h);
StepStats stepContinuous(World& world, const Params& params, double h);

}  // namespace physics
