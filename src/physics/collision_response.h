#pragma once
// The lecture's collision responses, one function per slide. Velocities in m/s,
// positions in m, masses in kg. Both methods (position_based.cpp,
// velocity_based.cpp) call these; they differ only in when.
#include <glm/vec3.hpp>

#include "physics/params.h"
#include "physics/world.h"

namespace physics {

enum class Response { None, Bounce, Static };

// Slide 4 and slide 13 for a sphere touching a plane of unit normal n:
// static contact when |v.n| <= epsilon, else v <- alpha v_par - beta v_perp while approaching.
Response respondToPlane(glm::dvec3& v, const glm::dvec3& n, const Params& params);

// Slide 8: p <- p + d n, d = r - (p - a).n (the distance of penetration).
void projectOnPlane(glm::dvec3& p, double r, const Plane& plane);

// Slide 7, option 2 (reflection): p <- p + (1 + beta) d n, the penetration mirrored.
void reflectOnPlane(glm::dvec3& p, double r, const Plane& plane, double beta);

// Whether a static sphere-sphere contact's friction damps the pair's relative
// tangential velocity (momentum kept) rather than each sphere's own velocity (the
// slide's v <- mu v): in the momentum-conserving model and in the continuous method.
bool frictionOnRelativeVelocity(const Params& params);

// Slides 11-13 for two touching spheres; u = (p1 - p2) / |p1 - p2| points from 2 to 1.
Response respondToSphere(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                         const glm::dvec3& u, const Params& params);

// Slide 14's shock propagation: the same response against a sphere of a lower level,
// frozen (infinitely heavy): m2 -> infinity, so sphere 1 takes the whole change (its mass
// share is 1) and the frozen sphere keeps its velocity. u points from the frozen sphere to 1.
Response respondToFrozenSphere(glm::dvec3& v1, const glm::dvec3& frozen, const glm::dvec3& u,
                               const Params& params);

// Its position response: sphere 1 alone moves out of the overlap, by d (m) along u.
void moveOffFrozenSphere(glm::dvec3& p1, const glm::dvec3& u, double d);

// How far (m, >= 0) separateSpheres moved each sphere.
struct Separation {
    double first, second;
};

// Slide 13, step 3: d = r1 + r2 - |p1 - p2|; p1 <- p1 + d/2 u, p2 <- p2 - d/2 u
// (or split in inverse proportion to the masses).
Separation separateSpheres(glm::dvec3& p1, glm::dvec3& p2, double m1, double m2, const glm::dvec3& u,
                           double d, PositionSplit split);

// Velocity-based method, step C: remove what still points into a penetration.
void cancelApproachToPlane(glm::dvec3& v, const glm::dvec3& n);
void cancelApproachBetween(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                           const glm::dvec3& u);

}  // namespace physics
