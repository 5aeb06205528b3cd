// The global constraint-based method, slide 14: "impulses only push, momentum kept,
// energy kept or dissipated => linear complementarity, Gauss-Seidel". All touching
// contacts of the pass in one problem (complementarity.h):
//   c+_k >= b_k,  lambda_k >= 0,  lambda_k (c+_k - b_k) = 0,
// b_k = -beta c_k for a contact that approached (a bounce), 0 for a static contact (slide
// 13: |c_k| <= epsilon). A contact that separates faster takes no part. Projected Gauss-Seidel until no contact is off by more than kLcpTolerance.
// Then the tangential part, per contact that pushed: alpha on a bounce's, mu on a static
// contact's relative tangential velocity.
#include "physics/complementarity.h"

namespace physics {
namespace {

// m/s: how far from its target a contact may end.
constexpr double kLcpTolerance = 1e-12;
// Sweeps over the contacts at most, whatever the tolerance: a step never hangs. (A
// landing pile of 1000 needs 300 a solve, and more as it settles: the residual left is
// shown.)
constexpr int kLcpMostSweeps = 1000;

}  // namespace

void solveContactsTogether(World& world, const Params& params, StepStats& stats, int pass) {
    std::vector<LcpContact>& contacts = world.workspace.lcpContacts;
    gatherContacts(world, params, false, contacts);
    if (contacts.empty()) return;
    if (world.recordContacts) world.workspace.passStart = world.velocity;
    double residual = 0.0;  // m/s
    stats.lcpSweeps += std::uint64_t(projectedGaussSeidel(world, contacts, kLcpTolerance, kLcpMostSweeps, residual));
    stats.lcpResidual = std::max(stats.lcpResidual, residual);
    dampTangential(world, params, contacts);
    reportContacts(world, contacts, world.workspace.passStart, stats, pass);
}

}  // namespace physics
