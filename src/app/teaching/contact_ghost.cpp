#include "app/teaching/contact_ghost.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "physics/collision_response.h"

namespace app {
namespace {

constexpr int kCircleSegments = 40;
constexpr float kGhostLineWidth = 2.0f;  // px

// m: where a sphere at p with path velocity w is after `seconds` of free flight.
glm::dvec3 flown(const glm::dvec3& p, const glm::dvec3& w, const glm::dvec3& g, double seconds) {
    return p + seconds * w + (0.5 * seconds * seconds) * g;
}

void appendCircle(render::FrameSnapshot& snapshot, const glm::dvec3& centre, double radius, const glm::dvec3& a,
                  const glm::dvec3& b, glm::u8vec4 color) {
    for (int s = 0; s < kCircleSegments; ++s) {
        const double t0 = 2.0 * M_PI * s / kCircleSegments, t1 = 2.0 * M_PI * (s + 1) / kCircleSegments;
        snapshot.addLine(glm::vec3(centre + radius * (std::cos(t0) * a + std::sin(t0) * b)),
                         glm::vec3(centre + radius * (std::cos(t1) * a + std::sin(t1) * b)), color, kGhostLineWidth);
    }
}

void appendWireSphere(render::FrameSnapshot& snapshot, const glm::dvec3& centre, double radius, glm::u8vec4 color) {
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    appendCircle(snapshot, centre, radius, x, y, color);
    appendCircle(snapshot, centre, radius, x, z, color);
    appendCircle(snapshot, centre, radius, y, z, color);
}

}  // namespace

std::optional<ContactGhost> lastContactGhost(const physics::World& world, const physics::Params& params, int selected) {
    if (selected < 0 || std::size_t(selected) >= world.size()) return std::nullopt;
    const auto me = std::uint32_t(selected);
    for (auto it = world.contacts.rbegin(); it != world.contacts.rend(); ++it) {
        const physics::ContactEvent& e = *it;
        if (e.timeOfImpact < 0.0 || (e.i != me && e.other != selected)) continue;
        const double r = world.radius[me], rest = params.solverStep() - e.timeOfImpact;  // m, s
        ContactGhost ghost{glm::dvec3(0.0), glm::dvec3(0.0), r, e.timeOfImpact, world.time};
        if (e.isPlane()) {
            ghost.atContact = e.point + r * e.normal;
            ghost.projected = flown(ghost.atContact, e.velocityBefore[0], params.gravity, rest);
            const physics::Plane face{e.point, e.normal, 0.0};
            if (glm::dot(ghost.projected - face.point, face.normal) < r) physics::projectOnPlane(ghost.projected, r, face);
            return ghost;
        }
        // The event's sphere i and the other, both flown on, then their overlap split.
        const auto other = std::uint32_t(e.other);
        if (other >= world.size()) return std::nullopt;
        const glm::dvec3 first = e.point + world.radius[e.i] * e.normal;
        const glm::dvec3 second = first - (world.radius[e.i] + world.radius[other]) * e.normal;
        glm::dvec3 p1 = flown(first, e.velocityBefore[0], params.gravity, rest);
        glm::dvec3 p2 = flown(second, e.velocityBefore[1], params.gravity, rest);
        const glm::dvec3 delta = p1 - p2;
        const double distance = glm::length(delta), overlap = world.radius[e.i] + world.radius[other] - distance;
        if (overlap > 0.0 && distance > 0.0 && !std::isfinite(e.massOf[1])) {
            p1 += overlap * (delta / distance);  // the shock sweep: the frozen sphere does not move
        } else if (overlap > 0.0 && distance > 0.0) {
            physics::separateSpheres(p1, p2, e.massOf[0], e.massOf[1], delta / distance, overlap, params.split);
        }
        const bool mine = e.i == me;
        ghost.atContact = mine ? first : second;
        ghost.projected = mine ? p1 : p2;
        return ghost;
    }
    return std::nullopt;
}

void ContactGhosts::afterStep(const physics::World& world, const physics::Params& params, int selected) {
    if (selected != selected_) latest_.reset();
    selected_ = selected;
    if (std::optional<ContactGhost> ghost = lastContactGhost(world, params, selected)) latest_ = ghost;
}

void appendContactGhost(const ContactGhost& ghost, render::FrameSnapshot& snapshot) {
    appendWireSphere(snapshot, ghost.atContact, ghost.radius, kGhostAtContactColor);
    appendWireSphere(snapshot, ghost.projected, ghost.radius, kGhostProjectedColor);
    snapshot.addLine(glm::vec3(ghost.atContact), glm::vec3(ghost.projected), glm::u8vec4(230, 230, 230, 255),
                     kGhostLineWidth);
}

}  // namespace app
