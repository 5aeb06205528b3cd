#include "physics/diagnostics.h"

#include <algorithm>
#include <cstring>

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
