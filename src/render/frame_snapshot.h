#pragma once
// What the renderer draws, as plain arrays copied out of the world once per
// frame. The renderer reads only this: it never touches the solver's state.
#include <cstddef>
#include <cstdint>
#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace physics {
struct World;
}

namespace render {

// A plane: a point on it and the unit normal pointing into the free side.
struct Plane {
    glm::vec3 point{0.0f};               // m
    glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit
};

// A segment drawn over the scene: contact normals, impulses, velocities, trails.
struct OverlayLine {
    glm::vec3 a{0.0f};  // m
    glm::vec3 b{0.0f};  // m
    glm::u8vec4 color{255, 255, 255, 255};
    float width = 2.0f;  // px (times RenderStyle::lineScale)
};

// A dot drawn over the scene: contact points, picked sphere.
struct OverlayPoint {
    glm::vec3 position{0.0f};  // m
    glm::u8vec4 color{255, 255, 255, 255};
    float size = 8.0f;  // px, diameter (times RenderStyle::lineScale)
};

struct FrameSnapshot {
    // One entry per sphere, all three arrays the same length.
    std::vector<glm::vec3> centers;   // m
    std::vector<float> radii;         // m
    std::vector<glm::u8vec4> colors;  // sRGB, alpha unused

    // The first boxPlaneCount planes form the box (it may be tilted, or absent
    // when boxPlaneCount is 0); the rest are extra planes such as an incline.
    std::vector<Plane> planes;
    int boxPlaneCount = 0;

    std::vector<OverlayLine> lines;
    std::vector<OverlayPoint> points;

    std::size_t sphereCount() const { return centers.size(); }
    void addSphere(const glm::vec3& center, float radius, glm::u8vec4 color);
    void addLine(const glm::vec3& a, const glm::vec3& b, glm::u8vec4 color, float width = 2.0f);
    void addPoint(const glm::vec3& position, glm::u8vec4 color, float size = 8.0f);
    void clear();
};

// How snapshotSpheres colours each sphere.
enum class ColorBy {
    Id,            // a fixed, varied palette: follow one sphere with the eye
    Speed,         // a perceptual colormap from 0 to maxSpeed
    ContactState,  // free / colliding / static contact (the lecture's epsilon rule)
    Penetration,   // the deepest overlap, on a log scale (penetrationColor)
};

// Copies the spheres (centres, radii, colours) of the world; maxSpeed in m/s is
// the top of the Speed colormap. Overwrites the sphere arrays only.
void snapshotSpheres(const physics::World& world, ColorBy colorBy, FrameSnapshot& snapshot,
                     float maxSpeed = 3.0f);
// Copies the planes and boxPlaneCount. Overwrites the plane array only.
void snapshotPlanes(const physics::World& world, FrameSnapshot& snapshot);

}  // namespace render
