#include "physics/time_of_impact.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace physics {
namespace {

constexpr Contact kNone{};

// Already touching or overlapping (f <= 0): contact now if approaching; else, when
// gravity turns the sphere back towards the plane (k < 0), where it starts to approach
// again while still inside (at the top of its path), or where it falls back in.
Contact contactFromInside(const Gap& f, double within) {
    if (f.b < 0.0) return {true, 0.0, 0};
    if (f.k >= 0.0) return kNone;  // leaving for good
    const double top = -f.b / f.k;  // s: where f stops rising
    const double t = f.at(top) <= 0.0 ? top : (f.b + std::sqrt(f.b * f.b - 2.0 * f.k * f.c)) / -f.k;
    return t <= within ? Contact{true, t, 0} : kNone;
}

// The earliest root of f at which f falls, from the two roots of 1/2 k t^2 + b t + c
// computed without cancellation.
Contact closedForm(const Gap& f, double within) {
    double roots[2];
    int count = 0;
    if (f.k == 0.0) {
        if (f.b != 0.0) roots[count++] = -f.c / f.b;
    } else {
        const double discriminant = f.b * f.b - 2.0 * f.k * f.c;
        if (discriminant < 0.0) return kNone;
        const double q = -0.5 * (f.b + std::copysign(std::sqrt(discriminant), f.b));
        if (q != 0.0) roots[count++] = f.c / q;
        roots[count++] = q / (0.5 * f.k);
    }
    Contact first = kNone;
    for (int n = 0; n < count; ++n) {
        const double t = roots[n];
        if (t < 0.0 || t > within || f.slope(t) >= 0.0) continue;
        if (!first.found || t < first.time) first = {true, t, 0};
    }
    return first;
}

// The slide's binary search: an interval [low, high] with f(low) > 0 >= f(high), halved
// until it is kBisectionTolerance long. The interval ends where f is lowest in the step
// (the vertex of a convex f, the end of the step otherwise), so it holds the first root.
Contact bisection(const Gap& f, double within) {
    double high = within;  // s
    if (f.k > 0.0) high = std::min(high, -f.b / f.k);
    if (high <= 0.0 || f.at(high) > 0.0) return kNone;
    double low = 0.0;  // s
    std::uint64_t iterations = 0;
    while (high - low > kBisectionTolerance) {
        const double middle = 0.5 * (low + high);
        (f.at(middle) > 0.0 ? low : high) = middle;
        ++iterations;
    }
    return {true, high, iterations};
}

}  // namespace

Gap gapToPlane(const glm::dvec3& p, const glm::dvec3& w, double r, const glm::dvec3& g, const Plane& face) {
    return {glm::dot(p - face.point, face.normal) - r, glm::dot(w, face.normal), glm::dot(g, face.normal)};
}

Gap squaredGap(const glm::dvec3& dp, const glm::dvec3& dw, double reach) {
    return {glm::dot(dp, dp) - reach * reach, 2.0 * glm::dot(dp, dw), 2.0 * glm::dot(dw, dw)};
}

Contact firstContact(const Gap& f, double within, TimeOfImpact finder) {
    if (!(f.c > 0.0)) return f.c <= 0.0 ? contactFromInside(f, within) : kNone;  // NaN: never
    // Too far to close the gap within the step at its fastest: no root (most gaps).
    if (f.c > within * (std::abs(f.b) + 0.5 * std::abs(f.k) * within)) return kNone;
    return finder == TimeOfImpact::ClosedForm ? closedForm(f, within) : bisection(f, within);
}

}  // namespace physics
