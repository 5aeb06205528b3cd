#include "physics/collision_response.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace physics {
namespace {

// kg: the mass that a pair's relative motion has, 1 / (1/m1 + 1/m2).
double reducedMass(double m1, double m2) { return 1.0 / (1.0 / m1 + 1.0 / m2); }

// Slide 12, written for any masses: v1 <- alpha v1_par + beta (v1_perp + j/m1 u),
// with j the elastic impulse of slide 11. For m1 = m2 this is alpha v1_par + beta v2_perp.
void lectureAttenuation(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                        const glm::dvec3& u, double approachSpeed, const Params& params) {
    const double j = 2.0 * reducedMass(m1, m2) * approachSpeed;  // kg m/s
    const glm::dvec3 v1Perp = glm::dot(v1, u) * u;
    const glm::dvec3 v2Perp = glm::dot(v2, u) * u;
    const glm::dvec3 v1Par = v1 - v1Perp;
    const glm::dvec3 v2Par = v2 - v2Perp;
    v1 = params.alpha * v1Par + params.beta * (v1Perp + (j / m1) * u);
    v2 = params.alpha * v2Par + params.beta * (v2Perp - (j / m2) * u);
}

// Equal and opposite impulses: (1 + beta) on the normal relative speed, and a
// tangential impulse that scales the relative tangential velocity by alpha.
void momentumConserving(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                        const glm::dvec3& u, double approachSpeed, const Params& params) {
    const double mass = reducedMass(m1, m2);
    const glm::dvec3 tangential = (v2 - v1) - approachSpeed * u;
    const glm::dvec3 impulse =
        (1.0 + params.beta) * mass * approachSpeed * u + (1.0 - params.alpha) * mass * tangential;
    v1 += impulse / m1;
    v2 -= impulse / m2;
}

// Slide 13, 2-b: no bounce (the approaching normal speed is removed, perfectly
// inelastic), then friction v <- mu v. In the momentum-conserving model the
// friction damps the relative tangential velocity instead, so momentum stays exact.
void staticSphereContact(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                         const glm::dvec3& u, double approachSpeed, const Params& params) {
    if (approachSpeed > 0.0) cancelApproachBetween(v1, v2, m1, m2, u);
    if (params.response == ResponseModel::LectureAttenuation) {
        v1 *= params.mu;
        v2 *= params.mu;
        return;
    }
    const glm::dvec3 relative = v2 - v1;
    const glm::dvec3 tangential = relative - glm::dot(relative, u) * u;
    const glm::dvec3 impulse = (1.0 - params.mu) * reducedMass(m1, m2) * tangential;
    v1 += impulse / m1;
    v2 -= impulse / m2;
}

}  // namespace

Response respondToPlane(glm::dvec3& v, const glm::dvec3& n, const Params& params) {
    const double normalSpeed = glm::dot(v, n);  // m/s, negative while approaching
    if (std::abs(normalSpeed) <= params.epsilon) {
        if (normalSpeed < 0.0) v -= normalSpeed * n;
        v *= params.mu;
        return Response::Static;
    }
    if (normalSpeed > 0.0) return Response::None;
    const glm::dvec3 vPerp = normalSpeed * n;
    const glm::dvec3 vPar = v - vPerp;
    v = params.alpha * vPar - params.beta * vPerp;
    return Response::Bounce;
}

void projectOnPlane(glm::dvec3& p, double r, const Plane& plane) {
    const double d = r - glm::dot(p - plane.point, plane.normal);  // m
    p += d * plane.normal;
}

Response respondToSphere(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                         const glm::dvec3& u, const Params& params) {
    const double approachSpeed = glm::dot(v2 - v1, u);  // m/s, positive while approaching
    if (std::abs(approachSpeed) <= params.epsilon) {
        staticSphereContact(v1, v2, m1, m2, u, approachSpeed, params);
        return Response::Static;
    }
    if (approachSpeed < 0.0) return Response::None;
    if (params.response == ResponseModel::LectureAttenuation) {
        lectureAttenuation(v1, v2, m1, m2, u, approachSpeed, params);
    } else {
        momentumConserving(v1, v2, m1, m2, u, approachSpeed, params);
    }
    return Response::Bounce;
}

void separateSpheres(glm::dvec3& p1, glm::dvec3& p2, double m1, double m2, const glm::dvec3& u,
                     double d, PositionSplit split) {
    const double share1 = split == PositionSplit::HalfHalf ? 0.5 : m2 / (m1 + m2);
    p1 += (share1 * d) * u;
    p2 -= ((1.0 - share1) * d) * u;
}

void cancelApproachToPlane(glm::dvec3& v, const glm::dvec3& n) {
    const double normalSpeed = glm::dot(v, n);
    if (normalSpeed < 0.0) v -= normalSpeed * n;
}

void cancelApproachBetween(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                           const glm::dvec3& u) {
    const double approachSpeed = glm::dot(v2 - v1, u);
    if (approachSpeed <= 0.0) return;
    const double j = reducedMass(m1, m2) * approachSpeed;  // kg m/s, perfectly inelastic
    v1 += (j / m1) * u;
    v2 -= (j / m2) * u;
}

}  // namespace physics
