#pragma once
// Turning infinite planes into drawable polygons: a large square on the plane,
// cut by the half-spaces of the box (Sutherland-Hodgman, one plane at a time).
#include <glm/vec3.hpp>
#include <vector>

#include "render/frame_snapshot.h"

namespace render {

using Polygon = std::vector<glm::vec3>;  // convex, vertices in order, m

// Keeps the part of the polygon on the free side of the plane ((p - point) . normal >= 0).
Polygon clipPolygon(const Polygon& polygon, const Plane& keep);
// A square of half-size halfSize (m) on the plane, centred on the plane's point.
Polygon planeSquare(const Plane& plane, float halfSize);
// planeSquare cut by every plane of `region` except the one at index `skip` (-1: none).
Polygon clipPlaneToRegion(const Plane& plane, const std::vector<Plane>& region, int skip,
                          float halfSize);
// The six planes of an axis-aligned cube, normals pointing inwards.
std::vector<Plane> cubePlanes(const glm::vec3& center, float halfSize);

// One polygon per snapshot plane (empty when the plane misses the region): box
// planes cut by the other box planes, extra planes cut by the box, and all of
// them cut by a cube around the scene, which also stands in for a missing box.
std::vector<Polygon> planePolygons(const FrameSnapshot& snapshot);

}  // namespace render
