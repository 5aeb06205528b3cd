#include "physics/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include <glm/geometric.hpp>

#include "physics/broad_phase.h"
#include "physics/solver_stages.h"

namespace physics {
namespace {

void addEnergies(const World& world, const Params& params, Diagnostics& d) {
    const glm::dvec3 g = params.gravity;
    const double h = params.solverStep();
    for (std::size_t i = 0; i < world.size(); ++i) {
        const double m = world.mass[i];
        const glm::dvec3& v = world.velocity[i];
        const glm::dvec3 vHalf = v + (0.5 * h) * g;  // m/s, the velocity E~ is built on
        d.kinetic += 0.5 * m * glm::dot(v, v);
        d.potential -= m * glm::dot(g, world.position[i]);
        d.modified += m * (-glm::dot(g, world.position[i]) + 0.5 * glm::dot(vHalf, vHalf));
        d.momentum += m * v;
        d.momentumScale += m * glm::length(v);
    }
    d.total = d.kinetic + d.potential;
}

void addSphereContacts(const World& world, const Params& params, Diagnostics& d) {
    Workspace workspace;
    findPairsGrid(world, 0.0, workspace, solverThreads(world, params));
    for (const SpherePair& pair : workspace.pairs) {
        const double reach = world.radius[pair.i] + world.radius[pair.j];
        const double depth = reach - glm::distance(world.position[pair.i], world.position[pair.j]);
        ++d.sphereContacts;
        const double smaller = std::min(world.radius[pair.i], world.radius[pair.j]);
        d.maxPenetration = std::max(d.maxPenetration, depth / smaller);
    }
}

void addWallContacts(const World& world, Diagnostics& d) {
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (const Plane& plane : world.planes) {
            const Plane face = faceFor(plane, world.position[i]);
            const double depth = world.radius[i] - glm::dot(world.position[i] - face.point, face.normal);
            if (depth < 0.0) continue;
            ++d.wallContacts;
            d.maxPenetration = std::max(d.maxPenetration, depth / world.radius[i]);
        }
    }
}

void hashBytes(std::uint64_t& hash, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) {
        hash ^= bytes[k];
        hash *= 0x100000001B3ull;  // FNV-1a 64 prime
    }
}

}  // namespace

double modifiedEnergy(const World& world, const Params& params) {
    Diagnostics d;
    addEnergies(world, params, d);
    return d.modified;
}

std::uint64_t stateHash(const World& world) {
    std::uint64_t hash = 0xCBF29CE484222325ull;  // FNV-1a 64 offset basis
    hashBytes(hash, world.position.data(), world.size() * sizeof(glm::dvec3));
    hashBytes(hash, world.velocity.data(), world.size() * sizeof(glm::dvec3));
    return hash;
}

Diagnostics measure(const World& world, const Params& params) {
    Diagnostics d;
    addEnergies(world, params, d);
    addSphereContacts(world, params, d);
    addWallContacts(world, d);
    d.hash = stateHash(world);
    return d;
}

glm::dvec3 momentumShown(const Diagnostics& d) {
    constexpr double kRounding = 1e-12;  // of sum m |v|
    glm::dvec3 shown = d.momentum;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(shown[k]) <= kRounding * d.momentumScale) shown[k] = 0.0;
    }
    return shown;
}

namespace {

constexpr double kTouching = 1e-4;  // m: a gap this small still carries a sphere
constexpr double kBelow = 0.1;      // a support lies this far below, as a share of the distance

// Whether sphere i rests on a plane: touching one whose normal points up (against g).
bool onAPlane(const World& world, std::size_t i, const glm::dvec3& down) {
    for (const Plane& plane : world.planes) {
        const Plane face = faceFor(plane, world.position[i]);
        const double gap = glm::dot(world.position[i] - face.point, face.normal) - world.radius[i];
        if (gap <= kTouching && -glm::dot(face.normal, down) > kBelow) return true;
    }
    return false;
}

}  // namespace

std::vector<double> deepestOverlaps(const World& world) {
    std::vector<double> deepest(world.size(), 0.0);
    if (world.size() == 0) return deepest;
    Workspace workspace;
    findPairsGrid(world, 0.0, workspace, 1);
    for (const SpherePair& pair : workspace.pairs) {
        const double reach = world.radius[pair.i] + world.radius[pair.j];  // m
        const double depth = reach - glm::distance(world.position[pair.i], world.position[pair.j]);  // m
        const double overlap = depth / std::min(world.radius[pair.i], world.radius[pair.j]);
        deepest[pair.i] = std::max(deepest[pair.i], overlap);
        deepest[pair.j] = std::max(deepest[pair.j], overlap);
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (const Plane& plane : world.planes) {
            const Plane face = faceFor(plane, world.position[i]);
            const double depth = world.radius[i] - glm::dot(world.position[i] - face.point, face.normal);  // m
            deepest[i] = std::max(deepest[i], depth / world.radius[i]);
        }
    }
    return deepest;
}

std::size_t spheresHeldInMidAir(const World& world, const Params& params) {
    const double g = glm::length(params.gravity);
    if (g == 0.0 || world.size() == 0) return 0;
    const glm::dvec3 down = params.gravity / g;
    Workspace workspace;
    findPairsGrid(world, kTouching, workspace, 1);
    std::vector<std::vector<std::uint32_t>> lower(world.size());  // the touching spheres below each
    std::vector<bool> touchesASphere(world.size(), false);
    for (const SpherePair& pair : workspace.pairs) {
        const glm::dvec3 ij = world.position[pair.j] - world.position[pair.i];
        const double distance = glm::length(ij);
        if (distance > world.radius[pair.i] + world.radius[pair.j] + kTouching) continue;
        touchesASphere[pair.i] = touchesASphere[pair.j] = true;
        const double drop = glm::dot(ij, down);  // how far j lies below i, m
        if (drop > kBelow * distance) lower[pair.i].push_back(pair.j);
        if (-drop > kBelow * distance) lower[pair.j].push_back(pair.i);
    }
    // Lowest first: a sphere is carried when it rests on a plane or on a carried sphere.
    std::vector<std::size_t> order(world.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return glm::dot(world.position[a], down) > glm::dot(world.position[b], down);
    });
    std::vector<bool> carried(world.size(), false);
    std::size_t held = 0;
    for (std::size_t i : order) {
        carried[i] = onAPlane(world, i, down) ||
                     std::any_of(lower[i].begin(), lower[i].end(), [&](std::uint32_t j) { return carried[j]; });
        // At rest: a static contact, and no faster than epsilon (spheres falling together touch
        // statically too: a falling lattice is not held).
        held += !carried[i] && touchesASphere[i] && world.contactState[i] == ContactState::Static &&
                glm::length(world.velocity[i]) <= params.epsilon;
    }
    return held;
}

std::size_t spheresOutsideBox(const World& world, double slack) {
    std::size_t outside = 0;
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (int k = 0; k < world.boxPlaneCount; ++k) {
            const Plane& plane = world.planes[static_cast<std::size_t>(k)];
            if (glm::dot(world.position[i] - plane.point, plane.normal) < -slack) {
                ++outside;
                break;
            }
        }
    }
    return outside;
}

}  // namespace physics

namespace physics {

MirrorAsymmetry mirrorAsymmetry(const World& world, const Plane& mirror) {
    if (world.size() > kMostMirroredSpheres) return {-1.0, -1.0};
    const auto reflect = [&](const glm::dvec3& d) { return d - 2.0 * glm::dot(d, mirror.normal) * mirror.normal; };
    MirrorAsymmetry worst;
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 image = mirror.point + reflect(world.position[i] - mirror.point);  // m
        std::size_t partner = i;
        double nearest = glm::length(world.position[i] - image);
        for (std::size_t k = 0; k < world.size(); ++k) {
            const double d = glm::length(world.position[k] - image);
            if (d < nearest) nearest = d, partner = k;
        }
        worst.position = std::max(worst.position, nearest);
        worst.velocity = std::max(worst.velocity, glm::length(world.velocity[partner] - reflect(world.velocity[i])));
    }
    return worst;
}

}  // namespace physics
