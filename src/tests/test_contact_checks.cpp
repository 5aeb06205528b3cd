// The remaining rows of the canonical checks: resting contact (slide 13), Newton's
// cradle and pair order (slide 14), shots at the walls, broad phase, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "physics/broad_phase.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "physics_fixtures.h"

using glm::dvec3;
using physics::Method;

namespace {

const Method kAllMethods[] = {Method::PositionBased, Method::VelocityBased, Method::ResponseOnly};

void run(physics::World& world, const physics::Params& params, int steps) {
    for (int k = 0; k < steps; ++k) physics::step(world, params);
}

// n spheres of radii in [0.01, 0.04] m placed anywhere in a cube, overlaps allowed.
physics::World scattered(std::size_t n, double extent, std::uint64_t seed) {
    physics::Random random(seed);
    physics::World world;
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3 p(random.uniform(), random.uniform(), random.uniform());
        world.addSphere(extent * p, {0, 0, 0}, random.uniform(0.01, 0.04), 1.0);
    }
    world.addSphere({50, -30, 7}, {0, 0, 0}, 0.02, 1.0);  // one far away stretches the grid
    return world;
}

}  // namespace

TEST(ContactChecks, RestingSphereStopsWithoutSinking) {
    for (Method method : {Method::PositionBased, Method::VelocityBased}) {
        physics::Params params = fixtures::exactParams(1.0 / 60.0);
        params.method = method;
        params.epsilon = 2 * 9.81 * params.solverStep();
        params.mu = 0.9;
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        world.addSphere({0, 0, 0.1}, {0.3, 0.2, 0}, 0.1, 1.0);  // sliding on the floor
        run(world, params, 300);  // 5 s
        const physics::Diagnostics d = physics::measure(world, params);
        EXPECT_LE(glm::length(world.velocity[0]), 1e-3);
        EXPECT_LE(d.maxPenetration, 0.01);
        EXPECT_EQ(world.contactState[0], physics::ContactState::Static);
    }
}

TEST(ContactChecks, EpsilonBelowOneGravityStepCannotCatchARestingSphere) {
    // Resting on the floor, each step meets the floor at (1 - beta) g h + beta * (the
    // last rebound): the rebound settles at beta g h / (1 + beta) and never drops below
    // epsilon = g h / 2, so the sphere keeps bouncing in place: "a resting ball keeps shaking".
    physics::Params params = fixtures::exactParams(1.0 / 60.0);
    const double gh = 9.81 * params.solverStep();  // m/s
    params.epsilon = 0.5 * gh;
    params.beta = 0.2;
    physics::World world;
    fixtures::addBox(world, {2, 2, 2});
    world.addSphere({0, 0, 0.1}, {0, 0, 0}, 0.1, 1.0);
    run(world, params, 300);
    EXPECT_EQ(world.contactState[0], physics::ContactState::Colliding);
    EXPECT_NEAR(world.velocity[0].z, params.beta * gh / (1 + params.beta), 1e-9);
}

TEST(ContactChecks, NewtonsCradleInIndexOrderTakesOnePass) {
    const double v0 = 2.0;
    for (Method method : {Method::PositionBased, Method::VelocityBased}) {
        physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
        params.method = method;
        params.passes = 1;
        physics::World world = fixtures::cradle(v0);
        physics::step(world, params);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(world.velocity[k].x, 0.0, 1e-6 * v0) << k;
        EXPECT_NEAR(world.velocity[4].x, v0, 1e-6 * v0);
        run(world, params, 100);  // and nothing else happens afterwards
        EXPECT_NEAR(world.velocity[4].x, v0, 1e-6 * v0);
        EXPECT_NEAR(world.velocity[0].x, 0.0, 1e-6 * v0);
    }
}

// Reversed order meets the moving sphere's pair last: each pass carries the
// velocity one sphere further, so four contacts need four passes in one step.
TEST(ContactChecks, NewtonsCradleInReversedOrderNeedsOnePassPerContact) {
    const double v0 = 2.0;
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = physics::PairOrder::Reversed;
    for (int passes = 1; passes <= 4; ++passes) {
        params.passes = passes;
        physics::World world = fixtures::cradle(v0);
        physics::step(world, params);
        for (int k = 0; k < 5; ++k) {
            EXPECT_NEAR(world.velocity[k].x, k == passes ? v0 : 0.0, 1e-6 * v0) << passes << " " << k;
        }
    }
}

TEST(ContactChecks, NoSphereLeavesTheBoxUnderTenThousandShots) {
    physics::Random random(2024);
    std::size_t worstOutside = 0;
    for (int round = 0; round < 10; ++round) {
        physics::Params params;
        params.substeps = 1;
        params.beta = random.uniform(0.2, 1.0);
        params.alpha = random.uniform(0.2, 1.0);
        physics::World world;
        fixtures::addBox(world, {1, 1, 1});
        fixtures::addRandomSpheres(world, 1000, 0.01, 0.03, 0.9, {0, 0, 0.5}, 0.0, 100 + round);
        for (glm::dvec3& v : world.velocity) {  // up to 100 m/s in any direction
            v = glm::dvec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
            v *= random.uniform(0, 100) / std::max(glm::length(v), 1e-9);
        }
        for (int k = 0; k < 120; ++k) {
            physics::step(world, params);
            worstOutside = std::max(worstOutside, physics::spheresOutsideBox(world, 0.0));
        }
    }
    EXPECT_EQ(worstOutside, 0u);
}

TEST(ContactChecks, GridFindsExactlyThePairsOfTheAllPairsLoop) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const double extent = 0.5 * static_cast<double>(seed);  // from dense to sparse
        const physics::World world = scattered(500 * seed, extent, seed);
        for (const auto& [margin, threads] : {std::pair{0.0, 1}, std::pair{0.004, 1}, std::pair{0.004, 3}}) {
            physics::Workspace grid;
            std::vector<physics::SpherePair> reference;
            physics::findPairsGrid(world, margin, grid, threads);
            physics::findPairsAllPairs(world, margin, reference);
            ASSERT_EQ(grid.pairs.size(), reference.size()) << "seed " << seed << ", threads " << threads;
            EXPECT_GT(reference.size(), 0u);
            for (std::size_t k = 0; k < reference.size(); ++k) {
                ASSERT_EQ(grid.pairs[k].i, reference[k].i);
                ASSERT_EQ(grid.pairs[k].j, reference[k].j);
            }
        }
    }
}

TEST(ContactChecks, SameSceneAndSeedGiveTheSameStateHash) {
    for (Method method : kAllMethods) {
        physics::Params params;
        params.method = method;
        params.order = physics::PairOrder::Shuffled;
        auto make = [](std::uint64_t seed) {
            physics::World world;
            fixtures::addBox(world, {1, 1, 1});
            fixtures::addRandomSpheres(world, 300, 0.02, 0.05, 0.9, {0, 0, 0.5}, 1.0, 11);
            world.seed = seed;
            return world;
        };
        physics::World a = make(5), b = make(5), c = make(6);
        run(a, params, 300);
        run(b, params, 300);
        run(c, params, 300);
        EXPECT_EQ(physics::stateHash(a), physics::stateHash(b));
        EXPECT_NE(physics::stateHash(a), physics::stateHash(c));  // the shuffle follows the seed
    }
}

TEST(ContactChecks, RecordedContactsCarryTheSlidesNumbers) {
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    physics::World world;
    fixtures::addBox(world, {4, 4, 4});
    world.addSphere({-0.25, 0, 1}, {1.5, 0, 0}, 0.1, 1.0);
    world.addSphere({0.25, 0, 1}, {-0.5, 0, 0}, 0.1, 3.0);
    world.recordContacts = true;
    std::vector<physics::ContactEvent> events;
    for (int k = 0; k < 120 && events.empty(); ++k) {
        physics::step(world, params);
        events = world.contacts;
    }
    ASSERT_EQ(events.size(), 1u);  // one bounce, handled in the first pass
    const physics::ContactEvent& e = events[0];
    EXPECT_EQ(e.i, 0u);
    EXPECT_EQ(e.other, 1);
    EXPECT_TRUE(e.bounce);
    EXPECT_NEAR(e.normal.x, -1.0, 1e-12);  // u points from sphere 1 to sphere 0
    // Elastic, masses 1 and 3: sphere 0 leaves at ((1-3) 1.5 + 2 * 3 * (-0.5)) / 4 = -1.5 m/s.
    EXPECT_NEAR(e.velocityAfter[0].x, -1.5, 1e-12);
    EXPECT_NEAR(e.impulse().x, -3.0, 1e-12);  // m (v after - v before) = 1 * (-1.5 - 1.5)
    EXPECT_NEAR(e.massOf[1] * (e.velocityAfter[1].x - e.velocityBefore[1].x), 3.0, 1e-12);

    // A sphere falling on the floor: the event names plane 0 and its normal.
    physics::World drop;
    fixtures::addBox(drop, {2, 2, 2});
    drop.addSphere({0, 0, 0.105}, {0, 0, -1}, 0.1, 2.0);
    drop.recordContacts = true;
    physics::step(drop, fixtures::exactParams(1.0 / 60.0));
    ASSERT_EQ(drop.contacts.size(), 1u);
    EXPECT_EQ(drop.contacts[0].other, -1);  // -1 - plane 0
    EXPECT_TRUE(drop.contacts[0].isPlane());
    EXPECT_EQ(drop.contacts[0].normal.z, 1.0);
    EXPECT_GT(drop.contacts[0].impulse().z, 0.0);
    drop.recordContacts = false;
    physics::step(drop, fixtures::exactParams(1.0 / 60.0));
    EXPECT_TRUE(drop.contacts.empty());
}

// A thin wall (thickness 1 cm) across a box; a small sphere shot at 30 m/s. At
// h = 1/60 s its centre jumps 0.5 m, past the wall's middle, and it comes out on the
// far side: tunnelling. At h = 1/1000 s it is caught on the near face and bounces back.
TEST(ContactChecks, ThinWallIsTunnelledAtALargeStepOnly) {
    auto finalX = [](double h) {
        physics::Params params = fixtures::exactParams(h, dvec3(0.0));
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        world.planes.push_back({{0, 0, 0}, {1, 0, 0}, 0.01});
        world.addSphere({-0.3, 0, 1}, {30, 0, 0}, 0.02, 1.0);
        for (int k = 0; k * h < 0.02; ++k) physics::step(world, params);  // 20 ms of flight
        return world.position[0].x;
    };
    EXPECT_GT(finalX(1.0 / 60.0), 0.0);   // crossed the wall
    EXPECT_LT(finalX(1.0 / 1000.0), 0.0); // bounced off it
}

// The position based wall stage passes by the spheres whose wall clearance is above 0.
// A sphere clear of the floor, pushed into it by the pair stage of the same pass, must
// still be projected: each push lowers its clearance.
TEST(ContactChecks, WallStageProjectsASpherePushedIntoTheWallInTheSamePass) {
    for (const double thickness : {0.0, 0.02}) {
        physics::Params params = fixtures::exactParams(1.0 / 60.0, dvec3(0.0));
        params.passes = 1;
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        const double floor = 0.5 * thickness;  // m, the floor's face
        if (thickness > 0.0) world.planes.push_back({{0, 0, 1}, {0, 0, 1}, thickness});
        const dvec3 lift(0, 0, thickness > 0.0 ? 1.0 : 0.0);  // above the thin wall
        const double r = 0.1, gap = 0.01, overlap = 0.05;  // m
        world.addSphere(lift + dvec3(0, 0, floor + r + gap), {0, 0, 0}, r, 1.0);
        world.addSphere(lift + dvec3(0, 0, floor + 3 * r + gap - overlap), {0, 0, 0}, r, 1.0);
        physics::step(world, params);  // pushed down by overlap / 2 > gap
        EXPECT_GE(world.position[0].z - lift.z, floor + r - 1e-12) << "thickness " << thickness;
    }
}

TEST(ContactChecks, ThinWallFaceIsOnTheSideOfTheCentre) {
    const physics::Plane wall{{0, 0, 0}, {1, 0, 0}, 0.02};
    const physics::Plane front = physics::faceFor(wall, {-0.5, 0, 0});
    const physics::Plane back = physics::faceFor(wall, {0.5, 0, 0});
    EXPECT_EQ(front.normal.x, -1.0);
    EXPECT_NEAR(front.point.x, -0.01, 1e-15);
    EXPECT_EQ(back.normal.x, 1.0);
    EXPECT_NEAR(back.point.x, 0.01, 1e-15);
    const physics::Plane halfSpace{{0, 0, 0}, {1, 0, 0}, 0.0};
    EXPECT_EQ(physics::faceFor(halfSpace, {-0.5, 0, 0}).normal.x, 1.0);  // one-sided: unchanged
}

// A blown-up state must not hang or throw in the broad phase: the app reports it.
TEST(ContactChecks, NonFiniteSpheresMeetNothingAndTheGridStillWorks) {
    physics::World world = scattered(300, 0.5, 9);
    world.position[3] = dvec3(NAN, 0, 0);
    world.position[7] = dvec3(INFINITY, 1, 2);
    world.position[8] = dvec3(-INFINITY, 0, NAN);
    physics::Workspace grid;
    std::vector<physics::SpherePair> reference;
    physics::findPairsGrid(world, 0.0, grid);
    physics::findPairsAllPairs(world, 0.0, reference);
    ASSERT_EQ(grid.pairs.size(), reference.size());
    EXPECT_GT(reference.size(), 0u);
    for (const physics::SpherePair& pair : grid.pairs) {
        EXPECT_TRUE(pair.i != 3 && pair.j != 3 && pair.i != 7 && pair.j != 7 && pair.i != 8 && pair.j != 8);
    }
    physics::Params params;
    physics::step(world, params);  // returns: no hang, no throw
    EXPECT_TRUE(std::isnan(world.position[3].x));
}

// The readouts' momentum: a symmetric answer's rounding (0.1 + 0.2 against 0.3: 5.55e-17
// kg m/s) reads 0, where a student read "|p| 5.551e-17" as momentum not kept; a momentum
// a property check could tell (1e-9 of sum m |v|) is shown as it is.
TEST(ContactChecks, TheMomentumShownReadsRoundingAsZero) {
    physics::World world;
    world.addSphere({-1, 0, 0}, {0.1 + 0.2, 0, 2.0}, 0.1, 1.0);
    world.addSphere({1, 0, 0}, {-0.3, 1e-9, 0}, 0.1, 1.0);
    physics::Params params;
    params.gravity = dvec3(0.0);
    const physics::Diagnostics d = physics::measure(world, params);
    ASSERT_NE(d.momentum.x, 0.0) << "the rounding this test is about";
    EXPECT_NEAR(d.momentumScale, std::sqrt(0.09 + 4.0) + std::hypot(0.3, 1e-9), 1e-12);
    const dvec3 shown = physics::momentumShown(d);
    EXPECT_EQ(shown.x, 0.0);
    EXPECT_EQ(shown.y, 1e-9);
    EXPECT_EQ(shown.z, 2.0);
}
