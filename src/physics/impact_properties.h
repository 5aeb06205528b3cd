#pragma once
// Smith et al. 2012 list five properties a simultaneous-impact answer may keep (physics.md,
// "Slide 14, the global approach"). Four of them are measured here, on the velocity stage
// of each solver step (the K passes, whatever the solver), when World::measureImpacts is
// on: momentum, kinetic energy, break-away and positivity. The fifth, mirror symmetry,
// needs the scene's mirror planes: diagnostics.h's mirrorAsymmetry.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace physics {

// What the velocity stages of a step did to the spheres in contact when they began.
struct ImpactProperties {
    std::uint64_t contacts = 0;   // touching contacts (sphere pairs and walls) at the start
    std::uint64_t struck = 0;     // of those, contacts that approached (a cluster with one is struck)
    // kg m/s: |sum m (v_after - v_before)| over the clusters that touch no plane (momentum
    // kept: 0), the largest of the steps; and sum m |v_before| of those spheres, its scale.
    double momentumChange = 0.0;
    double momentumScale = 0.0;
    // J: kinetic energy of the spheres of struck clusters, before and after, summed.
    double kineticBefore = 0.0;
    double kineticAfter = 0.0;
    // Touching sphere pairs that did not approach (|c| within kConvergedApproachSpeed), in
    // clusters an impact struck (a contact approaching faster than epsilon: a stack at rest
    // has nothing that should part), and how many of them separate afterwards (break-away).
    std::uint64_t restingPairs = 0;
    std::uint64_t brokeAway = 0;
    // m/s: the fastest approach left between touching spheres or a sphere and a wall
    // (positivity: 0), the largest of the steps.
    double fastestApproachAfter = 0.0;

    ImpactProperties& operator+=(const ImpactProperties& o);
};

// A contact of the measurement: spheres i and j (j < 0: the plane -1 - j), unit normal u
// from j to i.
struct MeasuredContact {
    std::uint32_t i = 0;
    std::int64_t j = -1;
    glm::dvec3 u{0.0};
    double approachBefore = 0.0;  // m/s, relative normal velocity c before the passes
};

// Scratch of the measurement, in the workspace.
struct ImpactScratch {
    std::vector<glm::dvec3> velocityBefore;  // m/s
    std::vector<MeasuredContact> contacts;
    std::vector<std::uint32_t> cluster;      // per sphere, its cluster's root (union-find)
    std::vector<std::uint8_t> clusterFlags;  // per root: 1 touches a plane, 2 struck
    bool open = false;  // between beginMeasuringImpacts and endMeasuringImpacts
};

}  // namespace physics
