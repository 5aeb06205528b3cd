// Slide 7's third answer, continuous collision detection (physics.md, "Slide 7, the
// other two answers"): the numbers issue 17 asks of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/broad_phase.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "physics/time_of_impact.h"
#include "physics_fixtures.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

using glm::dvec3;
using physics::Method;

namespace {

constexpr double kG = 9.81;  // m/s^2

physics::Params continuous(double h, dvec3 gravity = {0, 0, -kG}) {
    physics::Params params = fixtures::exactParams(h, gravity);
    params.method = Method::Continuous;
    return params;
}

// m: the deepest overlap of two spheres or of a sphere and a plane (0: none).
double deepestOverlap(const physics::World& world) {
    physics::Workspace ws;
    physics::findPairsGrid(world, 0.0, ws);
    double deepest = 0.0;
    for (const physics::SpherePair& pair : ws.pairs) {
        const double reach = world.radius[pair.i] + world.radius[pair.j];
        deepest = std::max(deepest, reach - glm::distance(world.position[pair.i], world.position[pair.j]));
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (const physics::Plane& plane : world.planes) {
            const physics::Plane face = physics::faceFor(plane, world.position[i]);
            deepest = std::max(deepest, world.radius[i] - glm::dot(world.position[i] - face.point, face.normal));
        }
    }
    return deepest;
}

}  // namespace

// Every bounce happens at the instant of contact, so the apex after it is exactly
// beta^2 times the apex before, at any step and from any height (the step's impact
// instant differs for each of the sweep's heights).
TEST(Continuous, BounceApexRatioIsBetaSquaredAtAnyStep) {
    for (double h : {1.0 / 30.0, 1.0 / 60.0, 1.0 / 240.0}) {
        for (double beta : {0.5, 0.8, 1.0}) {
            double worst = 0.0;
            for (int k = 0; k < 25; ++k) {
                physics::Params params = continuous(h);
                params.beta = beta;
                physics::World world;
                fixtures::addBox(world, {4, 4, 4});
                world.addSphere({0, 0, 0.4 + 0.137 * k}, {0, 0, 0}, 0.1, 1.0);
                const double before = physics::modifiedEnergy(world, params) / kG - 0.1;  // m, apex over contact
                std::uint64_t events = 0;
                while (events == 0) events += physics::step(world, params).events;
                const double after = physics::modifiedEnergy(world, params) / kG - 0.1;
                worst = std::max(worst, std::abs(after / before / (beta * beta) - 1.0));
            }
            EXPECT_LE(worst, 1e-9) << "h=" << h << " beta=" << beta;
        }
    }
}

TEST(Continuous, HundredElasticBouncesKeepTheModifiedEnergy) {
    const physics::Params params = continuous(1.0 / 60.0);
    physics::World world;
    fixtures::addBox(world, {4, 4, 4});
    world.addSphere({0.1, -0.2, 1.3}, {0.4, 0.3, 0}, 0.1, 1.0);
    const double start = physics::modifiedEnergy(world, params);
    std::uint64_t events = 0;
    while (events < 100) events += physics::step(world, params).events;
    EXPECT_LE(std::abs(physics::modifiedEnergy(world, params) - start) / start, 1e-12);
}

TEST(Continuous, ElasticGasKeepsItsEnergyAndNeverOverlaps) {
    const physics::Params params = continuous(1.0 / 60.0, dvec3(0.0));
    physics::World world;
    fixtures::addBox(world, {1.0, 1.0, 1.0});
    fixtures::addRandomSpheres(world, 1000, 0.02, 0.02, 0.9, {0, 0, 0.5}, 1.0, 11);
    const double before = physics::measure(world, params).kinetic;
    std::uint64_t events = 0;
    double deepest = 0.0;
    for (int k = 0; k < 10000; ++k) {
        events += physics::step(world, params).events;
        deepest = std::max(deepest, deepestOverlap(world));
    }
    EXPECT_GT(events, 100000u);
    EXPECT_LE(std::abs(physics::measure(world, params).kinetic - before) / before, 1e-9);
    EXPECT_LE(deepest, 1e-9);
}

namespace {

// A random direction (unit) and a speed up to 100 m/s.
dvec3 shot(physics::Random& random) {
    dvec3 v(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    return v * (random.uniform(0, 100) / std::max(glm::length(v), 1e-9));
}

}  // namespace

// 10^4 spheres shot at up to 100 m/s at a wall 2 mm thick, one solver step of 1/30 s:
// a centre travels up to 3.3 m per step, yet every sphere is stopped at the near face.
TEST(Continuous, NoShotTunnelsThroughAThinWall) {
    physics::Random random(17);
    int crossed = 0, hits = 0;
    for (int shots = 0; shots < 10000; ++shots) {
        physics::Params params = continuous(1.0 / 30.0);
        params.beta = random.uniform(0.2, 1.0);
        params.alpha = random.uniform(0.2, 1.0);
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        world.planes.push_back({{0, 0, 1}, {1, 0, 0}, 0.002});
        const double r = random.uniform(0.005, 0.05);
        world.addSphere({random.uniform(-0.9, -0.06), random.uniform(-0.9, 0.9), random.uniform(0.06, 1.9)},
                        shot(random), r, 1.0);
        world.velocity[0].x = std::abs(world.velocity[0].x);  // towards the wall
        for (int k = 0; k < 15; ++k) {
            hits += int(physics::step(world, params).events > 0);
            crossed += int(world.position[0].x > 0.0);
        }
    }
    EXPECT_GT(hits, 10000);
    EXPECT_EQ(crossed, 0);
}

TEST(Continuous, NoShotLeavesTheBox) {
    physics::Random random(2024);
    std::size_t worstOutside = 0;
    for (int round = 0; round < 100; ++round) {  // 100 spheres a round: 10^4 shots
        physics::Params params = continuous(1.0 / 30.0);
        params.beta = random.uniform(0.2, 1.0);
        params.alpha = random.uniform(0.2, 1.0);
        params.epsilon = 0.1;
        physics::World world;
        fixtures::addBox(world, {1, 1, 1});
        fixtures::addRandomSpheres(world, 100, 0.01, 0.03, 0.9, {0, 0, 0.5}, 0.0, 100 + round);
        for (dvec3& v : world.velocity) v = shot(random);
        for (int k = 0; k < 30; ++k) {
            physics::step(world, params);
            worstOutside = std::max(worstOutside, physics::spheresOutsideBox(world, 0.0));
        }
    }
    EXPECT_EQ(worstOutside, 0u);
}

// With gaps between the spheres every impact is a two-sphere event at its own instant:
// the striker's velocity is handed down the row exactly.
TEST(Continuous, NewtonsCradleWithGapsHandsOnTheVelocityExactly) {
    for (auto model : {physics::ResponseModel::LectureAttenuation, physics::ResponseModel::MomentumConserving}) {
        physics::Params params = continuous(1.0 / 60.0, dvec3(0.0));
        params.response = model;
        physics::World world;
        for (int k = 0; k < 5; ++k) world.addSphere({0.3 * k, 0, 0}, {k == 0 ? 2.0 : 0.0, 0, 0}, 0.125, 1.0);
        for (int k = 0; k < 60; ++k) physics::step(world, params);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(world.velocity[k].x, 0.0, 1e-12) << k;
        EXPECT_NEAR(world.velocity[4].x, 2.0, 1e-12);
        // Each sphere stopped where it touched the next: 0.05 m short of the gap.
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(world.position[k].x, 0.3 * k + 0.05, 1e-12) << k;
    }
}

TEST(Continuous, HeadOnMassesOneAndThreeMatchTheClosedForm) {
    const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0;
    physics::Params params = continuous(1.0 / 30.0, dvec3(0.0));
    physics::World world;
    world.addSphere({-0.25, 0, 0}, {v1, 0, 0}, 0.1, m1);
    world.addSphere({0.25, 0, 0}, {v2, 0, 0}, 0.1, m2);
    for (int k = 0; k < 30; ++k) physics::step(world, params);
    EXPECT_NEAR(world.velocity[0].x, ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2), 1e-12);
    EXPECT_NEAR(world.velocity[1].x, ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2), 1e-12);
    // They met at t = 0.3 m / 3 m/s = 0.1 s, at x = -0.25 + 0.2 = -0.05 and 0.05.
    const double t = 1.0 - 0.1;  // s since the impact
    EXPECT_NEAR(world.position[0].x, -0.05 + t * world.velocity[0].x, 1e-12);
}

// The slide's binary search and the roots of the quadratic find the same instants,
// the search at the cost of about log2(h / tolerance) halvings each.
TEST(Continuous, BisectionFindsTheClosedFormsInstants) {
    physics::Random random(5);
    int found = 0;
    std::uint64_t iterations = 0;
    for (int k = 0; k < 10000; ++k) {
        const double h = 1.0 / 30.0;
        const bool plane = k % 2 == 0;
        const dvec3 p(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), random.uniform(0.05, 0.5));
        const dvec3 w = shot(random);
        const physics::Gap gap =
            plane ? physics::gapToPlane(p, w, 0.05, {0, 0, -kG}, physics::Plane{})
                  : physics::squaredGap(p, w, random.uniform(0.02, 0.2));
        const physics::Contact exact = physics::firstContact(gap, h, physics::TimeOfImpact::ClosedForm);
        const physics::Contact searched = physics::firstContact(gap, h, physics::TimeOfImpact::Bisection);
        ASSERT_EQ(exact.found, searched.found) << k;
        if (!exact.found || gap.c <= 0.0) continue;
        ++found;
        iterations += searched.iterations;
        EXPECT_LE(searched.iterations, 35u);  // ceil(log2(h / 1e-12 s)) at h = 1/30 s
        EXPECT_LE(std::abs(searched.time - exact.time), physics::kBisectionTolerance) << k;
        EXPECT_LE(exact.time, searched.time);  // the search ends inside: f <= 0 there
    }
    EXPECT_GT(found, 1000);
    // Most start from the whole step, h / 2^35 <= 1e-12 s; a few from a shorter interval
    // (two spheres that would pass closest before the step ends).
    EXPECT_GT(double(iterations) / found, 34.9);
}

// A sphere set down on the floor stays there: one static contact per step, pressed in
// by 1/2 g h^2 and projected out at the step's end, velocity 0.
TEST(Continuous, RestingSphereRestsWithOneStaticContactPerStep) {
    physics::Params params = continuous(1.0 / 60.0);
    params.epsilon = 0.1;
    params.mu = 0.5;
    physics::World world;
    fixtures::addBox(world, {2, 2, 2});
    world.addSphere({0, 0, 0.1}, {0.2, 0, 0}, 0.1, 1.0);
    physics::StepStats stats;
    for (int k = 0; k < 60; ++k) stats += physics::step(world, params);
    EXPECT_EQ(stats.events, 60u);
    EXPECT_EQ(stats.staticContacts, 60u);
    EXPECT_EQ(world.position[0].z, 0.1);
    EXPECT_LE(glm::length(world.velocity[0]), 1e-12);
}

// Every preset, switched to the continuous method, at its own alpha and beta and at
// two more pairs (0.5, 0.5 and 1, 1), for 2 s each (without its emitter, which brings
// energy in): the modified energy never rises, and no step reaches the cap.
TEST(Continuous, NoPresetCreatesEnergyForAnyAlphaAndBetaUpToOne) {
    for (const std::string& name : scenes::listPresets()) {
        for (const std::vector<std::string>& restitution :
             {std::vector<std::string>{}, {"alpha=0.5", "beta=0.5"}, {"alpha=1", "beta=1"}}) {
            scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
            ASSERT_EQ(scenes::applySetting(scene, "method=continuous"), "");
            for (const std::string& setting : restitution) ASSERT_EQ(scenes::applySetting(scene, setting), "");
            const physics::Params& params = scene.params;
            if (params.alpha > 1.0 || params.beta > 1.0 || params.mu > 1.0) continue;
            physics::World world = scenes::buildWorld(scene);
            const double start = physics::modifiedEnergy(world, params);
            physics::StepStats stats;
            for (double t = 0.0; t < 2.0; t += params.timeStep) stats += physics::step(world, params);
            const double end = physics::modifiedEnergy(world, params);
            EXPECT_LE(end, start + 1e-9 * std::abs(start)) << name << " alpha " << params.alpha;
            EXPECT_EQ(stats.cappedSteps, 0u) << name << " alpha " << params.alpha;
        }
    }
}

// The same holds in a run: from one state of a gas under gravity, a step with each finder
// meets the same impacts, in the same order, at the same instants but for the
// bisection's tolerance carried down a chain of impacts (each later impact inherits the
// paths of the earlier ones): 5.6e-13 s apart at the median, 1.7e-10 s at most over the
// 6 296 impacts of 20 steps (measured).
TEST(Continuous, BisectionMeetsEveryImpactOfAStepWhereTheRootsDo) {
    physics::Params params = continuous(1.0 / 30.0);
    params.epsilon = 0.05;
    physics::World start;
    fixtures::addBox(start, {1.0, 1.0, 1.0});
    fixtures::addRandomSpheres(start, 400, 0.02, 0.04, 0.9, {0, 0, 0.5}, 3.0, 23);
    start.recordContacts = true;
    for (int k = 0; k < 30; ++k) physics::step(start, params);  // some resting on the floor
    std::vector<double> apart;  // s
    for (int k = 0; k < 20; ++k) {
        physics::World exact = start, searched = start;
        params.timeOfImpact = physics::TimeOfImpact::ClosedForm;
        physics::step(exact, params);
        params.timeOfImpact = physics::TimeOfImpact::Bisection;
        const physics::StepStats stats = physics::step(searched, params);
        ASSERT_EQ(exact.contacts.size(), searched.contacts.size()) << "step " << k;
        for (std::size_t e = 0; e < exact.contacts.size(); ++e) {
            const physics::ContactEvent &a = exact.contacts[e], &b = searched.contacts[e];
            ASSERT_EQ(a.i, b.i);
            ASSERT_EQ(a.other, b.other);
            apart.push_back(std::abs(a.timeOfImpact - b.timeOfImpact));
        }
        EXPECT_GT(stats.toiIterations, 0u);
        params.timeOfImpact = physics::TimeOfImpact::ClosedForm;
        physics::step(start, params);
    }
    ASSERT_GT(apart.size(), 500u);
    std::sort(apart.begin(), apart.end());
    std::printf("%zu impacts: median %.2g s, largest %.2g s apart\n", apart.size(), apart[apart.size() / 2],
                apart.back());
    EXPECT_LE(apart[apart.size() / 2], 2 * physics::kBisectionTolerance);
    EXPECT_LE(apart.back(), 1e-9);
}

// The max_events tooltip: with epsilon = 0 a sphere resting on the floor keeps bouncing
// in place (each flight beta times the last, never a static contact), and many of its
// solver steps reach the cap (default parameters otherwise: h = 1/60 s, 4 substeps).
// Measured over 1 s: 40 % of the solver steps at beta = 0.8, 50 % at 0.5, none at 1.
TEST(Continuous, ASphereBouncingInPlaceWithEpsilonZeroReachesTheCapInManySteps) {
    const auto cappedShare = [](double beta) {
        physics::Params params;
        params.method = Method::Continuous;
        params.epsilon = 0.0;
        params.beta = beta;
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        world.addSphere({0, 0, 0.1}, {0, 0, 0}, 0.1, 1.0);
        physics::StepStats stats;
        for (int k = 0; k < 60; ++k) stats += physics::step(world, params);
        return double(stats.cappedSteps) / (60.0 * params.substeps);
    };
    EXPECT_NEAR(cappedShare(0.8), 0.40, 0.01);
    EXPECT_NEAR(cappedShare(0.5), 0.50, 0.01);
    EXPECT_EQ(cappedShare(1.0), 0.0);
}
