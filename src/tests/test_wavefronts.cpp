// The lecture's pair orders run wavefront by wavefront (wavefronts.cpp): the wavefronts
// themselves, and the pass order's state, bit for bit, from the position stages that run
// them several pairs side by side and on threads.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/solver_stages.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace {

// The pile preset (1000 spheres) after "name=value" settings.
scenes::Scene pile(std::initializer_list<std::string> settings) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
    return scene;
}

}  // namespace

// No two pairs of a wavefront share a sphere, and each sphere meets its pairs in pass
// order: a pair's wavefront is later than those of its spheres' earlier pairs. On
// several threads, a wavefront's pairs go by strips across the pile.
TEST(Wavefronts, NoTwoPairsOfAWavefrontShareASphereAndEachSphereMeetsItsPairsInPassOrder) {
    for (const auto& [order, threads] : std::vector<std::pair<const char*, int>>{
             {"index", 1}, {"reversed", 1}, {"shuffled", 1}, {"index", 2}, {"reversed", 2}, {"shuffled", 2}}) {
        const scenes::Scene scene = pile({std::string("order=") + order});
        physics::World world = scenes::buildWorld(scene);
        for (int k = 0; k < 90; ++k) physics::step(world, scene.params);  // 1.5 s: landing
        physics::StepStats stats;
        physics::findOrderedPairs(world, scene.params, stats);
        ASSERT_TRUE(physics::passesByWavefronts(world, scene.params) || physics::laneWidths().back() < 4);
        physics::findWavefronts(world, threads);
        const physics::Workspace& ws = world.workspace;
        if (threads > 1) {
            ASSERT_EQ(ws.wavefrontStrips.ofSphere.size(), world.size());
            for (std::size_t w = 0; w + 1 < ws.wavefrontStart.size(); ++w) {
                for (std::uint32_t k = ws.wavefrontStart[w]; k + 1 < ws.wavefrontStart[w + 1]; ++k) {
                    EXPECT_LE(ws.wavefrontStrips.ofSphere[ws.wavefrontOrder[k].i], ws.wavefrontStrips.ofSphere[ws.wavefrontOrder[k + 1].i])
                        << order << ": wavefront " << w;
                }
            }
            const std::set<std::uint8_t> strips(ws.wavefrontStrips.ofSphere.begin(), ws.wavefrontStrips.ofSphere.end());
            EXPECT_GE(strips.size(), 8u) << order;
        }
        ASSERT_EQ(ws.wavefrontOrder.size(), ws.visitOrder.size());
        ASSERT_GT(ws.wavefrontStart.size(), 10u) << order;
        std::vector<int> wavefrontOf(ws.visitOrder.size());
        std::vector<int> lastWavefront(world.size(), -1);  // of each sphere's latest pair in pass order
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> wavefrontOfPair;
        for (std::size_t w = 0; w + 1 < ws.wavefrontStart.size(); ++w) {
            std::vector<bool> met(world.size(), false);
            for (std::uint32_t k = ws.wavefrontStart[w]; k < ws.wavefrontStart[w + 1]; ++k) {
                const physics::SpherePair pair = ws.wavefrontOrder[k];
                EXPECT_FALSE(met[pair.i] || met[pair.j]) << order << ": wavefront " << w;
                met[pair.i] = met[pair.j] = true;
                wavefrontOfPair[{pair.i, pair.j}] = int(w);
            }
        }
        ASSERT_EQ(wavefrontOfPair.size(), ws.visitOrder.size()) << "each pair once";
        for (const physics::SpherePair& pair : ws.visitOrder) {
            const int w = wavefrontOfPair.at({pair.i, pair.j});
            EXPECT_GT(w, lastWavefront[pair.i]) << order;
            EXPECT_GT(w, lastWavefront[pair.j]) << order;
            lastWavefront[pair.i] = lastWavefront[pair.j] = w;
        }
    }
}

// The strips go across the axis that splitCost (wavefronts.cpp) finds cheapest: on a
// lattice numbered along one axis, then a second, then the third, the second. Across the
// first, the spheres of a cache line would be on both threads; across the third, a band of
// numbers (as a wavefront is) would lie in a strip or two. 16 strips, all used.
TEST(Wavefronts, StripsGoAcrossTheAxisAlongWhichNumbersMoveNeitherFastestNorSlowest) {
    constexpr int kSide = 24;
    for (const glm::ivec3 axes : {glm::ivec3(0, 1, 2), glm::ivec3(1, 2, 0), glm::ivec3(2, 0, 1)}) {
        physics::World world;
        for (int slow = 0; slow < kSide; ++slow) {
            for (int middle = 0; middle < kSide; ++middle) {
                for (int fast = 0; fast < kSide; ++fast) {
                    glm::dvec3 p;
                    p[axes[0]] = 0.1 * fast, p[axes[1]] = 0.1 * middle, p[axes[2]] = 0.1 * slow;
                    world.addSphere(p, glm::dvec3(0.0), 0.05, 1.0);
                }
            }
        }
        physics::findWavefronts(world, 2);  // no pairs: the strips only
        const std::vector<std::uint8_t>& strip = world.workspace.wavefrontStrips.ofSphere;
        ASSERT_EQ(strip.size(), world.size());
        std::set<std::uint8_t> used;
        for (std::size_t i = 0; i < world.size(); ++i) {
            const int middle = int(std::lround(world.position[i][axes[1]] / 0.1));
            EXPECT_EQ(strip[i], strip[std::size_t(middle) * kSide]) << "numbered along " << axes[0] << ", sphere " << i;
            used.insert(strip[i]);
        }
        EXPECT_EQ(used.size(), 16u) << "numbered along " << axes[0];
    }
}

// Position based and reflection in the lecture's orders (and passes until converged), by
// wavefronts on one and two threads, against one pair at a time in pass order (a contact
// log turns the wavefronts off): the same state after every step.
TEST(Wavefronts, TheLecturesOrdersReachTheStateOfOnePairAtATime) {
    const std::vector<std::vector<std::string>> cases = {
        {"method=position", "order=index"},    {"method=position", "order=reversed"},
        {"method=position", "order=shuffled"}, {"method=reflection", "order=index"},
        {"method=reflection", "order=reversed"}, {"method=reflection", "order=shuffled"},
        {"method=position", "order=index", "solver=until-converged", "passes=20"}};
    for (const std::vector<std::string>& settings : cases) {
        for (const char* threads : {"1", "2"}) {
            scenes::Scene scene = pile({"count=5000", "radius=0.029", std::string("threads=") + threads});
            for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
            physics::World wavefronts = scenes::buildWorld(scene), onePair = wavefronts;
            onePair.recordContacts = true;
            for (int k = 0; k < 40; ++k) {
                physics::step(wavefronts, scene.params);
                physics::step(onePair, scene.params);
                onePair.contacts.clear();
                ASSERT_EQ(physics::stateHash(wavefronts), physics::stateHash(onePair))
                    << settings[0] << ", " << settings[1] << (settings.size() > 2 ? ", " + settings[2] : "") << ", "
                    << threads << " threads, step " << k;
            }
            EXPECT_EQ(physics::passesByWavefronts(wavefronts, scene.params), physics::laneWidths().back() >= 4);
            if (std::string(threads) == "2" && physics::passesByWavefronts(wavefronts, scene.params)) {
                // the strips found at an earlier step served (wavefronts.cpp)
                EXPECT_LT(wavefronts.workspace.wavefrontStrips.foundAtStep + 1, wavefronts.stepCount);
            }
        }
    }
}

// The strips only share a pass's wavefronts between threads: whichever strip a sphere is
// placed in (they are kept for some steps while the spheres move), the state is that of one
// thread. Each step here places every sphere in a strip at random, in the lecture's index
// order (wavefronts, where the CPU has lanes of 4) and in the colored order's border.
TEST(Wavefronts, WhicheverStripASphereIsPlacedInTheStateIsThatOfOneThread) {
    for (const char* order : {"order=index", "order=colored"}) {
        physics::World one = scenes::buildWorld(pile({"count=5000", "radius=0.029", order, "threads=1"}));
        const scenes::Scene two = pile({"count=5000", "radius=0.029", order, "threads=2"});
        physics::World scrambled = scenes::buildWorld(two);
        const physics::Params oneParams = pile({"count=5000", "radius=0.029", order, "threads=1"}).params;
        std::uint64_t placed = 0;
        for (int k = 0; k < 30; ++k) {
            physics::Workspace::WavefrontStrips& strips = scrambled.workspace.wavefrontStrips;
            strips.count = 16;  // two threads' (kStripsPerThread 8 a thread)
            strips.foundAtStep = scrambled.stepCount;
            strips.ofSphere.resize(scrambled.size());
            for (std::size_t i = 0; i < scrambled.size(); ++i) {
                strips.ofSphere[i] = std::uint8_t((i * 2654435761u + std::uint64_t(k) * 40503u) >> 7 & 15u);
            }
            physics::step(scrambled, two.params);
            physics::step(one, oneParams);
            placed += scrambled.workspace.wavefrontStrips.threads == 2;
            ASSERT_EQ(physics::stateHash(scrambled), physics::stateHash(one)) << order << ", step " << k;
        }
        if (std::string(order) == "order=colored" || physics::laneWidths().back() >= 4) {
            EXPECT_EQ(placed, 30u) << order << ": the passes went by strips";
        }
    }
}

// The colored order on two threads: its border group (the pairs between blocks, here of
// sphere numbers: 39 % of them in this pile at 1.5 s) goes by wavefronts, each sphere
// meeting its border pairs in the colours' order; on one thread it goes colour by colour.
TEST(Wavefronts, TheColoredOrdersBorderGoesByWavefrontsOnSeveralThreads) {
    for (const char* threads : {"2", "1"}) {
        const scenes::Scene scene = pile({"count=10000", "radius=0.0232", "order=colored", std::string("threads=") + threads});
        physics::World world = scenes::buildWorld(scene);
        for (int k = 0; k < 90; ++k) physics::step(world, scene.params);  // 1.5 s: landed
        const physics::Workspace& ws = world.workspace;
        if (std::string(threads) == "1") {
            EXPECT_FALSE(ws.borderByWavefronts);
            continue;
        }
        ASSERT_TRUE(ws.borderByWavefronts);
        const std::uint32_t border = physics::colorGroups(ws) - 1;
        const std::uint32_t first = physics::colorRange(ws, border, 0).begin;
        const std::uint32_t end = physics::colorRange(ws, border, physics::kGroupColors - 1).end;
        ASSERT_GT(end - first, ws.visitOrder.size() / 4) << "pairs between blocks (39 % measured)";
        ASSERT_EQ(ws.wavefrontOrder.size(), end - first);
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> wavefrontOf;
        for (std::size_t w = 0; w + 1 < ws.wavefrontStart.size(); ++w) {
            std::set<std::uint32_t> met;
            for (std::uint32_t k = ws.wavefrontStart[w]; k < ws.wavefrontStart[w + 1]; ++k) {
                const physics::SpherePair pair = ws.wavefrontOrder[k];
                EXPECT_TRUE(met.insert(pair.i).second && met.insert(pair.j).second) << "wavefront " << w;
                wavefrontOf[{pair.i, pair.j}] = int(w);
            }
        }
        std::vector<int> last(world.size(), -1);  // the wavefront of each sphere's last border pair
        for (std::uint32_t k = first; k < end; ++k) {
            const physics::SpherePair pair = ws.visitOrder[k];
            ASSERT_EQ(wavefrontOf.count({pair.i, pair.j}), 1u);
            const int w = wavefrontOf[{pair.i, pair.j}];
            EXPECT_GT(w, last[pair.i]);
            EXPECT_GT(w, last[pair.j]);
            last[pair.i] = last[pair.j] = w;
        }
    }
}

namespace {

// A world whose workspace holds `wavefronts` wavefronts over `strips` strips, with
// pairsPerStrip[s] pairs in strip s of each wavefront (the pairs themselves unused), and
// the given span.
physics::World stripsOnly(std::uint32_t wavefronts, const std::vector<std::uint32_t>& pairsPerStrip,
                          std::uint32_t span) {
    physics::World world;
    physics::Workspace& ws = world.workspace;
    physics::Workspace::WavefrontStrips& strips = ws.wavefrontStrips;
    strips.count = std::uint32_t(pairsPerStrip.size());
    strips.span = span;
    strips.start = {0};
    ws.wavefrontStart = {0};
    for (std::uint32_t w = 0; w < wavefronts; ++w) {
        for (const std::uint32_t pairs : pairsPerStrip) strips.start.push_back(strips.start.back() + pairs);
        ws.wavefrontStart.push_back(strips.start.back());
    }
    ws.wavefrontOrder.assign(strips.start.back(), physics::SpherePair{});
    return world;
}

}  // namespace

// The strip pass cuts the strips into runs of about as many pairs each, and makes the
// shares whose strips come within 2 x span of each other neighbours (two pairs that share
// a sphere have first spheres that near).
TEST(StripPass, CutsTheStripsByTheirPairsAndWaitsOnlyForSharesWithinReach) {
    const auto visit = [](const physics::SpherePair*, std::uint32_t, std::uint32_t, physics::StepStats&) {};
    {
        const physics::World world = stripsOnly(3, {9, 1, 1, 1, 1, 1, 1, 1}, 1);  // 16 pairs a wavefront
        const physics::StripPass<decltype(visit)> pass(world, 2, visit);
        EXPECT_EQ(pass.stripsOf(0).begin, 0u);
        EXPECT_EQ(pass.stripsOf(0).end, 1u) << "strip 0 holds the middle pair";
        EXPECT_EQ(pass.stripsOf(1).end, 8u);
    }
    for (const std::uint32_t span : {1u, 2u, 3u}) {
        const physics::World world = stripsOnly(2, std::vector<std::uint32_t>(16, 5), span);
        const physics::StripPass<decltype(visit)> pass(world, 4, visit);  // 4 strips each
        for (std::uint32_t s = 0; s < 4; ++s) {
            EXPECT_EQ(pass.stripsOf(s).begin, 4 * s);
            EXPECT_EQ(pass.stripsOf(s).end, 4 * s + 4);
        }
        // Shares 0 and 1 are 1 strip apart (their nearest strips), 0 and 2 five, 0 and 3 nine.
        EXPECT_EQ(pass.neighboursOf(0), span == 3 ? 0b0110u : 0b0010u) << "span " << span;
        EXPECT_EQ(pass.neighboursOf(1), span == 3 ? 0b1101u : 0b0101u) << "span " << span;
    }
}

// Alone, a thread that finishes its share advances the other share as far as its own
// needs (all but its last wavefront), then its own: each share's wavefronts in order, and each wavefront after the
// neighbour's wavefront before it.
TEST(StripPass, AThreadThatWaitsForAShareNobodyAdvancesAdvancesItItself) {
    constexpr std::uint32_t kWavefronts = 4;
    const physics::World world = stripsOnly(kWavefronts, {1, 1, 1, 1}, 1);  // two strips a share
    std::vector<std::pair<std::uint32_t, std::uint32_t>> visited;               // (share, wavefront)
    const auto visit = [&](const physics::SpherePair*, std::uint32_t first, std::uint32_t last, physics::StepStats&) {
        ASSERT_EQ(last - first, 2u);
        visited.push_back({first % 4 / 2, first / 4});
    };
    physics::StripPass<decltype(visit)> pass(world, 2, visit);
    physics::StepStats stats;
    pass.finish(0, stats);  // no other thread: share 1 has nobody
    ASSERT_EQ(visited.size(), 2 * kWavefronts - 1) << "share 0, and all of share 1 that it needed: all but the last";
    pass.finish(1, stats);
    ASSERT_EQ(visited.size(), 2 * kWavefronts);
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> at;  // the n-th visit
    for (std::size_t n = 0; n < visited.size(); ++n) at[visited[n]] = n;
    ASSERT_EQ(at.size(), visited.size()) << "each once";
    const auto when = [&](std::uint32_t share, std::uint32_t w) { return at[std::make_pair(share, w)]; };
    for (std::uint32_t w = 1; w < kWavefronts; ++w) {
        for (const std::uint32_t s : {0u, 1u}) {
            EXPECT_LT(when(s, w - 1), when(s, w)) << "share " << s << " out of order";
            EXPECT_LT(when(1 - s, w - 1), when(s, w)) << "share " << s << "'s wavefront " << w << " before its neighbour's last";
        }
    }
    pass.finish(0, stats);  // already done: returns at once
    EXPECT_EQ(visited.size(), 2 * kWavefronts);
}
