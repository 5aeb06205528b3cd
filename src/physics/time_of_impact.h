#pragma once
// Slide 7, option 3: "go backward in time to the exact instant of collision". Within
// one solver step every sphere follows the parabola semi-implicit Euler puts it on, so
// each gap the continuous method watches is a quadratic in the time since now:
//   f(t) = c + b t + 1/2 k t^2,
// the sphere-plane gap (m) or, for two spheres, |p1 - p2|^2 - (r1 + r2)^2 (m^2), in
// which gravity cancels. Contact is where f falls to 0.
#include <cstdint>

#include <glm/vec3.hpp>

#include "physics/params.h"
#include "physics/world.h"

namespace physics {

struct Gap {
    double c = 0.0;  // now
    double b = 0.0;  // per s
    double k = 0.0;  // per s^2
    double at(double t) const { return c + t * (b + 0.5 * k * t); }
    double slope(double t) const { return b + k * t; }
};

// A sphere (centre p, path velocity w, radius r) under gravity g and a plane face.
Gap gapToPlane(const glm::dvec3& p, const glm::dvec3& w, double r, const glm::dvec3& g, const Plane& face);

// Two spheres: dp = p1 - p2, dw = w1 - w2, reach = r1 + r2.
Gap squaredGap(const glm::dvec3& dp, const glm::dvec3& dw, double reach);

// The first contact within [0, within] s: the earliest t at which f(t) <= 0 while f
// falls (the two approach). Touching or overlapping now and approaching: t = 0.
struct Contact {
    bool found = false;
    double time = 0.0;              // s from now
    std::uint64_t iterations = 0;   // the bisection's halvings
};
Contact firstContact(const Gap& f, double within, TimeOfImpact finder);

}  // namespace physics
