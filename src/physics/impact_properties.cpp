// Four of Smith et al.'s five properties, measured around the K passes of a solver step.
#include "physics/impact_properties.h"

#include <algorithm>

#include "physics/solver_stages.h"

namespace physics {

ImpactProperties& ImpactProperties::operator+=(const ImpactProperties& o) {
    contacts += o.contacts;
    struck += o.struck;
    momentumChange = std::max(momentumChange, o.momentumChange);
    momentumScale = std::max(momentumScale, o.momentumScale);
    kineticBefore += o.kineticBefore;
    kineticAfter += o.kineticAfter;
    restingPairs += o.restingPairs;
    brokeAway += o.brokeAway;
    fastestApproachAfter = std::max(fastestApproachAfter, o.fastestApproachAfter);
    return *this;
}

namespace {

constexpr std::uint8_t kTouchesPlane = 1;
constexpr std::uint8_t kStruck = 2;
constexpr std::uint8_t kBounced = 4;  // a contact approached faster than epsilon: an impact

std::uint32_t root(std::vector<std::uint32_t>& cluster, std::uint32_t i) {
    while (cluster[i] != i) i = cluster[i] = cluster[cluster[i]];
    return i;
}

// m/s: c, the relative normal velocity (< 0 approaching).
double approach(const World& world, const MeasuredContact& c) {
    const glm::dvec3 other = c.j >= 0 ? world.velocity[std::size_t(c.j)] : glm::dvec3(0.0);
    return glm::dot(world.velocity[c.i] - other, c.u);
}

// The step's candidate pairs are visitOrder (Workspace::pairs holds them only while the
// grid keeps them from step to step: it held the last build's, and the pile's clusters
// came out split, their floor contacts lost: momentum marked broken on a resting column).
void findTouching(World& world, ImpactScratch& scratch) {
    scratch.contacts.clear();
    for (const SpherePair& pair : world.workspace.visitOrder) {
        SphereContact contact;
        if (touching(world, pair, contact)) scratch.contacts.push_back({pair.i, pair.j, contact.u, 0.0});
    }
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        forEachTouchedPlane(world, i, [&](std::size_t k, const Plane& face) {
            scratch.contacts.push_back({i, -1 - std::int64_t(k), face.normal, 0.0});
        });
    }
}

// Whether the contact still touches at the end of the step: the position stages may have
// moved its spheres apart (a contact that no longer touches may approach: it is no contact).
bool stillTouching(const World& world, const MeasuredContact& c) {
    if (c.j >= 0) {
        const glm::dvec3 delta = world.position[c.i] - world.position[std::size_t(c.j)];  // m
        const double reach = world.radius[c.i] + world.radius[std::size_t(c.j)];   // m
        return glm::dot(delta, delta) <= reach * reach;
    }
    const Plane& plane = world.planes[std::size_t(-1 - c.j)];
    return touching(world.position[c.i], world.radius[c.i], faceFor(plane, world.position[c.i]));
}

double kineticOf(const World& world, std::size_t i, const glm::dvec3& v) {
    return 0.5 * world.mass[i] * glm::dot(v, v);  // J
}

// The clusters of a and b become one, their flags merged.
void join(ImpactScratch& scratch, std::uint32_t a, std::uint32_t b) {
    a = root(scratch.cluster, a);
    b = root(scratch.cluster, b);
    if (a == b) return;
    scratch.cluster[a] = b;
    scratch.clusterFlags[b] |= scratch.clusterFlags[a];
}

}  // namespace

// Every response the step makes joins the clusters of its two spheres, wherever they end:
// a falling sphere projected onto a struck pile and answered there gives it energy (300
// spheres landing under lcp: counted apart, the struck clusters' kinetic energy rose 0.02 %
// in a step while the whole world's fell), and in the fast gas (overlaps of up to 200 % of r)
// the later passes' projections carried a pair that met in the second pass beyond the margin
// (joined by distance at the step's end, a cluster the world's exact exchange had passed
// through read "✗ momentum ✗ energy" at step 685).
void noteAnswered(World& world, std::uint32_t i, std::int64_t other) {
    ImpactScratch& scratch = world.workspace.impacts;
    if (!scratch.open) return;
    if (other >= 0) {
        join(scratch, i, std::uint32_t(other));
    } else {
        scratch.clusterFlags[root(scratch.cluster, i)] |= kTouchesPlane;
    }
}

void beginMeasuringImpacts(World& world, const Params& params) {
    world.workspace.impacts.open = false;
    if (!world.measureImpacts) return;
    ImpactScratch& scratch = world.workspace.impacts;
    scratch.open = true;
    scratch.velocityBefore = world.velocity;
    findTouching(world, scratch);
    scratch.cluster.resize(world.size());
    for (std::uint32_t i = 0; i < world.size(); ++i) scratch.cluster[i] = i;
    scratch.clusterFlags.assign(world.size(), 0);
    for (MeasuredContact& c : scratch.contacts) {
        c.approachBefore = approach(world, c);
        if (c.j >= 0) join(scratch, c.i, std::uint32_t(c.j));
    }
    for (const MeasuredContact& c : scratch.contacts) {
        std::uint8_t& flags = scratch.clusterFlags[root(scratch.cluster, c.i)];
        if (c.j < 0) flags |= kTouchesPlane;
        if (c.approachBefore < -kConvergedApproachSpeed) flags |= kStruck;
        if (c.approachBefore < -std::max(params.epsilon, kConvergedApproachSpeed)) flags |= kBounced;
    }
}

void endMeasuringImpacts(World& world, StepStats& stats) {
    if (!world.workspace.impacts.open) return;
    ImpactScratch& scratch = world.workspace.impacts;
    scratch.open = false;
    // A sphere the passes pushed into a wall took an impulse from it: its cluster is not free.
    // (Within the margin: one projected out of a wall ends touching it.)
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        if (nearAPlane(world, i, world.workspace.margin)) scratch.clusterFlags[root(scratch.cluster, i)] |= kTouchesPlane;
    }
    ImpactProperties p;
    p.contacts = scratch.contacts.size();
    glm::dvec3 momentum(0.0);  // kg m/s
    for (std::uint32_t i = 0; i < world.size(); ++i) {
        const std::uint8_t flags = scratch.clusterFlags[root(scratch.cluster, i)];
        const glm::dvec3 before = scratch.velocityBefore[i], after = world.velocity[i];
        if (flags & kStruck) {
            p.kineticBefore += kineticOf(world, i, before);
            p.kineticAfter += kineticOf(world, i, after);
        }
        if ((flags & kStruck) && !(flags & kTouchesPlane)) {
            momentum += world.mass[i] * (after - before);
            p.momentumScale += world.mass[i] * glm::length(before);
        }
    }
    p.momentumChange = glm::length(momentum);
    for (const MeasuredContact& measured : scratch.contacts) {
        p.struck += measured.approachBefore < -kConvergedApproachSpeed;
        // Break-away is tested where an impact struck: a stack at rest has nothing that should part.
        const bool struckCluster = scratch.clusterFlags[root(scratch.cluster, measured.i)] & kBounced;
        const bool resting = measured.j >= 0 && struckCluster && std::abs(measured.approachBefore) <= kConvergedApproachSpeed;
        const bool touchingNow = stillTouching(world, measured);
        if (!touchingNow && !resting) continue;
        // Along the normal the spheres have now: the position stages may have turned it (the
        // solvers answered the contacts along it).
        MeasuredContact c = measured;
        if (c.j >= 0) {
            const glm::dvec3 delta = world.position[c.i] - world.position[std::size_t(c.j)];  // m
            const double distance = glm::length(delta);
            if (distance > 0.0) c.u = delta / distance;
        }
        const double after = approach(world, c);  // m/s
        if (touchingNow) p.fastestApproachAfter = std::max(p.fastestApproachAfter, -after);
        if (!resting) continue;
        ++p.restingPairs;
        p.brokeAway += after > kConvergedApproachSpeed;
    }
    stats.impacts += p;
}

}  // namespace physics
