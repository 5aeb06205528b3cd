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
            ASSERT_EQ(ws.wavefrontStrip.size(), world.size());
            for (std::size_t w = 0; w + 1 < ws.wavefrontStart.size(); ++w) {
                for (std::uint32_t k = ws.wavefrontStart[w]; k + 1 < ws.wavefrontStart[w + 1]; ++k) {
                    EXPECT_LE(ws.wavefrontStrip[ws.wavefrontOrder[k].i], ws.wavefrontStrip[ws.wavefrontOrder[k + 1].i])
                        << order << ": wavefront " << w;
                }
            }
            const std::set<std::uint8_t> strips(ws.wavefrontStrip.begin(), ws.wavefrontStrip.end());
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
        const std::vector<std::uint8_t>& strip = world.workspace.wavefrontStrip;
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
            scenes::Scene scene = pile({"count=10000", "radius=0.0232", std::string("threads=") + threads});
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
        }
    }
}
