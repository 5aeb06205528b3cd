#include "physics/collision_response.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace physics {
namespace {

// How a change of the pair's relative velocity splits between its spheres. An impulse
// J = m_red dv (m_red = 1 / (1/m1 + 1/m2), the pair's reduced mass, dv in m/s) changes
// v1 by J/m1 = dv m2/(m1 + m2) and v2 by J/m2 = dv m1/(m1 + m2): each sphere takes the
// other's share of the total mass. One division per contact instead of five.
struct MassShares {
    double first, second;  // dimensionless, first + second = 1
};
MassShares massShares(double m1, double m2) {
    const double perTotalMass = 1.0 / (m1 + m2);  // 1/kg
    return {m2 * perTotalMass, m1 * perTotalMass};
}

// Slide 12, written for any masses: v1 <- alpha v1_par + beta (v1_perp + j/m1 u),
// with j the elastic impulse of slide 11, j = 2 m_red (v2 - v1).u. For m1 = m2 this
// is alpha v1_par + beta v2_perp.
void lectureAttenuation(glm::dvec3& v1, glm::dvec3& v2, const MassShares& shares,
                        const glm::dvec3& u, double approachSpeed, const Params& params) {
    const double elastic = 2.0 * approachSpeed;  // m/s: j / m_red
    const glm::dvec3 v1Perp = glm::dot(v1, u) * u;
    const glm::dvec3 v2Perp = glm::dot(v2, u) * u;
    const glm::dvec3 v1Par = v1 - v1Perp;
    const glm::dvec3 v2Par = v2 - v2Perp;
    v1 = params.alpha * v1Par + params.beta * (v1Perp + (elastic * shares.first) * u);
    v2 = params.alpha * v2Par + params.beta * (v2Perp - (elastic * shares.second) * u);
}

// Equal and opposite impulses: (1 + beta) on the normal relative speed, and a
// tangential impulse that scales the relative tangential velocity by alpha.
void momentumConserving(glm::dvec3& v1, glm::dvec3& v2, const MassShares& shares,
                        const glm::dvec3& u, double approachSpeed, const Params& params) {
    const glm::dvec3 tangential = (v2 - v1) - approachSpeed * u;
    const glm::dvec3 change =  // m/s: impulse / m_red
        (1.0 + params.beta) * approachSpeed * u + (1.0 - params.alpha) * tangential;
    v1 += shares.first * change;
    v2 -= shares.second * change;
}

// Perfectly inelastic along u: the pair stops approaching.
void cancelApproach(glm::dvec3& v1, glm::dvec3& v2, const MassShares& shares,
                    const glm::dvec3& u, double approachSpeed) {
    v1 += (approachSpeed * shares.first) * u;
    v2 -= (approachSpeed * shares.second) * u;
}

// Slide 13, 2-b: no bounce (the approaching normal speed is removed, perfectly
// inelastic), then friction v <- mu v (frictionOnRelativeVelocity says on what).
void staticSphereContact(glm::dvec3& v1, glm::dvec3& v2, const MassShares& shares,
                         const glm::dvec3& u, double approachSpeed, const Params& params) {
    if (approachSpeed > 0.0) cancelApproach(v1, v2, shares, u, approachSpeed);
    if (!frictionOnRelativeVelocity(params)) {
        v1 *= params.mu;
        v2 *= params.mu;
        return;
    }
    const glm::dvec3 relative = v2 - v1;
    const glm::dvec3 tangential = relative - glm::dot(relative, u) * u;
    const glm::dvec3 change = (1.0 - params.mu) * tangential;  // m/s: impulse / m_red
    v1 += shares.first * change;
    v2 -= shares.second * change;
}

}  // namespace

// The methods that claim physical correctness keep momentum in a static contact too, so
// that a touching pair in free fall falls (physics.md, slide 13).
bool frictionOnRelativeVelocity(const Params& params) {
    return params.response == ResponseModel::MomentumConserving || params.method == Method::Continuous;
}

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

void reflectOnPlane(glm::dvec3& p, double r, const Plane& plane, double beta) {
    const double d = r - glm::dot(p - plane.point, plane.normal);  // m
    p += ((1.0 + beta) * d) * plane.normal;
}

namespace {

// Slides 11-13 with the pair's mass shares given: the response of respondToSphere.
Response respondWithShares(glm::dvec3& v1, glm::dvec3& v2, const MassShares& shares, const glm::dvec3& u,
                           const Params& params) {
    const double approachSpeed = glm::dot(v2 - v1, u);  // m/s, positive while approaching
    if (std::abs(approachSpeed) <= params.epsilon) {
        staticSphereContact(v1, v2, shares, u, approachSpeed, params);
        return Response::Static;
    }
    if (approachSpeed < 0.0) return Response::None;
    if (params.response == ResponseModel::LectureAttenuation) {
        lectureAttenuation(v1, v2, shares, u, approachSpeed, params);
    } else {
        momentumConserving(v1, v2, shares, u, approachSpeed, params);
    }
    return Response::Bounce;
}

}  // namespace

Response respondToSphere(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                         const glm::dvec3& u, const Params& params) {
    return respondWithShares(v1, v2, massShares(m1, m2), u, params);
}

Response respondToFrozenSphere(glm::dvec3& v1, const glm::dvec3& frozen, const glm::dvec3& u,
                               const Params& params) {
    glm::dvec3 v2 = frozen;  // m/s: what the response would do to it is dropped
    return respondWithShares(v1, v2, MassShares{1.0, 0.0}, u, params);
}

void moveOffFrozenSphere(glm::dvec3& p1, const glm::dvec3& u, double d) { p1 += d * u; }

Separation separateSpheres(glm::dvec3& p1, glm::dvec3& p2, double m1, double m2, const glm::dvec3& u,
                           double d, PositionSplit split) {
    const MassShares shares = split == PositionSplit::HalfHalf ? MassShares{0.5, 0.5} : massShares(m1, m2);
    const Separation moved{shares.first * d, shares.second * d};  // m, along the unit u
    p1 += moved.first * u;
    p2 -= moved.second * u;
    return moved;
}

void cancelApproachToPlane(glm::dvec3& v, const glm::dvec3& n) {
    const double normalSpeed = glm::dot(v, n);
    if (normalSpeed < 0.0) v -= normalSpeed * n;
}

void cancelApproachBetween(glm::dvec3& v1, glm::dvec3& v2, double m1, double m2,
                           const glm::dvec3& u) {
    const double approachSpeed = glm::dot(v2 - v1, u);  // m/s
    if (approachSpeed > 0.0) cancelApproach(v1, v2, massShares(m1, m2), u, approachSpeed);
}

}  // namespace physics
