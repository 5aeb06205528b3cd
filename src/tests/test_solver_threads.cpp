// Threads never change a result: the thread team runs every task once, the slab
// order keeps spheres of concurrent groups apart, and every method reaches the
// same state, bit for bit, on 1, 2 or 3 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <set>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/solver_stages.h"
#include "physics/step.h"
#include "physics/thread_team.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace {

using physics::Method;
using physics::PairOrder;

// The pile preset with 5000 spheres of 2.5 cm (above the solver's threshold for
// threads), after "name=value" settings.
scenes::Scene pile(std::initializer_list<std::string> settings) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    EXPECT_EQ(scenes::applySetting(scene, "count=5000"), "");
    EXPECT_EQ(scenes::applySetting(scene, "radius=0.025"), "");
    for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "");
    return scene;
}

physics::World run(const scenes::Scene& scene, int steps) {
    physics::World world = scenes::buildWorld(scene);
    for (int k = 0; k < steps; ++k) physics::step(world, scene.params);
    return world;
}

TEST(ThreadTeam, RunsEveryTaskExactlyOnce) {
    for (int threads : {2, 3, 5}) {
        for (int tasks : {1, 2, 3, 7, 64}) {
            for (int round = 0; round < 50; ++round) {
                std::vector<std::atomic<int>> runs(static_cast<std::size_t>(tasks));
                physics::runTasks(threads, tasks, [&](int t) { ++runs[static_cast<std::size_t>(t)]; });
                for (int t = 0; t < tasks; ++t) {
                    ASSERT_EQ(runs[static_cast<std::size_t>(t)].load(), 1)
                        << "task " << t << " of " << tasks << ", " << threads << " threads";
                }
            }
        }
    }
}

TEST(SolverThreads, EveryMethodAndOrderReachesTheSameStateOnAnyThreadCount) {
    for (const char* method : {"position", "velocity", "response-only"}) {
        for (const char* order : {"index", "slabs", "shuffled"}) {
            std::set<std::uint64_t> hashes;
            std::uint64_t contacts = 0;
            for (const char* threads : {"1", "2", "3"}) {
                const scenes::Scene scene = pile({std::string("method=") + method, std::string("order=") + order,
                                                  std::string("threads=") + threads});
                ASSERT_EQ(physics::solverThreads(scenes::buildWorld(scene), scene.params), std::atoi(threads));
                const physics::World world = run(scene, 60);  // 1 s: falling and landing
                hashes.insert(physics::stateHash(world));
                contacts = physics::measure(world, scene.params).sphereContacts;
            }
            EXPECT_EQ(hashes.size(), 1u) << method << ", " << order;
            EXPECT_GT(contacts, 2500u) << "the pile has landed";
        }
    }
}

TEST(SolverThreads, LoggedContactsAreTheSameOnAnyThreadCount) {
    std::vector<std::size_t> counts;
    std::set<std::uint64_t> hashes;
    for (const char* threads : {"1", "2"}) {
        const scenes::Scene scene = pile({"order=slabs", std::string("threads=") + threads});
        physics::World world = scenes::buildWorld(scene);
        world.recordContacts = true;
        for (int k = 0; k < 60; ++k) physics::step(world, scene.params);
        counts.push_back(world.contacts.size());
        hashes.insert(physics::stateHash(world));
    }
    EXPECT_GT(counts[0], 0u);
    EXPECT_EQ(counts[0], counts[1]);
    EXPECT_EQ(hashes.size(), 1u);
}

// The slab order visits the pairs of the index order, regrouped: the groups of one
// parity (even slabs, then odd ones) share no sphere.
TEST(SlabOrder, VisitsTheIndexOrderPairsInGroupsThatShareNoSphere) {
    const physics::World landed = run(pile({}), 60);
    physics::World byIndex = landed, bySlabs = landed;
    physics::Params params = pile({}).params;
    physics::StepStats stats;
    physics::findOrderedPairs(byIndex, params, stats);
    params.order = PairOrder::Slabs;
    physics::findOrderedPairs(bySlabs, params, stats);

    const physics::Workspace& ws = bySlabs.workspace;
    std::vector<physics::SpherePair> regrouped = ws.visitOrder;
    const auto byIj = [](const physics::SpherePair& a, const physics::SpherePair& b) {
        return a.i != b.i ? a.i < b.i : a.j < b.j;
    };
    std::sort(regrouped.begin(), regrouped.end(), byIj);
    ASSERT_EQ(regrouped.size(), byIndex.workspace.visitOrder.size());
    EXPECT_GT(regrouped.size(), 5000u);
    for (std::size_t k = 0; k < regrouped.size(); ++k) {
        ASSERT_EQ(regrouped[k].i, byIndex.workspace.visitOrder[k].i);
        ASSERT_EQ(regrouped[k].j, byIndex.workspace.visitOrder[k].j);
    }

    const std::size_t groups = ws.groupStart.size() - 1;
    ASSERT_GT(groups, 2u);
    int busyGroups = 0;
    for (const auto& [first, last] : {std::pair{std::size_t(0), ws.firstOddGroup}, std::pair{ws.firstOddGroup, groups}}) {
        std::vector<int> groupOf(landed.size(), -1);  // which group of this parity touched the sphere
        for (std::size_t g = first; g < last; ++g) {
            busyGroups += ws.groupStart[g + 1] > ws.groupStart[g];
            for (std::uint32_t k = ws.groupStart[g]; k < ws.groupStart[g + 1]; ++k) {
                for (std::uint32_t sphere : {ws.visitOrder[k].i, ws.visitOrder[k].j}) {
                    int& owner = groupOf[sphere];
                    ASSERT_TRUE(owner == -1 || owner == int(g)) << "sphere " << sphere << " in groups " << owner << " and " << g;
                    owner = int(g);
                }
                if (k > ws.groupStart[g]) {
                    ASSERT_TRUE(byIj(ws.visitOrder[k - 1], ws.visitOrder[k])) << "index order in a group";
                }
            }
        }
    }
    EXPECT_GE(busyGroups, 8) << "the pile spans several slabs";
}

// The slab order is another order of the same passes: the pile stays in its box
// and overlaps no more than in index order.
TEST(SlabOrder, KeepsThePileInItsBoxAsTheIndexOrderDoes) {
    const scenes::Scene byIndex = pile({}), bySlabs = pile({"order=slabs", "threads=2"});
    const physics::World a = run(byIndex, 180), b = run(bySlabs, 180);
    EXPECT_EQ(physics::spheresOutsideBox(b, 0.0), 0u);
    const double indexPenetration = physics::measure(a, byIndex.params).maxPenetration;
    const double slabPenetration = physics::measure(b, bySlabs.params).maxPenetration;
    EXPECT_LT(slabPenetration, std::max(0.05, 2.0 * indexPenetration));
    EXPECT_NE(physics::stateHash(a), physics::stateHash(b)) << "another order, another (valid) result";
}

// Fresh builds with the skin at every step (as after a rewind) give the states of
// the adaptive cache, which builds without the skin while the pile jitters.
TEST(SolverCache, BuildingWithoutTheSkinChangesNoState) {
    const scenes::Scene scene = pile({});
    physics::World adaptive = scenes::buildWorld(scene), fresh = adaptive;
    std::uint64_t builds = 0;
    int mostBuildsNotReused = 0;
    for (int k = 0; k < 120; ++k) {
        builds += physics::step(adaptive, scene.params).broadPhaseBuilds;
        mostBuildsNotReused = std::max(mostBuildsNotReused, adaptive.workspace.buildsNotReused);
        fresh.workspace = physics::Workspace{};
        physics::step(fresh, scene.params);
        ASSERT_EQ(physics::stateHash(adaptive), physics::stateHash(fresh)) << "step " << k;
    }
    EXPECT_GT(builds, 0u);
    EXPECT_GE(mostBuildsNotReused, 3) << "the landing pile built without the skin";
}

}  // namespace
