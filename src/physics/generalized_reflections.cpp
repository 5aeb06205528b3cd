// Generalized reflections (Smith, Kaufman, Vouga, Tamstorf, Grinspun 2012, "Reflections on
// Simultaneous Impact", cited on slide 14). The lcp solver puts every touching contact in
// one problem, and so holds together spheres that touch but do not approach (the last
// ball of a cradle cannot break away). Generalized reflections only ever act on the
// contacts that approach, and repeat, in each cluster of touching spheres on its own:
//   active set = the contacts with c_k < -kConvergedApproachSpeed; stop when it is empty;
//   solve the problem of complementarity.h on the active set only; apply; repeat.
// Elastic (beta = 1): the target of an active contact is -c_k, its approach reflected;
// where lambda_k > 0 it ends at exactly -c_k, so each solve keeps the kinetic energy
// (dE = sum_k lambda_k (c_k + c+_k) / 2 = 0). For beta < 1 the generalized restitution:
// lambda = (1 - beta) lambda_inelastic + beta lambda_elastic, where the inelastic solve
// has targets 0; energy is convex in lambda, so it never rises. A static contact (slide
// 13: in a round where it approaches at epsilon or less) has target 0 in both. Then alpha
// and mu act on the tangential velocities, as in lcp.cpp.
#include <algorithm>
#include <cmath>

#include "physics/complementarity.h"

namespace physics {
namespace {

// Rounds of { active set, solve } at most: a cluster never hangs (counted when reached).
// Random elastic clusters of 3-8 spheres need at most 17; with beta < 1 up to 1322 (the
// blended answer leaves contacts that approach a little, round after round).
constexpr int kMostRounds = 10000;
constexpr int kMostSweeps = 1000;
// The work of a cluster in a pass at most, in contact visits of the sweeps summed over its
// rounds: 500 sweeps of all its contacts, at least 10^7. A resting pile pushes contacts
// into approach round after round (840 rounds a solver step for a pile of 1000, measured):
// past this budget the cluster stops, counted as a cap hit, and the methods' own safety
// nets (projection, the velocity method's cancelling) take what is left. (Random clusters
// of 3-8 spheres at beta < 1 need up to about 10^6 built by GCC, one of 10^4 more than
// that built by clang; the column of 20 (21_shock_column) as it first settles, 5.3 x 10^6
// in 696 rounds: 10^7 leaves room, about 0.1 s of one step at worst.)
constexpr std::uint64_t kVisitsPerContact = 500;
constexpr std::uint64_t kLeastVisits = 10000000;

// One cluster's scratch, per thread: a round's active set (copies, their index in the
// cluster in `where`), the velocities of their spheres at the round's start (m/s), and
// the two solves' impulses (kg m/s).
struct RoundScratch {
    std::vector<LcpContact> active;
    std::vector<std::uint32_t> where;
    std::vector<glm::dvec3> startOfI, startOfJ;
    std::vector<double> inelastic, elastic;
};

// The cluster's contacts that approach at the current velocities, into scratch.active;
// returns the fastest approach (m/s, > 0), 0 when none. A contact that approaches at
// epsilon or less is static in this round (slide 13): its target is 0. A resting contact
// (one that has pushed as static in an earlier round of this pass) stays in the active set
// while it does not separate, static, so that it keeps holding: else the next round's
// impulses press it in again, and a resting pile passes its weight back and forth between
// rounds (a pile of 1000 took 840 rounds a step without this). Its target 0 and c <= 0
// keep the energy rule: it adds lambda (c + c+) / 2 <= 0.
double findApproaching(const World& world, const Params& params, const LcpContact* contacts, std::size_t count,
                       double converged, RoundScratch& scratch) {
    scratch.active.clear();
    scratch.where.clear();
    scratch.startOfI.clear();
    scratch.startOfJ.clear();
    double fastest = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
        const double c = relativeNormal(world, contacts[k]);  // m/s
        const bool resting = contacts[k].isStatic && contacts[k].lambda > 0.0 && c <= 0.0;
        if (c >= -converged && !resting) continue;
        LcpContact copy = contacts[k];
        copy.isStatic = resting || -c <= params.epsilon;
        scratch.active.push_back(copy);
        scratch.where.push_back(std::uint32_t(k));
        scratch.startOfI.push_back(world.velocity[copy.i]);
        scratch.startOfJ.push_back(copy.j >= 0 ? world.velocity[std::size_t(copy.j)] : glm::dvec3(0.0));
        if (c < -converged) fastest = std::max(fastest, -c);
    }
    return fastest;
}

// Solves the active set from the round's start velocities, elastic (targets -c_k) or
// inelastic (targets 0); the impulses into `lambda`, the velocities put back. Returns the
// sweeps.
int solveActive(World& world, RoundScratch& scratch, bool elastic, double tolerance, int mostSweeps,
                std::vector<double>& lambda, double& residual) {
    std::vector<LcpContact>& active = scratch.active;
    for (LcpContact& c : active) {  // the velocities are the round's start
        c.target = elastic && !c.isStatic ? -relativeNormal(world, c) : 0.0;  // m/s
        c.lambda = 0.0;
    }
    const int sweeps = projectedGaussSeidel(world, active.data(), active.size(), tolerance, mostSweeps, residual);
    lambda.resize(active.size());
    for (std::size_t k = 0; k < active.size(); ++k) {
        lambda[k] = active[k].lambda;
        world.velocity[active[k].i] = scratch.startOfI[k];
        if (active[k].j >= 0) world.velocity[std::size_t(active[k].j)] = scratch.startOfJ[k];
    }
    return sweeps;
}

}  // namespace

void reflectCluster(World& world, const Params& params, LcpContact* contacts, ContactCluster& cluster, double converged) {
    thread_local RoundScratch scratch;
    for (std::size_t k = 0; k < cluster.count; ++k) contacts[k].lambda = 0.0;
    std::uint64_t visitsLeft = std::max(kLeastVisits, kVisitsPerContact * cluster.count);
    double fastest = findApproaching(world, params, contacts, cluster.count, converged, scratch);
    cluster.rounds = cluster.sweeps = 0;
    cluster.residual = 0.0;
    for (; fastest > 0.0 && cluster.rounds < kMostRounds && visitsLeft > 0;
         fastest = findApproaching(world, params, contacts, cluster.count, converged, scratch)) {
        ++cluster.rounds;
        const std::size_t size = scratch.active.size();
        // An impact's solve to 1e-14 of its fastest approach: the energy is then kept to
        // about 1e-13 of itself; resting contacts' and a pile's to 1e-12 m/s.
        const bool impact = std::any_of(scratch.active.begin(), scratch.active.end(),
                                        [](const LcpContact& c) { return !c.isStatic; });
        const double tolerance = clusterTolerance(cluster.count, fastest, impact);  // m/s
        const int solves = (params.beta < 1.0) + (params.beta > 0.0);
        const int mostSweeps = int(std::clamp<std::uint64_t>(visitsLeft / (solves * size), 1, kMostSweeps));
        scratch.inelastic.assign(size, 0.0);
        scratch.elastic.assign(size, 0.0);
        double residual = 0.0;  // m/s
        int sweeps = 0;
        if (params.beta < 1.0) sweeps += solveActive(world, scratch, false, tolerance, mostSweeps, scratch.inelastic, residual);
        cluster.residual = std::max(cluster.residual, residual);
        if (params.beta > 0.0) sweeps += solveActive(world, scratch, true, tolerance, mostSweeps, scratch.elastic, residual);
        cluster.residual = std::max(cluster.residual, residual);
        cluster.sweeps += std::uint32_t(sweeps);
        visitsLeft -= std::min(visitsLeft, std::uint64_t(sweeps) * size);
        for (std::size_t k = 0; k < size; ++k) {
            const double lambda = (1.0 - params.beta) * scratch.inelastic[k] + params.beta * scratch.elastic[k];  // kg m/s
            push(world, scratch.active[k], lambda);
            LcpContact& contact = contacts[scratch.where[k]];
            // Static (mu on its tangential velocity) if its first push was; a bounce once it bounces.
            if (lambda > 0.0 && (contact.lambda == 0.0 || !scratch.active[k].isStatic)) {
                contact.isStatic = scratch.active[k].isStatic;
            }
            contact.lambda += lambda;
        }
    }
    cluster.capped = fastest > 0.0;
}

// restorePositivity's rounds go on while a contact approaches faster than this (m/s): well
// under kConvergedApproachSpeed, so that the velocity method's C, which follows them with
// its own cancelling contact by contact, does not push one past it (22_shock_pyramid
// under lcp: 1.8e-9 m/s with kConvergedApproachSpeed here).
constexpr double kPositiveApproachSpeed = 1e-11;

// One cluster's positivity: first one inelastic complementarity problem over all its
// touching contacts, separating ones too (every target 0), by projected Gauss-Seidel: with
// every target 0 its answer never adds energy (lambda (c + A lambda) = 0 makes the change
// -lambda A lambda / 2 <= 0), and on a pile it is cheap (the 1k pile's lcp: 9.0 -> 10.7 ms a
// solver step, against 15.3 with the rounds alone). Where it stops at its sweeps short of
// the tolerance (a column of 20 is a slow chain for Gauss-Seidel), rounds of generalized
// reflections at beta = 0 take the contacts still approaching until none does.
void restoreClusterPositivity(World& world, const Params& inelastic, LcpContact* contacts, ContactCluster& cluster) {
    for (std::uint32_t k = 0; k < cluster.count; ++k) contacts[k].target = contacts[k].lambda = 0.0;
    projectedGaussSeidel(world, contacts, cluster.count, kPositiveApproachSpeed, kMostSweeps, cluster.residual);
    if (cluster.residual <= kPositiveApproachSpeed) {
        cluster.capped = false;
        return;
    }
    reflectCluster(world, inelastic, contacts, cluster, kPositiveApproachSpeed);
}

void restorePositivity(World& world, const Params& params, StepStats& stats) {
    Workspace& ws = world.workspace;
    std::vector<LcpContact>& contacts = ws.positivityContacts;
    gatherContacts(world, params, true, contacts);  // a separating one may approach by now
    sortIntoClusters(world, contacts, ws.positivityClusters);
    Params inelastic = params;
    inelastic.beta = 0.0;
    std::vector<ContactCluster>& clusters = ws.positivityClusters;
    runTasks(clusterThreads(world, params, clusters.size()), int(clusters.size()), [&](int k) {
        ContactCluster& cluster = clusters[std::size_t(k)];
        restoreClusterPositivity(world, inelastic, contacts.data() + cluster.first, cluster);
    });
    for (const ContactCluster& cluster : clusters) stats.reflectionCapHits += cluster.capped;
}

void endWithPositivity(World& world, const Params& params, StepStats& stats, bool moved) {
    if (!solvesGlobally(params.solver)) return;
    if (moved) findContacts(world, params);
    restorePositivity(world, params, stats);
}

void reflectGeneralized(World& world, const Params& params, StepStats& stats, int pass) {
    Workspace& ws = world.workspace;
    std::vector<LcpContact>& contacts = ws.lcpContacts;
    gatherContacts(world, params, true, contacts);  // a separating one may approach later
    if (contacts.empty()) return;
    if (world.recordContacts) ws.passStart = world.velocity;
    sortIntoClusters(world, contacts, ws.clusters);
    runTasks(clusterThreads(world, params, ws.clusters.size()), int(ws.clusters.size()), [&](int k) {
        ContactCluster& cluster = ws.clusters[std::size_t(k)];
        reflectCluster(world, params, contacts.data() + cluster.first, cluster);
    });
    std::uint32_t sweeps = 0, rounds = 0;  // of the cluster that took most
    for (const ContactCluster& cluster : ws.clusters) {
        sweeps = std::max(sweeps, cluster.sweeps);
        rounds = std::max(rounds, cluster.rounds);
        stats.lcpResidual = std::max(stats.lcpResidual, cluster.residual);
        stats.reflectionCapHits += cluster.capped;
    }
    stats.lcpSweeps += sweeps;
    stats.reflectionRounds += rounds;
    dampTangential(world, params, contacts);
    reportContacts(world, contacts, ws.passStart, stats, pass);
}

}  // namespace physics
