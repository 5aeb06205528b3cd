#pragma once
// What slide 14's global methods (lcp.cpp, generalized_reflections.cpp) share: the touching
// contacts of a pass as complementarity constraints, and projected Gauss-Seidel over them.
// A contact k between spheres i and j (or a sphere and a plane, of infinite mass) with
// normal u_k from j to i has the relative normal velocity c_k = (v_i - v_j).u_k, negative
// while approaching, and takes an impulse lambda_k >= 0 (kg m/s):
//   v_i += lambda_k u_k / m_i,  v_j -= lambda_k u_k / m_j.
// The problem: c+_k >= b_k, lambda_k >= 0, lambda_k (c+_k - b_k) = 0, b_k the target.
#include <vector>

#include "physics/solver_stages.h"

namespace physics {

// 1/m_i + 1/m_j (1/kg; a plane adds nothing).
double inverseMass(const World& world, const LcpContact& c);
// c_k (m/s) at the world's current velocities.
double relativeNormal(const World& world, const LcpContact& c);
// Applies an impulse (kg m/s) along the contact's normal: +u to i, -u to j.
void push(World& world, const LcpContact& c, double impulse);

// A contact with its target, by gatherContacts' rule below.
LcpContact contactFor(const World& world, const Params& params, std::uint32_t i, std::int64_t j, std::int32_t other,
                      const glm::dvec3& u, double depth);

// The contacts findContacts found; without `withSeparating`, not those that separate
// faster than epsilon (held at c+ >= 0, an impulse could push one to 0 and add lambda c / 2
// of energy: the fast gas gained 11 % in 2 s). A contact is static when its |c_k| <=
// epsilon (slide 13); its target is 0. One that approaches faster has -beta c_k, one that
// separates 0.
void gatherContacts(World& world, const Params& params, bool withSeparating, std::vector<LcpContact>& contacts);

// Sorts `contacts` into clusters: the spheres that contacts join (a plane joins
// nothing), each cluster's contacts in a fixed order (pairs by their spheres' numbers,
// then walls), the clusters in the order of their first contact. Clusters share no sphere: each is a problem of its own, and two
// threads can solve two of them at once with the result of one thread.
void sortIntoClusters(World& world, std::vector<LcpContact>& contacts, std::vector<ContactCluster>& clusters);

// The threads the global solvers use: clusters are taken whole, so any count gives the
// same result, bit for bit.
inline int clusterThreads(const World& world, const Params& params, std::size_t clusters) {
    return clusters > 1 ? threadsFor(world, params) : 1;
}

// m/s: how far from its target a contact of a cluster of `count` contacts may end, its
// fastest approach `fastest` (m/s), `impact` true when one of them is a bounce (approaches
// faster than epsilon). Resting contacts and piles: 1e-12 m/s. An impact in a cluster of
// at most 64 contacts: 1e-14 of its fastest approach where that is tighter. With 1e-12 m/s
// Bernoulli's problem was left 1.2e-14 m/s off symmetric, enough for a later wall contact
// to be found a step apart for the two mirror spheres (0.02 m by step 120). Resting
// contacts solved to 1e-14 of their approach took every sweep the caps allow (generalized
// reflections on 10_pyramid: 82 ms a step and 272 clusters capped in 2 s, against 11 ms
// and none at 1e-12 m/s).
double clusterTolerance(std::size_t count, double fastest, bool impact);

// Projected Gauss-Seidel over contacts[0, count) from their lambdas as they are: visits
// them in turn, sets each lambda to what meets its own target, clamps it at 0, until no
// contact is off by more than `tolerance` (m/s) or `mostSweeps` sweeps are done. Returns
// the sweeps; `residual` (m/s) is what is left.
int projectedGaussSeidel(World& world, LcpContact* contacts, std::size_t count, double tolerance, int mostSweeps,
                         double& residual);

// One cluster's normal solve: lcp's projected Gauss-Seidel to its tolerance (lcp.cpp), or
// generalized reflections' rounds (generalized_reflections.cpp); the cluster's record
// (sweeps, rounds, residual, capped) filled in, each contact's lambda its impulse.
void solveLcpCluster(World& world, LcpContact* contacts, ContactCluster& cluster);
// `converged` (m/s): the rounds go on while a contact approaches faster.
void reflectCluster(World& world, const Params& params, LcpContact* contacts, ContactCluster& cluster,
                    double converged = kConvergedApproachSpeed);
// Adds one cluster's record to the stats (a cluster solved alone: the continuous
// method's simultaneous impacts).
void countCluster(const ContactCluster& cluster, StepStats& stats);

// After the normal solve, per contact that pushed (lambda > 0): alpha on a bounce's, mu on
// a static contact's relative tangential velocity (equal and opposite impulses).
void dampTangential(World& world, const Params& params, const std::vector<LcpContact>& contacts);

// Positivity after alpha and mu: a tangential impulse at one contact of a sphere that has
// several tilts its velocity into another (the 1k pile under the position method and
// generalized reflections ended steps with a contact approaching at 0.85 m/s). Every
// touching contact findContacts found, separating ones too, is answered once more with
// normal impulses only, per cluster: one inelastic complementarity problem (every target
// 0) by projected Gauss-Seidel, then, where that stops short, rounds of generalized
// reflections at beta = 0 until none approaches (generalized_reflections.cpp). Neither ever
// adds energy. A cluster stopped at the work cap is counted in stats.reflectionCapHits;
// the solve's own contacts and lambdas are left as they are.
void restorePositivity(World& world, const Params& params, StepStats& stats);

// The spheres' contact states and the stats' counts, from the contacts that pushed or
// were static; with world.recordContacts each is also logged as a ContactEvent whose
// velocities are those before (`before`) and after the whole solve.
void reportContacts(World& world, const std::vector<LcpContact>& contacts, const std::vector<glm::dvec3>& before,
                    StepStats& stats, int pass);

}  // namespace physics
