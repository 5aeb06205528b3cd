// Smith et al.'s generalized reflections on 10^4 random touching clusters: the properties
// they prove (physics.md, "Slide 14, the global approach"), asserted on each cluster.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/random.h"
#include "physics/step.h"
#include "physics_fixtures.h"

using glm::dvec3;

namespace {

constexpr int kClusters = 10000;

// m/s: the approach a contact may keep. The rounds stop once none approaches faster than
// kConvergedApproachSpeed; the velocity method's stage C then cancels what is left, one
// contact after another, and may leave a neighbour up to about that much again.
constexpr double kLeftApproach = 2.0 * physics::kConvergedApproachSpeed;

// m: how much each new sphere overlaps the one it is placed on, so that the contact is
// found whatever the rounding (a contact touches at |p1 - p2| <= r1 + r2).
constexpr double kOverlap = 1e-9;

dvec3 randomDirection(physics::Random& random) {
    for (;;) {
        const dvec3 d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        const double length = glm::length(d);
        if (length > 0.1 && length <= 1.0) return d / length;
    }
}

bool fits(const physics::World& world, const dvec3& p, double r, std::size_t except) {
    for (std::size_t k = 0; k < world.size(); ++k) {
        if (k == except) continue;
        if (glm::length(world.position[k] - p) < world.radius[k] + r) return false;
    }
    return true;
}

// A tree of `count` touching spheres: each new one placed against a random earlier one,
// where it overlaps no other; radii 0.05-0.15 m, masses 0.1-10 kg, velocities up to 2 m/s
// per axis. With `mirrored`, half of them on x > 0 and their mirror images in x = 0
// (the first touches its own image), velocities mirrored too.
physics::World randomCluster(physics::Random& random, int count, bool mirrored) {
    physics::World world;
    const int built = mirrored ? count / 2 : count;
    for (int k = 0; k < built; ++k) {
        const double r = random.uniform(0.05, 0.15);  // m
        const double m = std::exp(random.uniform(std::log(0.1), std::log(10.0)));  // kg
        const dvec3 v(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));  // m/s
        if (k == 0) {
            world.addSphere({mirrored ? r - kOverlap / 2 : 0.0, 0, 0}, v, r, m);
            continue;
        }
        for (;;) {
            const std::size_t on = std::size_t(random.below(std::uint64_t(k)));
            const dvec3 p = world.position[on] + (world.radius[on] + r - kOverlap) * randomDirection(random);
            const dvec3 image(-p.x, p.y, p.z);
            if (mirrored && (p.x < r || glm::length(p - image) < 2 * r)) continue;
            if (!fits(world, p, r, on)) continue;
            if (mirrored && !fits(world, image, r, world.size())) continue;
            world.addSphere(p, v, r, m);
            break;
        }
    }
    if (mirrored) {
        for (int k = 0; k < built; ++k) {
            const dvec3 p = world.position[k], v = world.velocity[k];
            world.addSphere({-p.x, p.y, p.z}, {-v.x, v.y, v.z}, world.radius[k], world.mass[k]);
        }
    }
    return world;
}

dvec3 momentum(const physics::World& world) {
    dvec3 sum(0.0);  // kg m/s
    for (std::size_t i = 0; i < world.size(); ++i) sum += world.mass[i] * world.velocity[i];
    return sum;
}

double momentumScale(const physics::World& world) {
    double sum = 0.0;  // kg m/s
    for (std::size_t i = 0; i < world.size(); ++i) sum += world.mass[i] * glm::length(world.velocity[i]);
    return sum;
}

double kinetic(const physics::World& world) {
    double sum = 0.0;  // J
    for (std::size_t i = 0; i < world.size(); ++i) sum += 0.5 * world.mass[i] * glm::dot(world.velocity[i], world.velocity[i]);
    return sum;
}

// m/s: the fastest approach left between spheres that touched at `before` (the contacts
// the step solved, with their normals then), 0 when none approaches.
double fastestApproach(const physics::World& world, const physics::World& before) {
    double fastest = 0.0;
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (std::size_t j = i + 1; j < world.size(); ++j) {
            const dvec3 d = before.position[i] - before.position[j];
            if (glm::length(d) > world.radius[i] + world.radius[j]) continue;
            fastest = std::max(fastest, -glm::dot(world.velocity[i] - world.velocity[j], glm::normalize(d)));
        }
    }
    return fastest;
}

// m/s: how far sphere k's velocity is from the mirror image of its partner's (the second
// half mirrors the first).
double mirrorError(const physics::World& world) {
    const std::size_t half = world.size() / 2;
    double worst = 0.0;
    for (std::size_t k = 0; k < half; ++k) {
        const dvec3 v = world.velocity[k], image = world.velocity[k + half];
        worst = std::max(worst, glm::length(v - dvec3(-image.x, image.y, image.z)));
    }
    return worst;
}

// The velocity method: the contacts are found before the spheres move, and nothing else
// changes the velocities (no gravity, no walls, alpha = mu = 1).
physics::Params reflections(double beta) {
    physics::Params params = fixtures::exactParams(1e-6, dvec3(0.0));
    params.method = physics::Method::VelocityBased;
    params.solver = physics::Solver::GeneralizedReflections;
    params.beta = beta;
    params.passes = 1;
    return params;
}

// Every cluster of one test: its input from `make`, its beta from `betaOf`, and after one
// step momentum to 1e-12 (relative), kinetic energy kept to 1e-12 at beta = 1 and never
// more below, nothing approaching, no cap reached, and `check`. Prints the most rounds.
template <class Make, class Beta, class Check>
void forEveryCluster(std::uint64_t seed, const Make& make, const Beta& betaOf, const Check& check) {
    physics::Random random(seed);
    std::uint64_t worstRounds = 0;
    for (int n = 0; n < kClusters; ++n) {
        SCOPED_TRACE("cluster " + std::to_string(n));
        physics::World world = make(random);
        const physics::World before = world;
        const double beta = betaOf(random);
        const dvec3 p0 = momentum(world);
        const double scale = momentumScale(world), e0 = kinetic(world);
        const physics::StepStats stats = physics::step(world, reflections(beta));
        ASSERT_LE(glm::length(momentum(world) - p0), 1e-12 * scale);
        ASSERT_LE(kinetic(world), e0 * (1.0 + 1e-12));
        if (beta == 1.0) {
            ASSERT_NEAR(kinetic(world), e0, 1e-12 * e0);
        }
        ASSERT_LE(fastestApproach(world, before), kLeftApproach);
        ASSERT_EQ(stats.reflectionCapHits, 0u);
        check(world, beta);
        worstRounds = std::max(worstRounds, stats.reflectionRounds);
    }
    std::printf("most rounds in a cluster: %llu\n", static_cast<unsigned long long>(worstRounds));
}

physics::World anyCluster(physics::Random& random) { return randomCluster(random, 3 + int(random.below(6)), false); }

void nothingMore(const physics::World&, double) {}

}  // namespace

// Elastic, 10^4 clusters of 3-8 spheres: the most rounds any took is printed, measured 17.
TEST(GeneralizedReflections, RandomClustersKeepMomentumAndEnergyAndPart) {
    forEveryCluster(2012, anyCluster, [](physics::Random&) { return 1.0; }, nothingMore);
}

// beta in [0, 1): the generalized restitution never adds energy; 320 rounds at most.
TEST(GeneralizedReflections, RandomClustersNeverGainEnergyBelowBetaOne) {
    forEveryCluster(2013, anyCluster, [](physics::Random& random) { return random.uniform(); }, nothingMore);
}

// Mirror-symmetric clusters (4-8 spheres: 2-4 and their images in x = 0), elastic and not:
// the answer is mirror-symmetric to 1e-9 m/s; measured 1322 rounds at most (beta = 0.003:
// the blended answer is nearly inelastic, and the rounds pass an approach back and forth
// between neighbouring contacts, shrinking it by a little each time).
TEST(GeneralizedReflections, MirrorSymmetricClustersStaySymmetric) {
    int n = 0;
    forEveryCluster(
        2017,
        [](physics::Random& random) {
            physics::World world = randomCluster(random, 4 + 2 * int(random.below(3)), true);
            EXPECT_LE(mirrorError(world), 1e-15);
            return world;
        },
        [&n](physics::Random& random) { return n++ % 2 == 0 ? 1.0 : random.uniform(); },
        [](const physics::World& world, double beta) { ASSERT_LE(mirrorError(world), 1e-9) << "beta " << beta; });
}
