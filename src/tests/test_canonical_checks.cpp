// The "Canonical checks" table of shared/guides/physics.md, one test (or a few) per row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/step.h"
#include "physics_fixtures.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

using glm::dvec3;
using physics::Method;

namespace {

const Method kMethods[] = {Method::PositionBased, Method::VelocityBased};
// The checks that do not depend on the order run in the lecture's index order and in the
// colored order (not the lecture's: colored_order.cpp), which must pass them too.
const physics::PairOrder kOrders[] = {physics::PairOrder::Index, physics::PairOrder::Colored};

// Every method of kMethods in every order of kOrders.
std::vector<std::pair<Method, physics::PairOrder>> methodsAndOrders() {
    std::vector<std::pair<Method, physics::PairOrder>> all;
    for (Method method : kMethods) {
        for (physics::PairOrder order : kOrders) all.emplace_back(method, order);
    }
    return all;
}

void run(physics::World& world, const physics::Params& params, int steps) {
    for (int k = 0; k < steps; ++k) physics::step(world, params);
}

// Two spheres of radius 0.1 m on the x axis, 0.5 m apart, heading at each other.
physics::World headOn(double m1, double m2, double v1, double v2) {
    physics::World world;
    world.addSphere({-0.25, 0, 0}, {v1, 0, 0}, 0.1, m1);
    world.addSphere({0.25, 0, 0}, {v2, 0, 0}, 0.1, m2);
    return world;
}

}  // namespace

TEST(CanonicalChecks, FreeFlightConservesModifiedEnergyAndFollowsTheDiscretePath) {
    const double h = 1.0 / 60.0;
    const physics::Params params = fixtures::exactParams(h);
    physics::World world;
    const dvec3 p0(0.3, -0.2, 1.0), v0(1.5, 0.5, 7.0);
    world.addSphere(p0, v0, 0.1, 2.0);
    const double e0 = physics::modifiedEnergy(world, params);
    const int steps = 600;  // 10 s
    run(world, params, steps);
    const double t = steps * h;
    const dvec3 expected = p0 + (v0 + 0.5 * h * params.gravity) * t + 0.5 * params.gravity * t * t;
    EXPECT_LE(std::abs(physics::modifiedEnergy(world, params) - e0) / std::abs(e0), 1e-12);
    EXPECT_LE(glm::distance(world.position[0], expected), 1e-9);
}

TEST(CanonicalChecks, HeadOnEqualMassesExchangeVelocities) {
    for (Method method : kMethods) {
        for (auto model : {physics::ResponseModel::LectureAttenuation,
                           physics::ResponseModel::MomentumConserving}) {
            physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
            params.method = method;
            params.response = model;
            physics::World world = headOn(1.0, 1.0, 1.5, -0.5);
            run(world, params, 240);
            EXPECT_NEAR(world.velocity[0].x, -0.5, 1e-12);
            EXPECT_NEAR(world.velocity[1].x, 1.5, 1e-12);
            EXPECT_EQ(world.velocity[0].y, 0.0);
        }
    }
}

TEST(CanonicalChecks, HeadOnMassesOneAndThreeMatchTheClosedForm) {
    const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0;
    const double v1After = ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2);
    const double v2After = ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2);
    for (Method method : kMethods) {
        for (auto model : {physics::ResponseModel::LectureAttenuation,
                           physics::ResponseModel::MomentumConserving}) {
            physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
            params.method = method;
            params.response = model;
            physics::World world = headOn(m1, m2, v1, v2);
            run(world, params, 240);
            EXPECT_NEAR(world.velocity[0].x, v1After, 1e-12);
            EXPECT_NEAR(world.velocity[1].x, v2After, 1e-12);
        }
    }
}

TEST(CanonicalChecks, MomentumConservingModeKeepsMomentumForAnyAlphaBeta) {
    for (const auto& [method, order] : methodsAndOrders()) {
        for (double alpha : {0.0, 0.4, 1.0}) {
            physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
            params.method = method;
            params.order = order;
            params.response = physics::ResponseModel::MomentumConserving;
            params.alpha = alpha;
            params.beta = 0.5;
            params.epsilon = 0.05;  // some contacts are static: their friction must conserve too
            params.mu = 0.7;
            physics::World world;
            fixtures::addRandomSpheres(world, 200, 0.02, 0.08, 1.0, dvec3(0.0), 1.0, 42);
            double scale = 0.0;  // kg m/s, the size of the momenta involved
            for (std::size_t i = 0; i < world.size(); ++i) scale += world.mass[i] * glm::length(world.velocity[i]);
            const dvec3 before = physics::measure(world, params).momentum;
            std::uint64_t collisions = 0;
            for (int k = 0; k < 10000; ++k) collisions += physics::step(world, params).collisions;
            EXPECT_GT(collisions, 100u);
            EXPECT_LE(glm::length(physics::measure(world, params).momentum - before) / scale, 1e-12);
        }
    }
}

TEST(CanonicalChecks, ElasticGasInABoxKeepsItsKineticEnergy) {
    for (const auto& [method, order] : methodsAndOrders()) {
        physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
        params.method = method;
        params.order = order;
        physics::World world;
        fixtures::addBox(world, {1.0, 1.0, 1.0});
        fixtures::addRandomSpheres(world, 150, 0.03, 0.03, 0.8, {0, 0, 0.5}, 2.0, 7);
        const double before = physics::measure(world, params).kinetic;
        std::uint64_t collisions = 0;
        for (int k = 0; k < 10000; ++k) collisions += physics::step(world, params).collisions;
        EXPECT_GT(collisions, 10000u);
        EXPECT_LE(std::abs(physics::measure(world, params).kinetic - before) / before, 1e-9);
    }
}

// The flaw the README states: without static friction (mu = 1) the position method's
// projection can lift a stack within a step, so E~ rises in a step: the column of 09 gains
// up to 0.070 J (0.11 % of E~) in one step, in 481 of 1200 steps, and loses 0.37 J over
// them (measured); at mu = 0.98 up to 0.040 J in 597 steps. At mu = 0.97 and below it never
// rises there (as the test below asserts at 0.5 for a heap); a taller column at one pass
// is lifted from a lower mu.
TEST(CanonicalChecks, PositionBasedCanGainWithinAStepWithoutStaticFriction) {
    struct Rises {
        int steps = 0;
        double most = 0.0;  // J, in one step
        double lost = 0.0;  // J, over the run
    };
    const auto rises = [](const char* preset, std::initializer_list<const char*> settings) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath(preset));
        for (const char* setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "");
        physics::World world = scenes::buildWorld(scene);
        const double start = physics::modifiedEnergy(world, scene.params);
        double previous = start;  // J
        Rises r;
        for (int k = 0; k < 1200; ++k) {
            physics::step(world, scene.params);
            const double now = physics::modifiedEnergy(world, scene.params);
            if (now > previous + 1e-9 * std::abs(start)) {
                ++r.steps;
                r.most = std::max(r.most, now - previous);
            }
            previous = now;
        }
        r.lost = start - previous;
        return r;
    };
    const Rises one = rises("09_column", {"mu=1"}), high = rises("09_column", {"mu=0.98"}), below = rises("09_column", {"mu=0.97"});
    EXPECT_NEAR(one.most, 0.0704, 0.002);
    EXPECT_NEAR(one.steps, 481, 40);
    EXPECT_NEAR(one.lost, 0.37, 0.02);
    EXPECT_NEAR(high.most, 0.0398, 0.002);
    EXPECT_EQ(below.steps, 0);
    // 21's column of 20 at one pass (K = 1) is lifted from mu = 0.87 (0.052 J), and up to
    // 0.19 J in a step at 0.97; never at 0.86.
    EXPECT_NEAR(rises("21_shock_column", {"mu=0.87"}).most, 0.052, 0.003);
    EXPECT_NEAR(rises("21_shock_column", {"mu=0.97"}).most, 0.190, 0.005);
    EXPECT_EQ(rises("21_shock_column", {"mu=0.86"}).steps, 0);
    // At mu = 0.5 a run loses, and a step gains only while a pile first settles: 10's
    // pyramid switched to position based (as its text invites) gains up to 4.2e-7 J in a
    // step in its first 0.2 s (4e-9 of its energy; 2 steps above 1e-9 of it, 7 above 0);
    // 09's column never.
    const Rises pyramid = rises("10_pyramid", {"mu=0.5", "method=position"});
    EXPECT_NEAR(pyramid.most, 4.2e-7, 0.2e-7);
    EXPECT_EQ(pyramid.steps, 2);
    EXPECT_GT(pyramid.lost, 0.0);
    EXPECT_EQ(rises("09_column", {"mu=0.5"}).steps, 0);
}

// Position based: E~ never rises, not even within one step (the projection pays
// for the reflected half-step velocity). Velocity based: E~ may rise within a step by
// O(m |v| |g| h) when a rising sphere is turned down, but never over a run.
TEST(CanonicalChecks, EnergyIsNeverCreatedWhenAlphaAndBetaAreAtMostOne) {
    for (const auto& [method, order] : methodsAndOrders()) {
        for (double beta : {0.3, 0.8, 1.0}) {
            physics::Params params;
            params.method = method;
            params.order = order;
            params.beta = beta;
            params.alpha = 0.9;
            physics::World world;
            fixtures::addBox(world, {1.0, 1.0, 2.0});
            fixtures::addRandomSpheres(world, 300, 0.03, 0.06, 0.9, {0, 0, 1.0}, 1.0, 3);
            const double start = physics::modifiedEnergy(world, params);
            const double slack = 1e-9 * std::abs(start);
            double previous = start;
            for (int k = 0; k < 600; ++k) {
                physics::step(world, params);
                const double now = physics::modifiedEnergy(world, params);
                if (method == Method::PositionBased) {
                    ASSERT_LE(now, previous + slack) << "step " << k;
                }
                previous = now;
            }
            EXPECT_LE(previous, start + slack);
            EXPECT_LT(previous, 0.7 * start);  // and the collisions did dissipate
        }
    }
}
