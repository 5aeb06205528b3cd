#include "render/frame_snapshot.h"

#include <glm/geometric.hpp>

#include "physics/diagnostics.h"
#include "physics/world.h"
#include "render/palette.h"

namespace render {

void FrameSnapshot::addSphere(const glm::vec3& center, float radius, glm::u8vec4 color) {
    centers.push_back(center);
    radii.push_back(radius);
    colors.push_back(color);
}

void FrameSnapshot::addLine(const glm::vec3& a, const glm::vec3& b, glm::u8vec4 color,
                            float width) {
    lines.push_back({a, b, color, width});
}

void FrameSnapshot::addPoint(const glm::vec3& position, glm::u8vec4 color, float size) {
    points.push_back({position, color, size});
}

void FrameSnapshot::clear() {
    centers.clear();
    radii.clear();
    colors.clear();
    planes.clear();
    boxPlaneCount = 0;
    lines.clear();
    points.clear();
}

namespace {

glm::u8vec4 sphereColor(const physics::World& world, std::size_t i, ColorBy colorBy,
                        float maxSpeed, const std::vector<double>& overlaps) {
    switch (colorBy) {
        case ColorBy::Penetration:
            return penetrationColor(overlaps[i]);
        case ColorBy::Id:
            return idColor(static_cast<std::uint32_t>(i));
        case ColorBy::Speed:
            return speedColor(static_cast<float>(glm::length(world.velocity[i])), maxSpeed);
        case ColorBy::ContactState:
            // The solver may not have classified a sphere added since its last step.
            return contactColor(i < world.contactState.size() ? world.contactState[i]
                                                              : physics::ContactState::Free);
    }
    return idColor(static_cast<std::uint32_t>(i));
}

}  // namespace

void snapshotSpheres(const physics::World& world, ColorBy colorBy, FrameSnapshot& snapshot,
                     float maxSpeed) {
    const std::size_t n = world.size();
    const std::vector<double> overlaps = colorBy == ColorBy::Penetration ? physics::deepestOverlaps(world) : std::vector<double>{};
    snapshot.centers.resize(n);
    snapshot.radii.resize(n);
    snapshot.colors.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        snapshot.centers[i] = glm::vec3(world.position[i]);
        snapshot.radii[i] = static_cast<float>(world.radius[i]);
        snapshot.colors[i] = sphereColor(world, i, colorBy, maxSpeed, overlaps);
    }
}

void snapshotPlanes(const physics::World& world, FrameSnapshot& snapshot) {
    snapshot.planes.clear();
    for (const physics::Plane& plane : world.planes) {
        snapshot.planes.push_back({glm::vec3(plane.point), glm::vec3(plane.normal)});
    }
    snapshot.boxPlaneCount = world.boxPlaneCount;
}

}  // namespace render
