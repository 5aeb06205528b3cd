// The global constraint-based method, slide 14: "impulses only push, momentum kept,
// energy kept or dissipated => linear complementarity, Gauss-Seidel". All touching
// contacts of the pass at once: a contact k between spheres i and j (or a sphere and a
// plane, of infinite mass) with normal u_k from j to i has the relative normal velocity
// c_k = (v_i - v_j).u_k, negative while approaching, and takes an impulse lambda_k >= 0:
// v_i += lambda_k u_k / m_i, v_j -= lambda_k u_k / m_j. Find lambda with
//   c+_k >= b_k,  lambda_k >= 0,  lambda_k (c+_k - b_k) = 0,
// b_k = -beta c_k for a contact that approached (a bounce), 0 for the others (a static
// contact, slide 13, or one that was not approaching: it only pushes to stop an
// approach). Projected Gauss-Seidel: visit the contacts in turn, set each lambda_k to
// what would meet its own b_k, clamp it at 0, until no contact is off by more than
// kLcpTolerance. Then the tangential part, per contact that pushed: alpha on a bounce's,
// mu on a static contact's relative tangential velocity (equal and opposite impulses).
#include <algorithm>
#include <cmath>

#include "physics/solver_stages.h"

namespace physics {
namespace {

// m/s: how far from its target a contact may end.
constexpr double kLcpTolerance = 1e-12;
// Sweeps over the contacts at most, whatever the tolerance: a step never hangs. (A
// landing pile of 1000 needs 300 a solve, and more as it settles: the residual left is
// shown.)
constexpr int kLcpMostSweeps = 1000;

double inverseMass(const World& world, const LcpContact& c) {
    return 1.0 / world.mass[c.i] + (c.j >= 0 ? 1.0 / world.mass[std::size_t(c.j)] : 0.0);
}

double relativeNormal(const World& world, const LcpContact& c) {
    const glm::dvec3 other = c.j >= 0 ? world.velocity[std::size_t(c.j)] : glm::dvec3(0.0);
    return glm::dot(world.velocity[c.i] - other, c.u);
}

void push(World& world, const LcpContact& c, double impulse) {  // kg m/s along u
    world.velocity[c.i] += (impulse / world.mass[c.i]) * c.u;
    if (c.j >= 0) world.velocity[std::size_t(c.j)] -= (impulse / world.mass[std::size_t(c.j)]) * c.u;
}

// The contacts findContacts found, with their targets (m/s).
void gatherContacts(World& world, const Params& params, std::vector<LcpContact>& contacts) {
    const Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = pairsAsVisited(world, params);
    contacts.clear();
    const auto add = [&](std::uint32_t i, std::int64_t j, std::int32_t other, const glm::dvec3& u, double depth) {
        LcpContact c{i, j, other, u, depth, 0.0, 0.0, false};
        const double approach = relativeNormal(world, c);  // m/s, < 0 approaching
        c.isStatic = std::abs(approach) <= params.epsilon;
        c.target = approach < 0.0 && !c.isStatic ? -params.beta * approach : 0.0;
        contacts.push_back(c);
    };
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (ws.pairTouches[k]) {
            add(pairs[k].i, pairs[k].j, std::int32_t(pairs[k].j), ws.pairContacts[k].u, ws.pairContacts[k].depth);
        }
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        for (std::uint32_t w = ws.wallStart[i]; w < ws.wallStart[i + 1]; ++w) {
            const Plane& face = ws.wallContacts[w].face;
            const double depth = world.radius[i] - glm::dot(world.position[i] - face.point, face.normal);  // m
            add(i, -1, -1 - std::int32_t(ws.wallContacts[w].plane), face.normal, depth);
        }
    }
}

// Projected Gauss-Seidel; returns the sweeps made.
int projectedGaussSeidel(World& world, std::vector<LcpContact>& contacts, double& residual) {
    int sweeps = 0;
    do {
        residual = 0.0;
        for (LcpContact& c : contacts) {
            const double error = c.target - relativeNormal(world, c);  // m/s: > 0, too slow apart
            const double lambda = std::max(0.0, c.lambda + error / inverseMass(world, c));
            push(world, c, lambda - c.lambda);
            residual = std::max(residual, c.lambda > 0.0 || lambda > 0.0 ? std::abs(error) : std::max(error, 0.0));
            c.lambda = lambda;
        }
    } while (++sweeps < kLcpMostSweeps && residual > kLcpTolerance);
    return sweeps;
}

// Alpha on a bounce's, mu on a static contact's relative tangential velocity.
void dampTangential(World& world, const Params& params, const std::vector<LcpContact>& contacts) {
    for (const LcpContact& c : contacts) {
        if (c.lambda <= 0.0) continue;
        const glm::dvec3 other = c.j >= 0 ? world.velocity[std::size_t(c.j)] : glm::dvec3(0.0);
        const glm::dvec3 relative = world.velocity[c.i] - other;
        const glm::dvec3 tangential = relative - glm::dot(relative, c.u) * c.u;  // m/s
        const double keep = c.isStatic ? params.mu : params.alpha;
        const glm::dvec3 impulse = ((keep - 1.0) / inverseMass(world, c)) * tangential;  // kg m/s
        world.velocity[c.i] += impulse / world.mass[c.i];
        if (c.j >= 0) world.velocity[std::size_t(c.j)] -= impulse / world.mass[std::size_t(c.j)];
    }
}

// With world.recordContacts: each contact that pushed, or was static, as a ContactEvent
// whose velocities are those before and after the whole solve (the others' shares in).
void logContacts(World& world, const std::vector<LcpContact>& contacts, const std::vector<glm::dvec3>& before,
                 int pass) {
    for (const LcpContact& c : contacts) {
        if (c.lambda <= 0.0 && !c.isStatic) continue;
        const std::size_t j = c.j >= 0 ? std::size_t(c.j) : 0;
        const glm::dvec3 none(0.0);
        world.contacts.push_back({c.i, c.other, pass, !c.isStatic, c.u, world.position[c.i] - world.radius[c.i] * c.u,
                                  c.depth, {before[c.i], c.j >= 0 ? before[j] : none},
                                  {world.velocity[c.i], c.j >= 0 ? world.velocity[j] : none},
                                  {world.mass[c.i], c.j >= 0 ? world.mass[j] : 0.0}});
    }
}

}  // namespace

void solveContactsTogether(World& world, const Params& params, StepStats& stats, int pass) {
    std::vector<LcpContact>& contacts = world.workspace.lcpContacts;
    gatherContacts(world, params, contacts);
    if (contacts.empty()) return;
    if (world.recordContacts) world.workspace.passStart = world.velocity;
    double residual = 0.0;  // m/s
    stats.lcpSweeps += std::uint64_t(projectedGaussSeidel(world, contacts, residual));
    stats.lcpResidual = std::max(stats.lcpResidual, residual);
    dampTangential(world, params, contacts);
    if (world.recordContacts) logContacts(world, contacts, world.workspace.passStart, pass);
    for (const LcpContact& c : contacts) {
        if (c.lambda <= 0.0 && !c.isStatic) continue;
        const ContactState state = c.isStatic ? ContactState::Static : ContactState::Colliding;
        for (std::int64_t s : {std::int64_t(c.i), c.j}) {
            if (s < 0) continue;
            ContactState& mine = world.contactState[std::size_t(s)];
            if (state == ContactState::Colliding || mine == ContactState::Free) mine = state;
        }
        ++(c.isStatic ? stats.staticContacts : stats.collisions);
    }
}

}  // namespace physics
