// Slide 14's contact graph and shock propagation (physics.md, "Slide 14, the global
// approach"): the levels it finds, what the sweep does to stacks, and the cases that trip
// naive versions (cycles, a sphere on two stacks, a sphere on two walls, a tilted box,
// spheres that touch only each other in free fall, a stack struck from the side).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/solver_stages.h"
#include "physics/step.h"
#include "physics_fixtures.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

using glm::dvec3;
using physics::Method;
using physics::ShockPropagation;

namespace {

constexpr double kR = 0.05;  // m: the radius of every sphere below but where one says otherwise

physics::Params lecture(ShockPropagation shock, int passes, Method method = Method::PositionBased) {
    physics::Params params;  // the lecture's defaults: epsilon 0.1 m/s, mu 0.5, beta 0.8
    params.timeStep = 1.0 / 60.0;
    params.substeps = 4;
    params.passes = passes;
    params.method = method;
    params.shock = shock;
    return params;
}

// `count` spheres of radius kR, 1 kg, stacked on the floor at (x, y), touching.
void addColumn(physics::World& world, int count, double x = 0.0, double y = 0.0) {
    for (int k = 0; k < count; ++k) world.addSphere({x, y, kR + 2.0 * kR * k}, dvec3(0.0), kR, 1.0);
}

// The deepest overlap now, as a fraction of the smaller radius (the CLI's "max penetration").
double deepest(const physics::World& world, const physics::Params& params) {
    return physics::measure(world, params).maxPenetration;
}

struct ColumnRun {
    double deepestOverlap = 0.0;  // of r, the most at any step end
    double topHeight = 0.0;       // m: the top sphere's centre at the end
};

// The column: 20 equal spheres, position based, h = 1/60 s, 4 substeps, 10 s.
ColumnRun runColumn(ShockPropagation shock, int passes, Method method = Method::PositionBased) {
    physics::World world;
    fixtures::addBox(world, {1.0, 1.0, 2.5});
    addColumn(world, 20);
    const physics::Params params = lecture(shock, passes, method);
    ColumnRun run;
    for (int s = 0; s < 600; ++s) {
        physics::step(world, params);
        run.deepestOverlap = std::max(run.deepestOverlap, deepest(world, params));
    }
    run.topHeight = world.position[19].z;
    return run;
}

}  // namespace

// The lesson in numbers. Without the sweep one pass carries the floor's push up one
// sphere per solver step: the column squashes (19.3 % of r at its foot) and its top sinks
// by about one radius; four passes leave 3.2 %. With it, every step ends with the column
// as built: the top at 39 r to rounding, no overlap.
TEST(ShockPropagation, AColumnOfTwentyRestsAtAnyNumberOfPasses) {
    const ColumnRun off1 = runColumn(ShockPropagation::Off, 1), off4 = runColumn(ShockPropagation::Off, 4);
    const ColumnRun on1 = runColumn(ShockPropagation::On, 1), on4 = runColumn(ShockPropagation::On, 4);
    std::printf("deepest overlap / r: off K=1 %.4f, K=4 %.4f, on K=1 %.2g, K=4 %.2g\n", off1.deepestOverlap,
                off4.deepestOverlap, on1.deepestOverlap, on4.deepestOverlap);
    std::printf("top below 39 r (m): off K=1 %.4f, K=4 %.4f, on K=1 %.2g, K=4 %.2g\n", 39 * kR - off1.topHeight,
                39 * kR - off4.topHeight, 39 * kR - on1.topHeight, 39 * kR - on4.topHeight);
    EXPECT_NEAR(off1.deepestOverlap, 0.193, 0.003);
    EXPECT_NEAR(39 * kR - off1.topHeight, 0.049, 0.002);  // about one radius
    EXPECT_NEAR(off4.deepestOverlap, 0.0315, 0.001);
    for (const ColumnRun& on : {on1, on4}) {
        EXPECT_LT(on.deepestOverlap, 0.005);  // the bound; measured 0 to 1e-14
        EXPECT_LT(on.deepestOverlap, 1e-9);
        EXPECT_NEAR(on.topHeight, 39 * kR, 0.005 * kR);
        EXPECT_NEAR(on.topHeight, 39 * kR, 1e-12);
    }
}

// The velocity method moves no sphere in its passes, nor does the sweep: it answers the
// static contacts' velocities only, and the overlaps the passes leave stay (the shock
// tooltip says so): the column of 20 at K = 1 overlaps by 2.7 % of r, its top 1.1 cm low.
TEST(ShockPropagation, WithTheVelocityMethodTheSweepLeavesTheOverlaps) {
    const ColumnRun on1 = runColumn(ShockPropagation::On, 1, Method::VelocityBased);
    const ColumnRun on4 = runColumn(ShockPropagation::On, 4, Method::VelocityBased);
    EXPECT_NEAR(on1.deepestOverlap, 0.0266, 0.001);  // measured; 0 with the position method
    EXPECT_NEAR(on4.deepestOverlap, 0.0166, 0.001);
    EXPECT_NEAR(39 * kR - on1.topHeight, 0.0112, 0.0005);  // m: 1.1 cm lower than built
    // Its answers to the static contacts still carry the weight: without the sweep the
    // velocity method's column sinks into itself (200 % of r: spheres pass into each other).
    const ColumnRun off1 = runColumn(ShockPropagation::Off, 1, Method::VelocityBased);
    EXPECT_NEAR(off1.deepestOverlap, 2.0, 0.01);
}

// Levels by distance in contacts from a plane: a column of 4 has 0, 1, 2, 3; in a
// tetrahedron the base triangle is a cycle inside level 0 and the top is level 1.
TEST(ShockPropagation, LevelsCountContactsFromAPlaneThroughCycles) {
    physics::World world;
    fixtures::addBox(world, {2.0, 2.0, 2.0});
    addColumn(world, 4, -0.5);
    const double side = 2.0 * kR;  // m: the base triangle's side
    const dvec3 centre(0.5, 0.0, kR);
    for (int k = 0; k < 3; ++k) {
        const double angle = 2.0 * M_PI * k / 3.0;
        world.addSphere(centre + side / std::sqrt(3.0) * dvec3(std::cos(angle), std::sin(angle), 0.0), dvec3(0.0), kR, 1.0);
    }
    world.addSphere(centre + dvec3(0.0, 0.0, side * std::sqrt(2.0 / 3.0)), dvec3(0.0), kR, 1.0);
    physics::step(world, lecture(ShockPropagation::On, 1));
    const std::vector<std::int32_t>& level = world.workspace.contactGraph.level;
    EXPECT_EQ(level, (std::vector<std::int32_t>{0, 1, 2, 3, 0, 0, 0, 1}));
    EXPECT_LT(deepest(world, lecture(ShockPropagation::On, 1)), 1e-3);
}

// Each sphere's neighbours are in three runs (one level down, its own level, the rest), each
// by number; and the first besideBefore of its own level are numbered below it.
void expectRunsOfNeighbours(const physics::ContactGraph& graph) {
    for (std::uint32_t i = 0; i + 1 < graph.edgeStart.size(); ++i) {
        const auto first = graph.neighbour.begin() + graph.edgeStart[i];
        const auto below = first + graph.belowCount[i], beside = below + graph.besideCount[i];
        const auto last = graph.neighbour.begin() + graph.edgeStart[i + 1];
        ASSERT_LE(beside - first, last - first) << i;
        const std::int32_t level = graph.level[i];
        for (auto j = first; j != last; ++j) {
            const std::int32_t theirs = graph.level[*j];
            EXPECT_EQ(j < below, theirs == level - 1) << i;
            EXPECT_EQ(j >= below && j < beside, theirs == level) << i;
            EXPECT_EQ(j >= below && j < below + graph.besideBefore[i], theirs == level && *j < i) << i;
        }
        EXPECT_TRUE(std::is_sorted(first, below) && std::is_sorted(below, beside) && std::is_sorted(beside, last)) << i;
    }
}

// The graph does not depend on the pair order: each sphere's neighbours are by number
// (the sweep's order) in each of their runs, from pairs visited in index order, reversed
// or shuffled.
TEST(ShockPropagation, TheGraphIsTheSameInEveryPairOrder) {
    physics::World world;
    fixtures::addBox(world, {1.0, 1.0, 1.0});
    fixtures::addRandomSpheres(world, 400, 0.03, 0.06, 0.9, {0.0, 0.0, 0.45}, 1.0, 7);
    physics::Params params = lecture(ShockPropagation::On, 1);
    for (int s = 0; s < 60; ++s) physics::step(world, params);  // fallen: many contacts
    physics::ContactGraph index;
    physics::findContactGraph(world, params.order, index);
    ASSERT_GT(index.neighbour.size(), 1000u);
    std::vector<physics::SpherePair>& pairs = world.workspace.visitOrder;
    std::reverse(pairs.begin(), pairs.end());
    physics::ContactGraph other;
    physics::findContactGraph(world, physics::PairOrder::Reversed, other);
    EXPECT_EQ(other.neighbour, index.neighbour);
    std::rotate(pairs.begin(), pairs.begin() + pairs.size() / 3, pairs.end());
    std::swap(pairs.front(), pairs.back());
    physics::findContactGraph(world, physics::PairOrder::Shuffled, other);
    EXPECT_EQ(other.neighbour, index.neighbour);
    EXPECT_EQ(other.level, index.level);
    expectRunsOfNeighbours(index);
}

// The sweep keeps its graph from step to step, updated around the pairs and levels that
// changed: after every step it is the graph found anew from the same pairs, entry for entry
// (a 2k pile landing and settling for 2.5 s in the index and reversed orders, and a 5k one
// in the colored order, which update it: colored from the same pairs in index order, which
// colorPairs swapped out of its visit order; the shuffled order finds it anew at every
// step), and the update leaves
// its per-sphere marks cleared for the sweep. It fails when the spheres one level above a
// sphere that lost its level are not checked again, or when only the spheres with changed
// pairs get their runs found again.
TEST(ShockPropagation, TheGraphKeptFromStepToStepIsTheGraphFoundAnew) {
    // The colored order on 5k spheres: from 4096 the broad phase merges the movers' pairs
    // into its kept ones (below, a mover means a new build), and the graph reads that list.
    const std::pair<const char*, const char*> cases[] = {
        {"order=index", "count=2000"}, {"order=reversed", "count=2000"}, {"order=colored", "count=5000"}};
    for (const auto& [order, count] : cases) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
        for (const std::string setting : {count, "radius=0.04", "shock=on", order}) {
            ASSERT_EQ(scenes::applySetting(scene, setting), "");
        }
        physics::World world = scenes::buildWorld(scene);
        const physics::ContactGraph& kept = world.workspace.contactGraph;
        std::size_t levelsChanged = 0;  // steps whose levels changed
        std::vector<std::int32_t> lastLevels;
        for (int frame = 0; frame < 150; ++frame) {
            physics::step(world, scene.params);
            // The graph found anew from the pairs the sweep used, and its spheres near a plane.
            physics::ContactGraph anew;
            physics::findContactGraphAnew(kept.builtFrom, physics::PairOrder::Index, kept.zero, anew);
            ASSERT_EQ(anew.level, kept.level) << order << " frame " << frame;
            ASSERT_EQ(anew.edgeStart, kept.edgeStart) << order << " frame " << frame;
            ASSERT_EQ(anew.neighbour, kept.neighbour) << order << " frame " << frame;
            ASSERT_EQ(anew.belowCount, kept.belowCount) << order << " frame " << frame;
            ASSERT_EQ(anew.besideCount, kept.besideCount) << order << " frame " << frame;
            ASSERT_EQ(anew.besideBefore, kept.besideBefore) << order << " frame " << frame;
            ASSERT_EQ(anew.byLevel, kept.byLevel) << order << " frame " << frame;
            ASSERT_EQ(anew.levelStart, kept.levelStart) << order << " frame " << frame;
            ASSERT_EQ(std::count(kept.moved.begin(), kept.moved.end(), 0), std::ptrdiff_t(kept.moved.size())) << frame;
            ASSERT_TRUE(kept.builtInIndexOrder) << order << " frame " << frame;  // the next step may update it
            levelsChanged += kept.level != lastLevels;
            lastLevels = kept.level;
        }
        expectRunsOfNeighbours(kept);
        EXPECT_GT(levelsChanged, 50u) << order;  // the update repaired levels, not only pairs
    }
}

// A sphere resting on a stack of three and on a stack of two larger spheres whose tops
// sit lower: it touches level 1 (the short stack's top), so it is level 2 with the tall
// stack's top, and that contact is answered inside the level, both movable. It leans on
// the tall stack's top, which slides off the sphere below it (nothing holds it sideways
// but v <- mu v): not a resting state, and no step ends where it began. What the sweep
// keeps is the overlaps: the deepest at any step end of the first second, against what
// the passes leave alone.
TEST(ShockPropagation, ASphereOnTwoStacksOfDifferentHeights) {
    physics::World world;
    fixtures::addBox(world, {2.0, 2.0, 2.0});
    addColumn(world, 3, -0.06);                                        // spheres 0, 1, 2: tops at z = 0.25
    const double big = 0.07;                                           // m
    for (int k = 0; k < 2; ++k) world.addSphere({0.09, 0.0, big + 2 * big * k}, dvec3(0.0), big, 1.0);  // 3, 4: top at 0.21
    // Sphere 5 (r = kR) touches 2 at (-0.06, 0.25) and 4 at (0.09, 0.21): the circles of
    // radius 2 kR and kR + big around them meet at its centre (in the plane y = 0).
    const dvec3 a(-0.06, 0.0, 0.25), b(0.09, 0.0, 0.21);
    const double ra = 2 * kR, rb = kR + big, apart = glm::length(b - a);
    const double along = (ra * ra - rb * rb + apart * apart) / (2 * apart);
    const dvec3 e = (b - a) / apart, up(-e.z, 0.0, e.x);
    world.addSphere(a + along * e + std::sqrt(ra * ra - along * along) * up, dvec3(0.0), kR, 1.0);
    ASSERT_GT(world.position[5].z, 0.3);

    const auto deepestInOneSecond = [&](ShockPropagation shock) {
        physics::World run = world;
        const physics::Params params = lecture(shock, 1);
        double most = 0.0;  // of the smaller radius
        for (int s = 0; s < 60; ++s) {
            physics::step(run, params);
            if (s == 0 && shock == ShockPropagation::On) {
                EXPECT_EQ(run.workspace.contactGraph.level, (std::vector<std::int32_t>{0, 1, 2, 0, 1, 2}));
            }
            most = std::max(most, deepest(run, params));
        }
        return most;
    };
    const double on = deepestInOneSecond(ShockPropagation::On), off = deepestInOneSecond(ShockPropagation::Off);
    std::printf("deepest overlap / r in 1 s: shock on %.4f, off %.4f\n", on, off);
    EXPECT_LT(on, 0.001);             // measured 0.0004
    EXPECT_NEAR(off, 0.0186, 0.002);  // the passes alone
}

// A sphere in the corner of the floor and a wall, pushed into the wall by its neighbour
// on the floor (both level 0, an inside contact): the inside contact moves it into the
// wall, then its planes come last, so the position method's promise holds: walls are
// never crossed. The overlap is what gives: the pass and each round of the sweep split it
// in half and the wall takes back its sphere's half, 0.2 r -> 0.1 -> 0.05 -> ..., for
// the sweep's four rounds: 0.1 / 2^4; then, deeper than 0.5 % of r, once more after the
// levels (what is left, split as a pass splits it): 0.1 / 2^5.
TEST(ShockPropagation, ASphereOnTwoWallsIsNeverLeftInsideEither) {
    physics::World world;
    fixtures::addBox(world, {1.0, 1.0, 1.0});
    world.addSphere({-0.5 + kR, 0.0, kR}, dvec3(0.0), kR, 1.0);          // touches the floor and x = -0.5
    world.addSphere({-0.5 + 2.8 * kR, 0.0, kR}, dvec3(0.0), kR, 1.0);    // overlaps it by 0.2 r
    physics::Params params = lecture(ShockPropagation::On, 1);
    params.substeps = 1;
    physics::step(world, params);
    EXPECT_EQ(world.workspace.contactGraph.level, (std::vector<std::int32_t>{0, 0}));
    for (const physics::Plane& plane : world.planes) {
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_GE(glm::dot(world.position[i] - plane.point, plane.normal), kR - 1e-12) << "sphere " << i;
        }
    }
    EXPECT_NEAR(deepest(world, params), 0.1 / 32, 1e-9);
}

// In a tilted box the levels start from the tilted floor: a column along its normal
// keeps its shape after a step, every overlap within 1e-3 of r.
TEST(ShockPropagation, ATiltedBoxHasItsLevelsFromTheTiltedFloor) {
    scenes::Scene scene;
    scene.box = scenes::Box{{2.0, 2.0, 2.0}, 20.0};  // m, tilted by 20 degrees
    physics::World world = scenes::buildWorld(scene);
    const physics::Plane floor = world.planes[0];
    for (int k = 0; k < 5; ++k) world.addSphere(floor.point + (kR + 2 * kR * k) * floor.normal, dvec3(0.0), kR, 1.0);
    ASSERT_GT(floor.normal.x * floor.normal.x + floor.normal.y * floor.normal.y, 0.01);  // tilted
    physics::Params params = lecture(ShockPropagation::On, 1);
    for (int s = 0; s < 3; ++s) physics::step(world, params);
    EXPECT_EQ(world.workspace.contactGraph.level, (std::vector<std::int32_t>{0, 1, 2, 3, 4}));
    EXPECT_LT(deepest(world, params), 1e-3);
    for (int k = 0; k + 1 < 5; ++k) {  // still a column along the normal: its spheres slide together
        const dvec3 link = world.position[k + 1] - world.position[k];
        EXPECT_NEAR(glm::dot(link, floor.normal), 2 * kR, 1e-3 * kR) << "spheres " << k << ", " << k + 1;
    }
}

// Spheres that touch only each other, far from every plane, reach no level: the sweep
// leaves them as the passes left them, bit for bit.
TEST(ShockPropagation, SpheresInFreeFallTouchingOnlyEachOtherKeepThePassesAnswer) {
    physics::World world;
    fixtures::addBox(world, {2.0, 2.0, 4.0});
    addColumn(world, 3, 0.0);
    for (std::size_t i = 0; i < 3; ++i) world.position[i].z += 2.0;  // touching, 2 m up
    world.addSphere({0.3, 0.0, 2.1}, {0.0, 0.0, 0.3}, kR, 1.0);
    world.addSphere({0.3 + 1.9 * kR, 0.0, 2.1}, {0.0, 0.0, -0.3}, kR, 1.0);  // an overlapping pair
    for (Method method : {Method::PositionBased, Method::VelocityBased, Method::Reflection}) {
        physics::World on = world, off = world;
        for (int s = 0; s < 12; ++s) {
            physics::step(on, lecture(ShockPropagation::On, 1, method));
            physics::step(off, lecture(ShockPropagation::Off, 1, method));
        }
        EXPECT_EQ(physics::stateHash(on), physics::stateHash(off));
        EXPECT_EQ(on.workspace.contactGraph.level, (std::vector<std::int32_t>(5, -1)));
    }
}

// A stack struck from the side: the impact (faster than epsilon) is the passes' to
// answer, with both masses, so the struck sphere leaves as it does without the sweep and
// the spheres above and below it do not move with it (the stack is not made rigid).
// With mu = 1: the lecture's v <- mu v at the struck sphere's static contacts above and
// below would otherwise damp it, once per pass and once more in the sweep (2 m/s ->
// 0.25 m/s at mu = 0.5 and K = 4, 0.125 m/s with the sweep: measured).
TEST(ShockPropagation, AStackStruckFromTheSideIsNotMadeRigid) {
    physics::World world;
    fixtures::addBox(world, {2.0, 2.0, 2.0});
    addColumn(world, 5);
    world.addSphere({-2.0 * kR - 0.001, 0.0, 5.0 * kR}, {2.0, 0.0, 0.0}, kR, 1.0);  // level with sphere 2
    physics::Params on = lecture(ShockPropagation::On, 4), off = lecture(ShockPropagation::Off, 4);
    on.beta = off.beta = 1.0;
    on.mu = off.mu = 1.0;
    on.substeps = off.substeps = 1;
    on.timeStep = off.timeStep = 1.0 / 240.0;
    physics::World withSweep = world, without = world;
    physics::step(withSweep, on);
    physics::step(without, off);
    EXPECT_NEAR(withSweep.velocity[2].x, 2.0, 1e-9);  // equal masses, elastic: they swap
    EXPECT_NEAR(withSweep.velocity[5].x, 0.0, 1e-9);
    for (std::size_t i = 0; i < world.size(); ++i) {  // to the rounding of the contacts' normals
        EXPECT_NEAR(withSweep.velocity[i].x, without.velocity[i].x, 1e-6) << "sphere " << i;
    }
    for (std::size_t i : {0u, 1u, 3u, 4u}) EXPECT_NEAR(withSweep.velocity[i].x, 0.0, 1e-6) << "sphere " << i;
    for (int s = 0; s < 60; ++s) physics::step(withSweep, on);
    EXPECT_GT(withSweep.position[2].x, 0.2);  // struck out of the stack, 0.25 s later
    EXPECT_LT(std::abs(withSweep.position[3].x), 0.05);

    // The flaw the README states: at mu = 0.5 the sweep brakes the struck sphere once more.
    on.mu = off.mu = 0.5;
    physics::World dampedWithSweep = world, dampedWithout = world;
    physics::step(dampedWithSweep, on);
    physics::step(dampedWithout, off);
    EXPECT_NEAR(dampedWithout.velocity[2].x, 0.25, 1e-9);
    EXPECT_NEAR(dampedWithSweep.velocity[2].x, 0.125, 1e-9);
}

// An impact that travels upward, the stacked drop (a 1 kg sphere resting on a 3 kg one,
// both falling onto the floor): its bounces are impacts, which the sweep leaves to the
// passes, so every velocity after the landing is what the passes give alone.
TEST(ShockPropagation, AnImpactTravellingUpIsThePassesToAnswer) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("20_stacked_drop"));
    ASSERT_EQ(scenes::applySetting(scene, "method=position"), "");
    physics::World on = scenes::buildWorld(scene), off = on;
    scenes::Scene withSweep = scene;
    ASSERT_EQ(scenes::applySetting(withSweep, "shock=on"), "");
    for (int s = 0; s < 30; ++s) {
        physics::step(on, withSweep.params);
        physics::step(off, scene.params);
    }
    for (std::size_t i = 0; i < on.size(); ++i) {
        EXPECT_LT(glm::length(on.velocity[i] - off.velocity[i]), 1e-9) << "sphere " << i;
    }
}

// The sweep never creates energy: every preset under the position, velocity and
// reflection methods with shock propagation on, 2 s (generated scenes at 300 spheres, as
// the solvers' energy test): the modified energy never ends higher than it began, or,
// where the method gains energy by itself (the velocity method's bounce at beta = 1 in 01:
// 12 %, the contact found after v <- v + h g), no higher than without the sweep.
TEST(ShockPropagation, NoPresetCreatesEnergyWithTheSweep) {
    const auto rise = [](scenes::Scene scene, const char* shock) {
        EXPECT_EQ(scenes::applySetting(scene, shock), "");
        const physics::Params& params = scene.params;
        physics::World world = scenes::buildWorld(scene);
        const double start = physics::modifiedEnergy(world, params);
        for (double t = 0.0; t < 2.0; t += params.timeStep) physics::step(world, params);
        return (physics::modifiedEnergy(world, params) - start) / std::max(std::abs(start), 1e-12);
    };
    for (const std::string& name : scenes::listPresets()) {
        for (const char* method : {"method=position", "method=velocity", "method=reflection"}) {
            scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
            ASSERT_EQ(scenes::applySetting(scene, method), "");
            if (!scene.generators.empty()) {
                ASSERT_EQ(scenes::applySetting(scene, "count=300"), "");
            }
            scene.emitters.clear();  // an emitter brings energy in
            if (scene.params.alpha > 1.0 || scene.params.beta > 1.0 || scene.params.mu > 1.0) continue;
            const double withSweep = rise(scene, "shock=on"), without = rise(scene, "shock=off");
            if (std::string(method) == "method=reflection" && withSweep > std::max(without, 0.0) + 1e-9) {
                // Reflection lifts a column's foot off the floor by beta d (55 um at the end
                // of 09), and the sweep stands the column on it uncompressed, where without
                // it the column is squashed lower: 09_column gains 8.7e-5 of its energy,
                // 21_shock_column 7.6e-5 (measured). The sweep projects; the lift is reflection's.
                std::printf("%s %s: %.3g with the sweep, %.3g without\n", name.c_str(), method, withSweep, without);
                EXPECT_LT(withSweep, 1e-4) << name;
                continue;
            }
            EXPECT_LE(withSweep, std::max(without, 0.0) + 1e-9) << name << " " << method << ", without " << without;
            if (without > 1e-9) std::printf("%s %s gains %.3g without the sweep, %.3g with\n", name.c_str(), method, without, withSweep);
        }
    }
}

// The pile: 10 000 spheres of the pile preset (r = 5 cm x (1000/N)^(1/3), as the
// peer benchmark scales it), position based, K = 4, h = 1/240 s, 5 s from the lattice:
// the deepest overlap then, with the sweep under 1 % of r (0.64 % measured; 0.50, 0.74,
// 0.58 and 0.69 % with seeds 2 to 5, since the contacts still deeper than 0.5 % of r are
// split after the levels: before, seeds 4 and 5 had 1.53 and 1.02 %, cages), without it
// 4.6 % (4.5 and 5.0 %). And, asserted for seed 1, at every step from 3 to 6 s while the
// last spheres land, under 2 % with the sweep (1.25 % measured; 1.24, 2.24, 0.72 and 0.89 %
// with seeds 2 to 5): when its graph was found from the pairs before the passes, a landing
// impact's lift pushed a sphere into one it had no pair with, the sweep lifted it deeper,
// and one step reached 16.5 % (3.7 to 7.4 % without the sweep). About 12 s.
TEST(ShockPropagation, APileOfTenThousandSettlesWithOverlapsUnderOnePercent) {
    struct Run {
        double atFiveSeconds = 0.0, mostFromThreeToSix = 0.0;  // deepest overlap / r
    };
    const auto run = [](const char* shock, int steps) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
        for (const char* setting : {"count=10000", "radius=0.0232", "passes=4", "threads=1", shock}) {
            EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
        }
        physics::World world = scenes::buildWorld(scene);
        Run result;
        for (int s = 1; s <= steps; ++s) {
            physics::step(world, scene.params);
            if (s == 300) result.atFiveSeconds = deepest(world, scene.params);
            if (s >= 180) result.mostFromThreeToSix = std::max(result.mostFromThreeToSix, deepest(world, scene.params));
        }
        return result;
    };
    const Run on = run("shock=on", 360), off = run("shock=off", 300);
    std::printf("10k pile at 5 s, deepest overlap / r: shock on %.4f, off %.4f; on, most from 3 to 6 s %.4f\n",
                on.atFiveSeconds, off.atFiveSeconds, on.mostFromThreeToSix);
    EXPECT_LT(on.atFiveSeconds, 0.01);
    EXPECT_GT(off.atFiveSeconds, 0.04);
    EXPECT_LT(on.mostFromThreeToSix, 0.02);
}

// The 1k pile at rest (its last second, 14 to 15 s, four seeds). What the sweep changes is
// the velocities, not the motion:
// - the typical sphere's velocity is lower with the sweep (the median speed at 15 s 0.49-0.54
//   of the passes' alone: 0.16-0.21 against 0.30-0.40 micrometres per second);
// - but the typical sphere moves as far: 1.2-1.5 mm in the second with or without the sweep
//   (0.93-1.33 times; seeds 5 to 8 as well), thousands of times what its velocity shows. The
//   position stage moves what the velocity does not: each step gravity moves a resting
//   sphere g h^2 (0.17 mm) into the spheres below,
//   and the passes' projection splits that overlap between both, spreading the levels below
//   sideways. The sweep comes after them, and the pile creeps as much (its mean height sinks
//   1.8 mm from 15 to 30 s in seed 1, against 2.1 mm without);
// - and the kinetic energy per sphere, a mean set by the few fastest, is higher in most
//   seeds: 19, 1.0, 0.23 and 55 times the passes' (the mean over the second; seeds 5 to 8:
//   121, 2.3, 55 and 0.67). The fastest rest on one sphere. Seed 4's (716, r = 5.5 cm) sits
//   on a sphere (520) held only by a contact at its side, slide 13's v <- mu v, which sinks
//   both at 4.4 cm/s with or without the sweep; with the sweep, 520 is answered as a frozen
//   level first, ends some steps 1e-6 m below 716, and 716 then ends the step with
//   gravity's g h (4.1 cm/s) unanswered. Which seeds hold such a sphere is as good as random.
// The aim (no more kinetic energy per sphere with the sweep) is not reached: the test
// asserts the flaw's size, under 300 times in every seed and more than twice in some, and
// that the sweep's pile moves as the passes' does.
TEST(ShockPropagation, ARestingPileMovesAsMuchWithTheSweepThoughItsVelocitiesAreLower) {
    struct Rest {
        double medianSpeed = 0.0;       // m/s, at 15 s
        double medianMotion = 0.0;      // m, from 14 to 15 s
        double kineticPerSphere = 0.0;  // J, the mean over the time steps of the last second
        int touchedByFastest = 0;       // spheres the fastest touches at 15 s (to 10^-4 r)
    };
    const auto rest = [](const std::string& seed, const char* shock) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
        EXPECT_EQ(scenes::applySetting(scene, "seed=" + seed), "");
        EXPECT_EQ(scenes::applySetting(scene, shock), "");
        physics::World world = scenes::buildWorld(scene);
        while (world.time < 14.0 - 1e-9) physics::step(world, scene.params);
        const std::vector<dvec3> before = world.position;
        Rest result;
        int steps = 0;
        while (world.time < 15.0 - 1e-9) {
            physics::step(world, scene.params);
            result.kineticPerSphere += physics::measure(world, scene.params).kinetic / double(world.size());
            ++steps;
        }
        result.kineticPerSphere /= steps;
        std::vector<double> speeds, motions;
        for (std::size_t i = 0; i < world.size(); ++i) {
            speeds.push_back(glm::length(world.velocity[i]));
            motions.push_back(glm::length(world.position[i] - before[i]));
        }
        const std::size_t fastest = std::max_element(speeds.begin(), speeds.end()) - speeds.begin();
        for (std::size_t j = 0; j < world.size(); ++j) {
            const double gap = glm::length(world.position[fastest] - world.position[j]) - world.radius[fastest] - world.radius[j];
            result.touchedByFastest += j != fastest && gap < 1e-4 * world.radius[fastest];
        }
        const auto median = [](std::vector<double>& values) {
            std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
            return values[values.size() / 2];
        };
        result.medianSpeed = median(speeds);
        result.medianMotion = median(motions);
        return result;
    };
    double mostKineticRatio = 0.0;
    for (const std::string seed : {"1", "2", "3", "4"}) {
        const Rest on = rest(seed, "shock=on"), off = rest(seed, "shock=off");
        const double kineticRatio = on.kineticPerSphere / off.kineticPerSphere;
        mostKineticRatio = std::max(mostKineticRatio, kineticRatio);
        std::printf("seed %s, on / off: median speed %.2e / %.2e m/s, median motion %.2e / %.2e m, kinetic energy per sphere "
                    "%.2e / %.2e J (x %.2f), the fastest touches %d\n",
                    seed.c_str(), on.medianSpeed, off.medianSpeed, on.medianMotion, off.medianMotion, on.kineticPerSphere,
                    off.kineticPerSphere, kineticRatio, on.touchedByFastest);
        EXPECT_LT(on.medianSpeed, 0.75 * off.medianSpeed) << seed;
        EXPECT_GT(on.medianSpeed, 0.4 * off.medianSpeed) << seed;
        EXPECT_GT(on.medianMotion, 0.8 * off.medianMotion) << seed;
        EXPECT_LT(on.medianMotion, 1.5 * off.medianMotion) << seed;
        EXPECT_EQ(on.touchedByFastest, 1) << seed;
        EXPECT_LT(kineticRatio, 300.0) << seed;
    }
    EXPECT_GT(mostKineticRatio, 2.0) << "the aim is met: resolve it in issue 19";
}

// The graph is found from the last step's candidate pairs: a world that lost spheres since
// (a state put back from the timeline, a sphere removed) is read within range, its graph
// empty until the next step finds its pairs (the sanitized run checks the reads).
TEST(ShockPropagation, TheGraphOfAWorldThatLostSpheresSinceItsLastStepIsEmpty) {
    physics::World world;
    fixtures::addBox(world, {1.0, 1.0, 1.0});
    addColumn(world, 10);
    physics::step(world, lecture(ShockPropagation::On, 1));
    ASSERT_FALSE(world.workspace.visitOrder.empty());
    for (int k = 0; k < 5; ++k) world.removeSphere(world.size() - 1);
    physics::ContactGraph graph;
    physics::findContactGraph(world, physics::PairOrder::Index, graph);
    EXPECT_TRUE(graph.neighbour.empty());
    EXPECT_EQ(graph.level, (std::vector<std::int32_t>{0, -1, -1, -1, -1}));
    physics::step(world, lecture(ShockPropagation::On, 1));
    EXPECT_EQ(world.workspace.contactGraph.level, (std::vector<std::int32_t>{0, 1, 2, 3, 4}));
}

namespace {

// The 10k pile, one thread, the sweep on.
scenes::Scene landingPileScene() {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    for (const char* setting : {"count=10000", "radius=0.0232", "threads=1", "shock=on"}) {
        EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
    }
    return scene;
}

}  // namespace

// The sweep's pushes off the frozen level, several spheres side by side (colored_lanes.cpp):
// every lane width the CPU runs moves the spheres of a level, and lowers their wall
// clearances, as one sphere at a time does, bit for bit (the state hashes check the widest
// against the sweep's own code before it).
TEST(ShockPropagation, ThePushesOffTheFrozenLevelSideBySideAreThoseOfOneSphereAtATime) {
    const scenes::Scene scene = landingPileScene();
    physics::World world = scenes::buildWorld(scene);
    for (int k = 0; k < 150; ++k) physics::step(world, scene.params);  // 2.5 s: landing
    const physics::ContactGraph& graph = world.workspace.contactGraph;
    ASSERT_GT(graph.levelStart.size(), 6u);
    for (const std::uint32_t level : {1u, 3u, 5u}) {
        const std::vector<std::uint32_t> spheres(graph.byLevel.begin() + graph.levelStart[level],
                                                 graph.byLevel.begin() + graph.levelStart[level + 1]);
        ASSERT_GT(spheres.size(), 20u) << "level " << level;
        // The level sunk by 1 % of its radii, so that most of its spheres touch the level below.
        physics::World sunk = world;
        for (const std::uint32_t i : spheres) sunk.position[i].z -= 0.01 * sunk.radius[i];
        physics::World one = sunk;
        std::vector<std::uint8_t> againOne(spheres.size(), 2), againLanes(spheres.size(), 2);
        physics::pushOffFrozenSideBySide(one, graph, spheres.data(), spheres.size(), true, againOne.data(), 1e-3, 1);
        int moved = 0;
        for (const std::uint32_t i : spheres) moved += one.position[i] != sunk.position[i];
        EXPECT_GT(moved, int(spheres.size()) / 2) << "level " << level;
        const auto goOn = std::count(againOne.begin(), againOne.end(), 1);
        EXPECT_GT(goOn, 0) << "level " << level;
        EXPECT_LT(goOn, std::ptrdiff_t(spheres.size())) << "level " << level;
        for (const int width : physics::laneWidths()) {
            physics::World lanes = sunk;
            physics::pushOffFrozenSideBySide(lanes, graph, spheres.data(), spheres.size(), true, againLanes.data(), 1e-3,
                                             width);
            EXPECT_EQ(lanes.position, one.position) << width << " lanes, level " << level;
            EXPECT_EQ(againLanes, againOne) << width << " lanes, level " << level;
            EXPECT_EQ(lanes.workspace.wallClearance, one.workspace.wallClearance) << width << " lanes";
        }
    }
}

// The sweep's first round off the frozen level, side by side: each sphere's static contacts
// with the frozen spheres below it answered (v <- mu v after the approach is removed, the
// frozen sphere infinitely heavy), each before its push, as the one-sphere code does it
// (touching, respondToFrozenContact, moveOffFrozenSphere), at every lane width and under
// both response models: the same positions, velocities, contact states, count of static
// contacts and wall clearances. It fails when a lane answers a contact that does not touch
// (checked).
TEST(ShockPropagation, TheFirstRoundOffTheFrozenLevelSideBySideIsThatOfOneSphereAtATime) {
    const scenes::Scene scene = landingPileScene();
    physics::World world = scenes::buildWorld(scene);
    for (int k = 0; k < 150; ++k) physics::step(world, scene.params);  // 2.5 s: landing
    const physics::ContactGraph& graph = world.workspace.contactGraph;
    physics::Params params = scene.params;
    // The lecture's response (v <- mu v), then the momentum-conserving one (mu on the
    // relative tangential velocity).
    for (const auto response : {physics::ResponseModel::LectureAttenuation, physics::ResponseModel::MomentumConserving})
    for (const std::uint32_t level : {1u, 3u, 5u}) {
        params.response = response;
        const std::vector<std::uint32_t> spheres(graph.byLevel.begin() + graph.levelStart[level],
                                                 graph.byLevel.begin() + graph.levelStart[level + 1]);
        // The level sunk by 1 % of its radii, so that most touch the level below; every third
        // sphere falling at 0.3 m/s, so that its contacts are impacts (left alone), not static.
        physics::World sunk = world;
        for (std::size_t k = 0; k < spheres.size(); ++k) {
            sunk.position[spheres[k]].z -= 0.01 * sunk.radius[spheres[k]];
            if (k % 3 == 0) sunk.velocity[spheres[k]].z -= 0.3;
        }
        physics::World one = sunk;
        physics::StepStats oneStats;
        std::vector<std::uint8_t> againOne;
        std::uint64_t touchingContacts = 0;
        for (const std::uint32_t i : spheres) {
            double deepestOverlap = 0.0;
            int pushed = 0;
            for (std::uint32_t e = graph.edgeStart[i]; e < graph.edgeStart[i] + graph.belowCount[i]; ++e) {
                const std::uint32_t frozen = graph.neighbour[e];
                physics::SphereContact contact;
                if (!physics::touching(one, physics::SpherePair{i, frozen}, contact)) continue;
                ++touchingContacts;
                if (std::abs(glm::dot(one.velocity[frozen] - one.velocity[i], contact.u)) <= params.epsilon) {
                    physics::respondToFrozenContact(one, i, frozen, contact, params, oneStats);
                }
                physics::moveOffFrozenSphere(one.position[i], contact.u, contact.depth);
                one.workspace.wallClearance[i] -= contact.depth;
                deepestOverlap = std::max(deepestOverlap, contact.depth);
                pushed += contact.depth > 0.0;
            }
            againOne.push_back(pushed > 1 && deepestOverlap > 1e-3 * one.radius[i]);
        }
        EXPECT_GT(oneStats.staticContacts, touchingContacts / 2) << "level " << level;
        EXPECT_LT(oneStats.staticContacts, touchingContacts * 9 / 10) << "level " << level;
        for (const int width : {1, 2, 4, 8}) {
            const std::vector<int> widths = physics::laneWidths();
            if (width > 1 && std::find(widths.begin(), widths.end(), width) == widths.end()) continue;
            physics::World lanes = sunk;
            physics::StepStats lanesStats;
            std::vector<std::uint8_t> againLanes(spheres.size(), 2);
            physics::pushOffFrozenSideBySide(lanes, graph, spheres.data(), spheres.size(), true, againLanes.data(), 1e-3,
                                             width, &params, &lanesStats);
            EXPECT_EQ(lanes.position, one.position) << width << " lanes, level " << level;
            EXPECT_EQ(lanes.velocity, one.velocity) << width << " lanes, level " << level;
            EXPECT_EQ(lanes.contactState, one.contactState) << width << " lanes, level " << level;
            EXPECT_EQ(lanesStats.staticContacts, oneStats.staticContacts) << width << " lanes, level " << level;
            EXPECT_EQ(lanes.workspace.wallClearance, one.workspace.wallClearance) << width << " lanes";
            EXPECT_EQ(againLanes, againOne) << width << " lanes, level " << level;
        }
    }
}

// The whole sweep side by side (the contacts inside a level by wavefronts, the rounds off the
// frozen level in lanes) reaches the state of its one-contact-at-a-time code, which runs
// while contacts are logged: the landing 2k pile, 40 steps from 1 s, positions, velocities
// and contact states bit for bit. It fails when the contacts inside a level answer their
// impacts too, not only their static contacts (checked).
TEST(ShockPropagation, TheSweepSideBySideReachesTheStateOfOneContactAtATime) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    for (const char* setting : {"count=2000", "radius=0.04", "threads=1", "shock=on"}) {
        ASSERT_EQ(scenes::applySetting(scene, setting), "") << setting;
    }
    physics::World lanes = scenes::buildWorld(scene);
    for (int k = 0; k < 60; ++k) physics::step(lanes, scene.params);
    physics::World one = lanes;
    one.recordContacts = true;
    for (int k = 0; k < 40; ++k) {
        physics::step(lanes, scene.params);
        physics::step(one, scene.params);
        one.contacts.clear();
    }
    EXPECT_GT(lanes.workspace.contactGraph.levelStart.size(), 4u);
    EXPECT_EQ(lanes.position, one.position);
    EXPECT_EQ(lanes.velocity, one.velocity);
    EXPECT_EQ(lanes.contactState, one.contactState);
}
