#include "physics/complementarity.h"

#include <algorithm>
#include <cmath>

namespace physics {

double inverseMass(const World& world, const LcpContact& c) {
    return 1.0 / world.mass[c.i] + (c.j >= 0 ? 1.0 / world.mass[std::size_t(c.j)] : 0.0);
}

double relativeNormal(const World& world, const LcpContact& c) {
    const glm::dvec3 other = c.j >= 0 ? world.velocity[std::size_t(c.j)] : glm::dvec3(0.0);
    return glm::dot(world.velocity[c.i] - other, c.u);
}

void push(World& world, const LcpContact& c, double impulse) {
    world.velocity[c.i] += (impulse / world.mass[c.i]) * c.u;
    if (c.j >= 0) world.velocity[std::size_t(c.j)] -= (impulse / world.mass[std::size_t(c.j)]) * c.u;
    if (world.measureImpacts && impulse != 0.0) noteAnswered(world, c.i, c.j);
}

LcpContact contactFor(const World& world, const Params& params, std::uint32_t i, std::int64_t j, std::int32_t other,
                      const glm::dvec3& u, double depth) {
    LcpContact c{i, j, other, u, depth, 0.0, 0.0, false};
    const double approach = relativeNormal(world, c);  // m/s, < 0 approaching
    c.isStatic = std::abs(approach) <= params.epsilon;
    c.target = approach < 0.0 && !c.isStatic ? -params.beta * approach : 0.0;
    return c;
}

void countCluster(const ContactCluster& cluster, StepStats& stats) {
    stats.lcpSweeps += cluster.sweeps;
    stats.reflectionRounds += cluster.rounds;
    stats.lcpResidual = std::max(stats.lcpResidual, cluster.residual);
    stats.reflectionCapHits += cluster.capped;
}

namespace {

// The contacts solved together take in the pairs apart by no more than rounding: this
// fraction of their reach or of their centres' distance from the origin, the larger (the
// last bit of a coordinate). Two impacts of one instant then stay one impact when the last
// bit of a centre has drifted: in 17's second squeeze the middle sphere came back 3e-16 m off
// centre (the first solve left it 4e-16 m/s), so only one of its strikers touched, and lcp
// and generalized reflections answered them in two steps, as the sequential solver would
// ("symmetry ✗" on the projector for the slide that says they keep it).
constexpr double kSameInstantGap = 1e-12;

// A pair that touching() found apart, within kSameInstantGap of touching: its normal, and
// its depth (m, < 0: the gap).
bool apartByRounding(const World& world, const SpherePair& pair, SphereContact& contact) {
    const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];
    const double reach = world.radius[pair.i] + world.radius[pair.j];  // m
    const double scale = std::max({reach, glm::length(world.position[pair.i]), glm::length(world.position[pair.j])});
    const double within = reach + kSameInstantGap * scale;  // m
    const double distanceSquared = glm::dot(delta, delta);
    if (!(distanceSquared > reach * reach && distanceSquared <= within * within)) return false;
    const double distance = std::sqrt(distanceSquared);  // m, > reach > 0
    contact.u = delta * (1.0 / distance);
    contact.depth = reach - distance;
    return true;
}

}  // namespace

void gatherContacts(World& world, const Params& params, bool withSeparating, std::vector<LcpContact>& contacts) {
    const Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = pairsAsVisited(world, params);
    contacts.clear();
    const auto add = [&](std::uint32_t i, std::int64_t j, std::int32_t other, const glm::dvec3& u, double depth) {
        const LcpContact c = contactFor(world, params, i, j, other, u, depth);
        // A contact that separates faster than epsilon takes no part: held at c+ >= 0 it
        // could be pushed to 0, and gain lambda c / 2 of energy from nowhere. Separating by
        // rounding is not separating (kConvergedApproachSpeed, at epsilon = 0): 18's row of
        // three, which the first solve left 2e-15 m/s apart, met the far wall with one of its
        // two contacts left out, and lcp's next pass lost 3.6 % of the energy.
        if (!withSeparating && relativeNormal(world, c) > std::max(params.epsilon, kConvergedApproachSpeed)) return;
        contacts.push_back(c);
    };
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        SphereContact near;
        if (ws.pairTouches[k]) {
            add(pairs[k].i, pairs[k].j, std::int32_t(pairs[k].j), ws.pairContacts[k].u, ws.pairContacts[k].depth);
        } else if (apartByRounding(world, pairs[k], near)) {
            add(pairs[k].i, pairs[k].j, std::int32_t(pairs[k].j), near.u, near.depth);
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

namespace {

std::uint32_t rootOf(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

void sortIntoClusters(World& world, std::vector<LcpContact>& contacts, std::vector<ContactCluster>& clusters) {
    Workspace& ws = world.workspace;
    std::vector<std::uint32_t>& parent = ws.clusterParent;
    parent.resize(world.size());
    for (std::uint32_t i = 0; i < world.size(); ++i) parent[i] = i;
    for (const LcpContact& c : contacts) {
        if (c.j >= 0) parent[rootOf(parent, c.i)] = rootOf(parent, std::uint32_t(c.j));
    }
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t>& clusterOf = ws.clusterOfSphere;  // by root
    clusterOf.assign(world.size(), kNone);
    clusters.clear();
    for (const LcpContact& c : contacts) {
        std::uint32_t& cluster = clusterOf[rootOf(parent, c.i)];
        if (cluster == kNone) cluster = std::uint32_t(clusters.size()), clusters.push_back({});
        ++clusters[cluster].count;
    }
    std::uint32_t first = 0;
    for (ContactCluster& cluster : clusters) {
        cluster.first = first;
        first += cluster.count;
        cluster.count = 0;  // counts again as the contacts are placed
    }
    ws.clusterSorted.resize(contacts.size());
    for (const LcpContact& c : contacts) {
        ContactCluster& cluster = clusters[clusterOf[rootOf(parent, c.i)]];
        ws.clusterSorted[cluster.first + cluster.count++] = c;
    }
    contacts.swap(ws.clusterSorted);
    // Within a cluster, pairs by their spheres' numbers, then walls by sphere and plane:
    // the order the passes visit pairs in depends on the threads (and on the pair order),
    // and the solution's rounding on the order of the sweeps.
    const auto before = [](const LcpContact& a, const LcpContact& b) {
        const bool aWall = a.j < 0, bWall = b.j < 0;
        if (aWall != bWall) return bWall;
        if (a.i != b.i) return a.i < b.i;
        return aWall ? a.other > b.other : a.j < b.j;
    };
    for (const ContactCluster& cluster : clusters) {
        std::sort(contacts.begin() + cluster.first, contacts.begin() + cluster.first + cluster.count, before);
    }
}

double clusterTolerance(std::size_t count, double fastest, bool impact) {
    constexpr double kRestingTolerance = 1e-12;       // m/s
    constexpr std::size_t kSmallCluster = 64;          // contacts
    constexpr double kImpactTolerance = 1e-14;        // of the fastest approach
    if (!impact || count > kSmallCluster) return kRestingTolerance;
    return std::min(kRestingTolerance, kImpactTolerance * fastest);
}

int projectedGaussSeidel(World& world, LcpContact* contacts, std::size_t count, double tolerance, int mostSweeps,
                         double& residual) {
    int sweeps = 0;
    do {
        residual = 0.0;
        for (std::size_t k = 0; k < count; ++k) {
            LcpContact& c = contacts[k];
            const double error = c.target - relativeNormal(world, c);  // m/s: > 0, too slow apart
            const double lambda = std::max(0.0, c.lambda + error / inverseMass(world, c));
            push(world, c, lambda - c.lambda);
            residual = std::max(residual, c.lambda > 0.0 || lambda > 0.0 ? std::abs(error) : std::max(error, 0.0));
            c.lambda = lambda;
        }
    } while (++sweeps < mostSweeps && residual > tolerance);
    return sweeps;
}

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

namespace {

void logContact(World& world, const LcpContact& c, const std::vector<glm::dvec3>& before, int pass) {
    const std::size_t j = c.j >= 0 ? std::size_t(c.j) : 0;
    const glm::dvec3 none(0.0);
    ContactEvent event{c.i, c.other, pass, !c.isStatic, c.u, world.position[c.i] - world.radius[c.i] * c.u,
                       c.depth, {before[c.i], c.j >= 0 ? before[j] : none},
                       {world.velocity[c.i], c.j >= 0 ? world.velocity[j] : none},
                       {world.mass[c.i], c.j >= 0 ? world.mass[j] : 0.0}};
    event.solvedImpulse = c.lambda;  // kg m/s, the global solve's
    event.solverStep = world.stepCount;
    world.contacts.push_back(event);
}

}  // namespace

void reportContacts(World& world, const std::vector<LcpContact>& contacts, const std::vector<glm::dvec3>& before,
                    StepStats& stats, int pass) {
    for (const LcpContact& c : contacts) {
        if (c.lambda <= 0.0 && !c.isStatic) continue;
        if (world.recordContacts) logContact(world, c, before, pass);
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
