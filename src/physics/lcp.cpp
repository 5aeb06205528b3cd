// The global constraint-based method, slide 14: "impulses only push, momentum kept,
// energy kept or dissipated => linear complementarity, Gauss-Seidel". All touching
// contacts of the pass in one problem (complementarity.h):
//   c+_k >= b_k,  lambda_k >= 0,  lambda_k (c+_k - b_k) = 0,
// b_k = -beta c_k for a contact that approached (a bounce), 0 for a static contact (slide
// 13: |c_k| <= epsilon). A contact that separates faster takes no part. The problem falls
// apart into clusters of spheres that touch: projected Gauss-Seidel on each, until none of
// its contacts is off by more than clusterTolerance (clusters on several threads). Then the
// tangential part, per contact that pushed: alpha on a bounce's, mu on a static contact's
// relative tangential velocity.
#include <algorithm>
#include <cmath>

#include "physics/complementarity.h"

namespace physics {
namespace {

// Sweeps over a cluster's contacts at most, whatever the tolerance: a step never hangs.
// (A landing pile of 1000 needs 300 a solve, and more as it settles: the residual left
// is shown.)
constexpr int kLcpMostSweeps = 1000;

}  // namespace

void solveLcpCluster(World& world, LcpContact* contacts, ContactCluster& cluster) {
    double fastest = 0.0;  // m/s
    bool impact = false;   // a bounce among them
    for (std::uint32_t k = 0; k < cluster.count; ++k) {
        fastest = std::max(fastest, std::abs(relativeNormal(world, contacts[k])));
        impact = impact || contacts[k].target > 0.0;
    }
    const double tolerance = clusterTolerance(cluster.count, fastest, impact);  // m/s
    cluster.sweeps = std::uint32_t(
        projectedGaussSeidel(world, contacts, cluster.count, tolerance, kLcpMostSweeps, cluster.residual));
    cluster.capped = false;
}

void solveContactsTogether(World& world, const Params& params, StepStats& stats, int pass) {
    Workspace& ws = world.workspace;
    std::vector<LcpContact>& contacts = ws.lcpContacts;
    gatherContacts(world, params, false, contacts);
    if (contacts.empty()) return;
    if (world.recordContacts) ws.passStart = world.velocity;
    sortIntoClusters(world, contacts, ws.clusters);
    runTasks(clusterThreads(world, params, ws.clusters.size()), int(ws.clusters.size()), [&](int k) {
        ContactCluster& cluster = ws.clusters[std::size_t(k)];
        solveLcpCluster(world, contacts.data() + cluster.first, cluster);
    });
    std::uint32_t sweeps = 0;  // of the cluster that took most
    for (const ContactCluster& cluster : ws.clusters) {
        sweeps = std::max(sweeps, cluster.sweeps);
        stats.lcpResidual = std::max(stats.lcpResidual, cluster.residual);
    }
    stats.lcpSweeps += sweeps;
    dampTangential(world, params, contacts);
    reportContacts(world, contacts, ws.passStart, stats, pass);
}

}  // namespace physics
