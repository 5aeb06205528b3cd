// Generalized reflections (Smith, Kaufman, Vouga, Tamstorf, Grinspun 2012, "Reflections on
// Simultaneous Impact", cited on slide 14). The lcp solver puts every touching contact in
// one problem, and so holds together spheres that touch but do not approach (the last
// ball of a cradle cannot break away). Generalized reflections only ever act on the
// contacts that approach, and repeat:
//   active set = the contacts with c_k < -kConvergedApproachSpeed; stop when it is empty;
//   solve the problem of complementarity.h on the active set only; apply; repeat.
// Elastic (beta = 1): the target of an active contact is -c_k, its approach reflected;
// where lambda_k > 0 it ends at exactly -c_k, so each solve keeps the kinetic energy
// (dE = sum_k lambda_k (c_k + c+_k) / 2 = 0). For beta < 1 the generalized restitution:
// lambda = (1 - beta) lambda_inelastic + beta lambda_elastic, where the inelastic solve
// has targets 0; energy is convex in lambda, so it never rises. A static contact (slide
// 13: in a round where it approaches at epsilon or less) has target 0 in both. Then alpha and mu act on the
// tangential velocities, as in lcp.cpp.
#include <algorithm>
#include <cmath>

#include "physics/complementarity.h"

namespace physics {
namespace {

// Rounds of { active set, solve } at most: a pass never hangs (counted when reached).
// Random elastic clusters of 3-8 spheres need at most 17; with beta < 1 up to 1322 (the
// blended answer leaves contacts that approach a little, round after round).
constexpr int kMostRounds = 10000;
// Each round's solve stops at this fraction of the fastest approach of its active set
// (m/s per m/s): the energy is then kept to about 1e-13 of itself.
constexpr double kRelativeTolerance = 1e-14;
constexpr int kMostSweeps = 1000;
// The work of a pass at most, in contact visits of the sweeps summed over its rounds: 2000
// sweeps of all its contacts (twice the lcp solver's cap), at least 10^6. A resting pile
// pushes contacts into approach round after round (840 rounds a solver step for a pile of
// 1000, measured): past this budget the pass stops, counted as a cap hit, and the methods'
// own safety nets (projection, the velocity method's cancelling) take what is left.
constexpr std::uint64_t kVisitsPerContact = 500;
constexpr std::uint64_t kLeastVisits = 1000000;

// The contacts that approach at the current velocities, into `active` (their index in
// `contacts` in `where`); returns the fastest approach (m/s, > 0), 0 when none. A contact
// that approaches at epsilon or less is static in this round (slide 13): its target is 0.
double findApproaching(const World& world, const Params& params, const std::vector<LcpContact>& contacts,
                       std::vector<LcpContact>& active, std::vector<std::uint32_t>& where) {
    active.clear();
    where.clear();
    double fastest = 0.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const double c = relativeNormal(world, contacts[k]);  // m/s
        if (c >= -kConvergedApproachSpeed) continue;
        LcpContact copy = contacts[k];
        copy.isStatic = -c <= params.epsilon;
        active.push_back(copy);
        where.push_back(std::uint32_t(k));
        fastest = std::max(fastest, -c);
    }
    return fastest;
}

// Solves the active set from the round's start velocities (Workspace::passStart), elastic
// (targets -c_k) or inelastic (targets 0); the impulses into `lambda`, the velocities put
// back. Returns the sweeps.
int solveActive(World& world, std::vector<LcpContact>& active, bool elastic, double tolerance, int mostSweeps,
                std::vector<double>& lambda, double& residual) {
    const std::vector<glm::dvec3>& start = world.workspace.passStart;
    for (LcpContact& c : active) {  // the velocities are the round's start
        c.target = elastic && !c.isStatic ? -relativeNormal(world, c) : 0.0;  // m/s
        c.lambda = 0.0;
    }
    const int sweeps = projectedGaussSeidel(world, active, tolerance, mostSweeps, residual);
    lambda.resize(active.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
        lambda[k] = active[k].lambda;
        world.velocity[active[k].i] = start[active[k].i];
        if (active[k].j >= 0) world.velocity[std::size_t(active[k].j)] = start[std::size_t(active[k].j)];
    }
    return sweeps;
}

}  // namespace

void reflectGeneralized(World& world, const Params& params, StepStats& stats, int pass) {
    Workspace& ws = world.workspace;
    std::vector<LcpContact>& contacts = ws.lcpContacts;
    gatherContacts(world, params, true, contacts);  // a separating one may approach later
    if (contacts.empty()) return;
    const std::vector<glm::dvec3> before = world.recordContacts ? world.velocity : std::vector<glm::dvec3>();
    for (LcpContact& c : contacts) c.lambda = 0.0;  // the impulse summed over the rounds
    std::vector<LcpContact>& active = ws.activeContacts;
    std::vector<std::uint32_t>& where = ws.activeIndex;
    int rounds = 0;
    std::uint64_t visitsLeft = std::max(kLeastVisits, kVisitsPerContact * contacts.size());
    double fastest = findApproaching(world, params, contacts, active, where);
    for (; fastest > 0.0 && rounds < kMostRounds && visitsLeft > 0;
         fastest = findApproaching(world, params, contacts, active, where)) {
        ++rounds;
        ws.passStart = world.velocity;
        const double tolerance = kRelativeTolerance * fastest;  // m/s
        const int solves = (params.beta < 1.0) + (params.beta > 0.0);
        const int mostSweeps = int(std::clamp<std::uint64_t>(visitsLeft / (solves * active.size()), 1, kMostSweeps));
        double residual = 0.0;
        std::vector<double>& inelastic = ws.inelasticImpulse;
        std::vector<double>& elastic = ws.elasticImpulse;
        inelastic.assign(active.size(), 0.0);
        elastic.assign(active.size(), 0.0);
        int sweeps = 0;
        if (params.beta < 1.0) sweeps += solveActive(world, active, false, tolerance, mostSweeps, inelastic, residual);
        stats.lcpResidual = std::max(stats.lcpResidual, residual);
        if (params.beta > 0.0) sweeps += solveActive(world, active, true, tolerance, mostSweeps, elastic, residual);
        stats.lcpResidual = std::max(stats.lcpResidual, residual);
        stats.lcpSweeps += std::uint64_t(sweeps);
        visitsLeft -= std::min(visitsLeft, std::uint64_t(sweeps) * active.size());
        for (std::size_t k = 0; k < active.size(); ++k) {
            const double lambda = (1.0 - params.beta) * inelastic[k] + params.beta * elastic[k];  // kg m/s
            push(world, active[k], lambda);
            LcpContact& contact = contacts[where[k]];
            // Static (mu on its tangential velocity) if its first push was; a bounce once it bounces.
            if (lambda > 0.0 && (contact.lambda == 0.0 || !active[k].isStatic)) contact.isStatic = active[k].isStatic;
            contact.lambda += lambda;
        }
    }
    stats.reflectionRounds += std::uint64_t(rounds);
    stats.reflectionCapHits += fastest > 0.0;
    dampTangential(world, params, contacts);
    reportContacts(world, contacts, before, stats, pass);
}

}  // namespace physics
