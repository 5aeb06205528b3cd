// The pair order `colored` (not the lecture's, colored_order.cpp): its colouring, and the
// physics guide's checks that do not depend on the order, run in it (energy, momentum and
// the elastic gas in test_canonical_checks.cpp, the same state on any thread count in
// test_solver_threads.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/solver_stages.h"
#include "physics/step.h"
#include "physics_fixtures.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

using glm::dvec3;
using physics::Method;
using physics::PairOrder;

namespace {

const Method kMethods[] = {Method::PositionBased, Method::VelocityBased};

void run(physics::World& world, const physics::Params& params, int steps) {
    for (int k = 0; k < steps; ++k) physics::step(world, params);
}

// The pile preset with `count` spheres of `radius` m, after "name=value" settings.
scenes::Scene pile(int count, double radius, std::initializer_list<std::string> settings) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    EXPECT_EQ(scenes::applySetting(scene, "count=" + std::to_string(count)), "");
    EXPECT_EQ(scenes::applySetting(scene, "radius=" + std::to_string(radius)), "");
    for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "");
    return scene;
}

// The scene's world after `steps` steps (a pile: landed), its next pairs found and
// coloured.
physics::World landedAndColoured(const scenes::Scene& scene, int steps) {
    physics::World world = scenes::buildWorld(scene);
    run(world, scene.params, steps);
    physics::StepStats none;
    physics::findOrderedPairs(world, scene.params, none);
    return world;
}

// The colours of the last solver step: each colour's pairs share no sphere (but the
// overflow's), a block's pairs lie inside it and the border's between blocks, and the
// pairs are those of the index order, each once.
struct Colouring {
    unsigned colours = 0;         // the most colours a group holds, the overflow not counted
    unsigned mostPairs = 0;       // the most pairs one sphere has
    std::size_t border = 0;       // pairs between blocks
    std::size_t overflow = 0;     // pairs in the overflow
    bool disjoint = true;         // no two pairs of a colour share a sphere
    bool inTheirGroup = true;     // a block's pairs inside it, the border's between blocks
    bool eachPairOnce = true;     // the same pairs as the index order's
};

Colouring colouringOf(const physics::World& world, const physics::Params& params) {
    const physics::Workspace& ws = world.workspace;
    Colouring c;
    const std::uint32_t groups = physics::colorGroups(ws);
    for (std::uint32_t g = 0; g < groups; ++g) {
        const bool border = g + 1 == groups;
        unsigned colours = 0;
        for (unsigned colour = 0; colour < physics::kGroupColors; ++colour) {
            const physics::Range r = physics::colorRange(ws, g, colour);
            colours += r.end > r.begin;
            if (border) c.border += r.end - r.begin;
            std::set<std::uint32_t> spheres;
            for (std::uint32_t k = r.begin; k < r.end; ++k) {
                const physics::SpherePair pair = ws.visitOrder[k];
                c.disjoint = c.disjoint && spheres.insert(pair.i).second && spheres.insert(pair.j).second;
                const std::uint32_t bi = ws.blockOfSphere[pair.i], bj = ws.blockOfSphere[pair.j];
                c.inTheirGroup = c.inTheirGroup && (border ? bi != bj : bi == g && bj == g);
            }
        }
        c.colours = std::max(c.colours, colours);
    }
    const physics::Range overflow = physics::overflowRange(ws);
    c.overflow = overflow.end - overflow.begin;
    EXPECT_EQ(overflow.end, ws.visitOrder.size());
    std::vector<unsigned> pairsOf(world.size(), 0);
    for (const auto& p : ws.visitOrder) c.mostPairs = std::max({c.mostPairs, ++pairsOf[p.i], ++pairsOf[p.j]});
    physics::World indexed = world;
    physics::Params index = params;
    index.order = PairOrder::Index;
    physics::StepStats none;
    physics::findOrderedPairs(indexed, index, none);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> a, b;
    for (const auto& p : ws.visitOrder) a.emplace_back(p.i, p.j);
    for (const auto& p : indexed.workspace.visitOrder) b.emplace_back(p.i, p.j);
    std::sort(a.begin(), a.end());
    c.eachPairOnce = a == b;
    return c;
}

}  // namespace

// The landed pile of 5000: a sphere with D pairs needs D colours, and greedy colouring
// takes at most 2 D - 1 (a pair meets at most 2 (D - 1) others); never the overflow.
TEST(ColoredOrder, NoTwoPairsOfAColourShareASphere) {
    const scenes::Scene scene = pile(5000, 0.025, {"order=colored"});
    const physics::World world = landedAndColoured(scene, 60);  // 1 s
    ASSERT_GT(world.workspace.visitOrder.size(), 8000u);
    const Colouring c = colouringOf(world, scene.params);
    EXPECT_TRUE(c.disjoint);
    EXPECT_TRUE(c.inTheirGroup);
    EXPECT_TRUE(c.eachPairOnce);
    EXPECT_EQ(c.overflow, 0u);
    EXPECT_EQ(physics::colorGroups(world.workspace), 3u) << "two blocks (4096 + 904 spheres), the border";
    EXPECT_GT(c.border, 0u);
    EXPECT_GE(c.colours, c.mostPairs);
    EXPECT_LE(c.colours, 2 * c.mostPairs - 1);
    EXPECT_GE(c.mostPairs, 6u) << "a pile, not a gas";
}

// A sphere touching 100 small ones has more pairs than there are colours: the pairs past
// the 64th go to the overflow, visited in index order, and the run is the same on any
// thread count.
TEST(ColoredOrder, ASphereWithMorePairsThanColoursFillsTheOverflow) {
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = PairOrder::Colored;
    physics::World world;
    world.addSphere({0, 0, 0}, {0, 0, 0}, 1.0, 100.0);
    for (int k = 0; k < 100; ++k) {  // on a spiral over the big sphere's surface, pressed in
        const double z = 1.0 - (2.0 * k + 1.0) / 100.0, ring = std::sqrt(1.0 - z * z), turn = 2.399963 * k;
        world.addSphere(1.04 * dvec3(ring * std::cos(turn), ring * std::sin(turn), z), {0, 0, 0}, 0.05, 0.01);
    }
    physics::StepStats none;
    physics::findOrderedPairs(world, params, none);
    const Colouring c = colouringOf(world, params);
    EXPECT_EQ(c.overflow, 36u) << "100 pairs with the big sphere, 64 coloured";
    EXPECT_TRUE(c.disjoint);
    EXPECT_TRUE(c.eachPairOnce);
}

// A box packed with `count` spheres of radius 0.1 m on a cubic lattice (each touching its
// six neighbours), `across` a side and as many as needed up, numbered in a shuffled order:
// spheres next to each other in space are far apart in number.
physics::World shuffledLattice(int count, int across) {
    std::vector<dvec3> places;
    for (int k = 0; k < count; ++k) places.push_back(0.199 * dvec3(k % across, k / across % across, k / (across * across)));
    std::shuffle(places.begin(), places.end(), std::mt19937(7));
    physics::World world;
    for (const dvec3& p : places) world.addSphere(p, {0, 0, 0}, 0.1, 1.0);
    return world;
}

// Below 40 960 spheres the blocks are runs of 4096 sphere numbers (10 000: three blocks,
// the border 39 % of the landed pile's pairs); from there on, places: runs of 4096 spheres
// along a curve through the world, so that most pairs lie inside one block, however the
// spheres are numbered. In a lattice of 48 000 numbered at random, blocks of numbers would
// leave nearly every pair (11 of 12) to the border; by place it holds 7.8 % (measured).
TEST(ColoredOrder, FromTenBlocksOnTheBlocksArePlaces) {
    const scenes::Scene scene = pile(10000, 0.0232, {"order=colored"});
    const physics::World pileWorld = landedAndColoured(scene, 90);  // 1.5 s
    for (std::uint32_t i = 0; i < pileWorld.size(); ++i) {
        ASSERT_EQ(pileWorld.workspace.blockOfSphere[i], i / physics::kBlockSpheres) << i;
    }
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = PairOrder::Colored;
    physics::World world = shuffledLattice(48000, 40);
    physics::StepStats none;
    physics::findOrderedPairs(world, params, none);
    const physics::Workspace& ws = world.workspace;
    std::vector<std::size_t> spheresOf(physics::colorGroups(ws) - 1, 0);
    for (const std::uint32_t block : ws.blockOfSphere) ++spheresOf.at(block);
    ASSERT_EQ(spheresOf.size(), 12u) << "11 blocks of 4096, one of 2944";
    for (std::size_t b = 0; b + 1 < spheresOf.size(); ++b) EXPECT_EQ(spheresOf[b], physics::kBlockSpheres) << b;
    const Colouring c = colouringOf(world, params);
    EXPECT_TRUE(c.inTheirGroup);
    EXPECT_TRUE(c.disjoint);
    EXPECT_TRUE(c.eachPairOnce);
    const double border = double(c.border) / double(ws.visitOrder.size());
    EXPECT_GT(border, 0.04);
    EXPECT_LT(border, 0.12);
}

// Every centre at one height (spheres on a table): the box around them has no height,
// and tiles sized for its volume would number a million. They stay at most 64 a block,
// and the blocks are still places: patches of the table (the border 1.7 % of the pairs).
TEST(ColoredOrder, SpheresAtOneHeightKeepFewTiles) {
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = PairOrder::Colored;
    physics::World world;
    for (int k = 0; k < 42000; ++k) world.addSphere({0.199 * (k % 210), 0.199 * (k / 210), 0.1}, {0, 0, 0}, 0.1, 1.0);
    physics::StepStats none;
    physics::findOrderedPairs(world, params, none);
    const physics::Workspace& ws = world.workspace;
    EXPECT_LE(ws.tileStart.size() - 1, 64u * 11);
    EXPECT_EQ(physics::colorGroups(ws), 12u) << "11 blocks, the border";
    const Colouring c = colouringOf(world, params);
    EXPECT_TRUE(c.disjoint);
    EXPECT_TRUE(c.inTheirGroup);
    EXPECT_TRUE(c.eachPairOnce);
    EXPECT_EQ(ws.visitOrder.size(), 2u * 42000 - 200 - 210) << "each sphere and its right and upper neighbours";
    EXPECT_LT(double(c.border) / double(ws.visitOrder.size()), 0.05);
}

// Two spheres each touching 150 small ones, at opposite corners of a lattice of spheres
// that touch nothing (41 000 in all: eleven blocks): the colouring, overflow included, is
// the same on one, two and three threads. The first star lies last along the blocks'
// curve, so on several threads its overflow is found by a later task than the second
// star's, and must still come first.
TEST(ColoredOrder, TheColouringIsTheSameOnAnyThreadCount) {
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = PairOrder::Colored;
    physics::World world;
    for (const double x : {40.0, -4.0}) {
        world.addSphere({x, x, x}, {0, 0, 0}, 1.0, 100.0);
        for (int k = 0; k < 150; ++k) {  // on a spiral over the big sphere's surface, pressed in
            const double z = 1.0 - (2.0 * k + 1.0) / 150.0, ring = std::sqrt(1.0 - z * z), turn = 2.399963 * k;
            world.addSphere(dvec3(x) + 1.04 * dvec3(ring * std::cos(turn), ring * std::sin(turn), z), {0, 0, 0},
                            0.05, 0.01);
        }
    }
    for (int k = 0; world.size() < 41000; ++k) {
        world.addSphere(dvec3(k % 35, k / 35 % 35, k / 1225), {0, 0, 0}, 0.1, 1.0);
    }
    std::vector<physics::SpherePair> order;
    std::vector<std::uint32_t> colorStart;
    for (const int threads : {1, 2, 3}) {
        physics::World copy = world;
        params.threads = threads;
        physics::StepStats none;
        physics::findOrderedPairs(copy, params, none);
        ASSERT_EQ(physics::colorGroups(copy.workspace), 12u) << "eleven blocks, the border";
        const Colouring c = colouringOf(copy, params);
        EXPECT_TRUE(c.disjoint);
        EXPECT_TRUE(c.eachPairOnce);
        EXPECT_GE(c.overflow, 22u) << "each big sphere has 150 pairs, at most 128 in colours";
        if (threads == 1) {
            order = copy.workspace.visitOrder;
            colorStart = copy.workspace.colorStart;
            continue;
        }
        const auto samePair = [](const physics::SpherePair& a, const physics::SpherePair& b) {
            return a.i == b.i && a.j == b.j;
        };
        EXPECT_TRUE(std::equal(order.begin(), order.end(), copy.workspace.visitOrder.begin(),
                               copy.workspace.visitOrder.end(), samePair))
            << threads << " threads";
        EXPECT_EQ(copy.workspace.colorStart, colorStart) << threads << " threads";
    }
}

// Slide 14's lesson still shows: in the cradle, the colored order visits (0,1), (2,3),
// then (1,2), (3,4): with the position method one pass carries the strike two spheres on,
// and two reach the last (index order needs one pass, reversed four).
TEST(ColoredOrder, NewtonsCradleNeedsTwoPasses) {
    const double v0 = 2.0;
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.order = PairOrder::Colored;
    for (int passes = 1; passes <= 2; ++passes) {
        params.passes = passes;
        physics::World world = fixtures::cradle(v0);
        physics::step(world, params);
        for (int k = 0; k < 5; ++k) {
            EXPECT_NEAR(world.velocity[k].x, k == 2 * passes ? v0 : 0.0, 1e-6 * v0) << passes << " " << k;
        }
    }
}

// The guide's resting sphere, three times side by side, touching: sliding on the floor,
// they stop without sinking, into the floor or into each other.
TEST(ColoredOrder, RestingSpheresStopWithoutSinking) {
    for (Method method : kMethods) {
        physics::Params params = fixtures::exactParams(1.0 / 60.0);
        params.method = method;
        params.order = PairOrder::Colored;
        params.epsilon = 2 * 9.81 * params.solverStep();
        params.mu = 0.9;
        physics::World world;
        fixtures::addBox(world, {2, 2, 2});
        for (int k = 0; k < 3; ++k) world.addSphere({0.2 * k, 0, 0.1}, {0.3, 0.2, 0}, 0.1, 1.0);
        run(world, params, 300);  // 5 s
        const physics::Diagnostics d = physics::measure(world, params);
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(glm::length(world.velocity[k]), 1e-3) << k;
            EXPECT_EQ(world.contactState[k], physics::ContactState::Static) << k;
        }
        EXPECT_LE(d.maxPenetration, 0.01);
        EXPECT_EQ(physics::step(world, params).candidatePairs, 2u) << "still side by side";
    }
}

// The pile of 1000 comes to rest in the colored order as in index order (the peer
// benchmark's kinetic energy column, one instant, once showed 0.0020 J a sphere for
// colored against 4.3e-6 for index: a sphere rolling off the edge then). The benchmark's
// steps, h = 1/240 s, K = 4; the median over every step from 3 to 5 s: index 1.4e-7 J a
// sphere, colored 1.6e-8 (measured).
TEST(ColoredOrder, ThePileComesToRestAsInIndexOrder) {
    const auto restingEnergy = [](const char* order) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));  // as shipped: 1000, mixed radii
        for (const char* setting : {"h=0.004166666666666667", "substeps=1", order}) {
            EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
        }
        physics::World world = scenes::buildWorld(scene);
        run(world, scene.params, 720);
        std::vector<double> kinetic;  // J a sphere, at each step from 3 to 5 s
        for (int k = 0; k < 480; ++k) {
            physics::step(world, scene.params);
            kinetic.push_back(physics::measure(world, scene.params).kinetic / double(world.size()));
        }
        std::nth_element(kinetic.begin(), kinetic.begin() + 240, kinetic.end());
        return kinetic[240];
    };
    const double index = restingEnergy("order=index"), colored = restingEnergy("order=colored");
    EXPECT_LT(index, 1e-6);
    EXPECT_LT(colored, 1e-6);
    EXPECT_LE(colored, 2.0 * index);
}

// The grid and the lecture's all-pairs loop find the same pairs in index order; coloured
// alike, they give the same state.
TEST(ColoredOrder, GridAndAllPairsReachTheSameState) {
    for (Method method : kMethods) {
        std::set<std::uint64_t> hashes;
        for (const char* broadPhase : {"broadphase=grid", "broadphase=allpairs"}) {
            const scenes::Scene scene = pile(600, 0.05, {"order=colored", broadPhase});
            physics::Params params = scene.params;
            params.method = method;
            physics::World world = scenes::buildWorld(scene);
            run(world, params, 90);
            hashes.insert(physics::stateHash(world));
        }
        EXPECT_EQ(hashes.size(), 1u);
    }
}

// The position based pair stage of one pass, one pair at a time in the colored order, as
// position_based.cpp does it: the reference for the lanes.
void separateOnePairAtATime(physics::World& world, const physics::Params& params, std::uint32_t first,
                            std::uint32_t last, physics::StepStats& stats, double factor) {
    for (std::uint32_t k = first; k < last; ++k) {
        const physics::SpherePair pair = world.workspace.visitOrder[k];
        physics::SphereContact contact;
        if (!physics::touching(world, pair, contact)) continue;
        physics::respondToContact(world, pair, contact, params, stats, 0);
        const physics::Separation moved =
            physics::separateSpheres(world.position[pair.i], world.position[pair.j], world.mass[pair.i],
                                     world.mass[pair.j], contact.u, factor * contact.depth, params.split);
        world.workspace.wallClearance[pair.i] -= moved.first;
        world.workspace.wallClearance[pair.j] -= moved.second;
    }
}

// Each lane width the CPU runs (2; 4 with AVX2; 8 with AVX-512) answers a pass of the
// landed pile with the one-pair code's numbers, bit for bit: velocities, positions,
// contact states, wall clearances and counts, for the lecture's response with the
// projection and for the momentum response, mass split and reflection.
TEST(ColoredOrder, EveryLaneWidthGivesTheOnePairNumbersBitForBit) {
    for (const bool lecture : {true, false}) {
        const scenes::Scene scene =
            lecture ? pile(5000, 0.025, {"order=colored"})
                    : pile(5000, 0.025, {"order=colored", "method=reflection", "response=momentum", "split=mass", "mu=0.7"});
        const physics::Params& params = scene.params;
        physics::World world = scenes::buildWorld(scene);
        if (!lecture) {  // masses of 1, 1.5 and 2 times the preset's: the mass split differs
            for (std::size_t i = 0; i < world.size(); ++i) world.mass[i] *= 1.0 + 0.5 * double(i % 3);
        }
        run(world, params, 60);
        // A solver step up to its passes (position_based.cpp), with a smaller epsilon so
        // that some contacts bounce.
        physics::Params sharper = params;
        sharper.epsilon = 0.002;
        physics::integrateVelocity(world, params, params.solverStep());
        physics::integratePosition(world, params, params.solverStep());
        physics::StepStats none;
        physics::findOrderedPairs(world, params, none);
        physics::findWallClearances(world, params);
        const double factor = params.method == Method::Reflection ? 1.0 + params.beta : 1.0;
        const physics::Workspace& ws = world.workspace;
        physics::World reference = world;
        physics::StepStats expected;
        separateOnePairAtATime(reference, sharper, 0, std::uint32_t(ws.visitOrder.size()), expected, factor);
        ASSERT_GT(expected.collisions, 0u);
        ASSERT_GT(expected.staticContacts, 0u);
        for (int width : physics::laneWidths()) {
            physics::World lanes = world;
            physics::StepStats stats;
            const auto visit = [&](physics::Range r) {
                const std::uint32_t rest = physics::separateColorInLanes(lanes, sharper, ws.visitOrder.data(), r.begin,
                                                                         r.end, stats, 0, factor, true, width);
                separateOnePairAtATime(lanes, sharper, rest, r.end, stats, factor);
                return r.end - rest;
            };
            for (std::uint32_t g = 0; g < physics::colorGroups(ws); ++g) {
                for (unsigned c = 0; c < physics::kGroupColors; ++c) {
                    EXPECT_LT(visit(physics::colorRange(ws, g, c)), std::uint32_t(width)) << "colour " << c;
                }
            }
            visit(physics::overflowRange(ws));
            EXPECT_EQ(physics::stateHash(lanes), physics::stateHash(reference)) << width << " lanes";
            EXPECT_EQ(lanes.workspace.wallClearance, reference.workspace.wallClearance) << width << " lanes";
            EXPECT_TRUE(lanes.contactState == reference.contactState) << width << " lanes";
            EXPECT_EQ(stats.collisions, expected.collisions);
            EXPECT_EQ(stats.staticContacts, expected.staticContacts);
            EXPECT_EQ(stats.sphereContacts, expected.sphereContacts);
        }
    }
}
