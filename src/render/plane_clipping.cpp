#include "render/plane_clipping.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace render {
namespace {

float signedDistance(const glm::vec3& p, const Plane& plane) {
    return glm::dot(p - plane.point, plane.normal);
}

// The axis-aligned bounds of the spheres and the planes' points, or a unit cube.
void sceneBounds(const FrameSnapshot& snapshot, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(INFINITY);
    hi = glm::vec3(-INFINITY);
    for (std::size_t i = 0; i < snapshot.centers.size(); ++i) {
        lo = glm::min(lo, snapshot.centers[i] - snapshot.radii[i]);
        hi = glm::max(hi, snapshot.centers[i] + snapshot.radii[i]);
    }
    for (const Plane& plane : snapshot.planes) {
        lo = glm::min(lo, plane.point);
        hi = glm::max(hi, plane.point);
    }
    if (!(lo.x <= hi.x)) {
        lo = glm::vec3(-0.5f);
        hi = glm::vec3(0.5f);
    }
}

}  // namespace

Polygon clipPolygon(const Polygon& polygon, const Plane& keep) {
    // m: vertices this close to the plane count as on it, so that a cut through
    // a corner keeps the corner once instead of adding near-duplicates.
    constexpr float kOnPlane = 1e-5f;
    Polygon out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3& a = polygon[i];
        const glm::vec3& b = polygon[(i + 1) % n];
        const float da = signedDistance(a, keep);
        const float db = signedDistance(b, keep);
        if (da >= -kOnPlane) out.push_back(a);
        // The edge crosses the plane strictly: keep the crossing point.
        if ((da > kOnPlane && db < -kOnPlane) || (da < -kOnPlane && db > kOnPlane)) {
            out.push_back(a + (b - a) * (da / (da - db)));
        }
    }
    return out;
}

Polygon planeSquare(const Plane& plane, float halfSize) {
    const glm::vec3 n = glm::normalize(plane.normal);
    // Any direction not parallel to n gives a tangent basis.
    const glm::vec3 helper =
        std::abs(n.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, n)) * halfSize;
    const glm::vec3 v = glm::cross(n, u);
    const glm::vec3& c = plane.point;
    return {c - u - v, c + u - v, c + u + v, c - u + v};
}

Polygon clipPlaneToRegion(const Plane& plane, const std::vector<Plane>& region, int skip,
                          float halfSize) {
    Polygon polygon = planeSquare(plane, halfSize);
    for (std::size_t i = 0; i < region.size() && polygon.size() >= 3; ++i) {
        if (static_cast<int>(i) != skip) polygon = clipPolygon(polygon, region[i]);
    }
    return polygon.size() >= 3 ? polygon : Polygon{};
}

std::vector<Plane> cubePlanes(const glm::vec3& center, float halfSize) {
    std::vector<Plane> planes;
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            Plane plane;
            plane.point = center;
            plane.point[axis] += side * halfSize;
            plane.normal = glm::vec3(0.0f);
            plane.normal[axis] = -side;
            planes.push_back(plane);
        }
    }
    return planes;
}

std::vector<Polygon> planePolygons(const FrameSnapshot& snapshot) {
    glm::vec3 lo;
    glm::vec3 hi;
    sceneBounds(snapshot, lo, hi);
    // Large enough to contain any closed box, so it only trims what is unbounded.
    const float halfSize = 0.75f * glm::length(hi - lo) + 0.5f;
    const glm::vec3 center = 0.5f * (lo + hi);
    const int boxCount =
        std::clamp(snapshot.boxPlaneCount, 0, static_cast<int>(snapshot.planes.size()));
    std::vector<Plane> region(snapshot.planes.begin(), snapshot.planes.begin() + boxCount);
    const std::vector<Plane> cube = cubePlanes(center, halfSize);
    region.insert(region.end(), cube.begin(), cube.end());

    // The square must outgrow the cube wherever the plane's point sits.
    const float squareHalf = 4.0f * halfSize + glm::length(hi - lo);
    std::vector<Polygon> polygons;
    for (std::size_t i = 0; i < snapshot.planes.size(); ++i) {
        const int skip = static_cast<int>(i) < boxCount ? static_cast<int>(i) : -1;
        polygons.push_back(clipPlaneToRegion(snapshot.planes[i], region, skip, squareHalf));
    }
    return polygons;
}

}  // namespace render
