// Threads never change a result: the thread team runs every task once, the pairs
// shared out between threads wait for the pairs that met their spheres before, and
// every method and order reaches the same state, bit for bit, on 1, 2 or 3 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "physics/automatic_threads.h"
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

// The caller takes tasks from the first on, the workers from the last back, so that each
// thread keeps to the same end of a run's ranges from one run to the next (and its spheres'
// cache lines stay with its core): the caller's tasks are 0, 1, ... with none of the
// workers' among them. (Taken as they come, not by number: a caller slow to start, as when
// it woke the workers another test left asleep, may find every task taken.) Each task
// lasts about 20 us, long enough for both to take some in most runs on an idle machine.
TEST(ThreadTeam, TheCallerTakesTasksFromTheFirstAndTheWorkersFromTheLast) {
    int runsOfBoth = 0;
    for (int round = 0; round < 200; ++round) {
        constexpr int kTasks = 16;
        const std::thread::id caller = std::this_thread::get_id();
        std::vector<std::uint8_t> byCaller(kTasks, 0);
        physics::runTasks(2, kTasks, [&](int t) {
            byCaller[std::size_t(t)] = std::this_thread::get_id() == caller;
            const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
            while (std::chrono::steady_clock::now() < until) {
            }
        });
        const auto callersEnd = std::find(byCaller.begin(), byCaller.end(), 0);
        EXPECT_EQ(std::count(callersEnd, byCaller.end(), 1), 0) << "round " << round;
        runsOfBoth += callersEnd != byCaller.begin() && callersEnd != byCaller.end();
    }
    // (Not "in most runs": beside other tests on few cores, the worker may get no core.)
    EXPECT_GT(runsOfBoth, 0) << "the caller and a worker both took tasks in some run";
}

// Runs that ask for fewer threads than the team has leave some workers idle: a worker
// that wakes late for such a run must not take the next run's helper count for its own
// (it would count itself done twice: a run could return with a task unfinished, or the
// next one wait forever, which ctest's time limit turns into a failure).
TEST(ThreadTeam, EveryTaskHasEndedWhenARunReturnsWhileTheThreadCountChanges) {
    for (int round = 0; round < 3000; ++round) {
        const int threads = round % 2 == 0 ? 4 : 2;
        std::atomic<int> ended{0};
        physics::runTasks(threads, threads, [&](int) {
            volatile int work = 0;
            for (int k = 0; k < 2000; ++k) work = work + k;
            ++ended;
        });
        ASSERT_EQ(ended.load(), threads) << "round " << round;
    }
}

// The position method handles the walls last in every pass, so no sphere is left in a
// wall of the box after a step. Its wall stage visits only the spheres whose wall
// clearance has fallen to 0, so this holds only if every push of the pair stage, on
// any thread and in any pass, lowers the clearance of the sphere it moves.
TEST(SolverThreads, PositionMethodLeavesNoSphereInAWallOfTheBoxOnAnyThreadCount) {
    for (const char* threads : {"1", "2", "3"}) {
        const scenes::Scene scene = pile({"method=position", "passes=3", std::string("threads=") + threads});
        physics::World world = scenes::buildWorld(scene);
        ASSERT_EQ(world.boxPlaneCount, 6);
        double deepest = 0.0;  // m, into a wall of the box after a step
        for (int step = 0; step < 40; ++step) {
            physics::step(world, scene.params);
            for (std::uint32_t i = 0; i < world.size(); ++i) {
                for (int k = 0; k < world.boxPlaneCount; ++k) {
                    const physics::Plane& wall = world.planes[std::size_t(k)];
                    const double gap = glm::dot(world.position[i] - wall.point, wall.normal) - world.radius[i];
                    deepest = std::max(deepest, -gap);
                }
            }
        }
        EXPECT_LE(deepest, 1e-12) << threads << " threads";
    }
}

// Automatic threads (threads = 0) start where a second thread pays, 8192 spheres (on
// two cores, two threads gained nothing at 6k); a count set by hand applies from 4096
// spheres. (On a machine of one core, automatic is one thread at any count.)
TEST(SolverThreads, AutomaticThreadsStartWhereASecondThreadPays) {
    const int cores = std::min(physics::usableCores(), 8);
    const auto threadsAt = [](int count, const std::string& threads) {
        const scenes::Scene scene = pile({"radius=0.02", "count=" + std::to_string(count), "threads=" + threads});
        return physics::solverThreads(scenes::buildWorld(scene), scene.params);
    };
    EXPECT_EQ(threadsAt(6000, "0"), 1);
    EXPECT_EQ(threadsAt(8191, "0"), 1);
    EXPECT_EQ(threadsAt(8192, "0"), cores);
    EXPECT_EQ(threadsAt(4096, "2"), 2);
    EXPECT_EQ(threadsAt(4095, "2"), 1);
}

// A task watching another's word sleeps once its spin is over, and wakes when the
// word changes: also when it sleeps long before the change (20 ms, far beyond the
// spin), and not when the same value is stored again.
TEST(ThreadTeam, AWatcherWakesWhenTheWordChanges) {
    for (const int delayMs : {0, 20}) {
        physics::WatchedWord word;
        std::atomic<unsigned> seen{0};
        std::atomic<bool> woke{false};
        std::thread watcher([&] {
            seen = word.awaitChange(0, true);
            woke = true;
        });
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        word.store(0);
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        EXPECT_FALSE(woke.load()) << "woke while the word was unchanged";
        word.store(5);
        watcher.join();
        EXPECT_EQ(seen.load(), 5u);
    }
    physics::WatchedWord word;
    word.store(3);
    EXPECT_EQ(word.spinForChange(3, true), 3u) << "gives up after its spin";
    EXPECT_FALSE(word.compareExchange(2, 7));
    EXPECT_TRUE(word.compareExchange(3, 7));
    EXPECT_EQ(word.load(), 7u);
}

// A share whose thread never comes (another process has its core) is advanced by
// the thread that waits for it: here the caller alone finishes share 0, whose pair k
// needs pair k of share 1, and visits every pair after the pair it needs.
TEST(ThreadTeam, AThreadThatWaitsForAShareNobodyAdvancesAdvancesItItself) {
    constexpr std::uint32_t kPerShare = 100;
    physics::World world;
    physics::Workspace& ws = world.workspace;
    ws.sharedPairs.assign(2 * kPerShare, physics::SpherePair{});
    ws.shareStart = {0, kPerShare, 2 * kPerShare};
    ws.pairNeeds.assign(4 * kPerShare, physics::Workspace::PairNeed{});
    for (std::uint32_t k = 0; k < kPerShare; ++k) ws.pairNeeds[2 * k] = {1, k + 1};  // share 1 done >= k + 1
    std::vector<std::uint32_t> visited;
    const auto visit = [&](const physics::SpherePair*, std::uint32_t first, std::uint32_t last, physics::StepStats&) {
        for (std::uint32_t k = first; k < last; ++k) visited.push_back(k);
    };
    physics::SharedPass<decltype(visit)> pass(world, 2, visit);
    physics::StepStats stats;
    pass.finish(0, stats);  // no other thread: share 1 has nobody
    ASSERT_EQ(visited.size(), 2 * kPerShare) << "share 0, and all of share 1 that it needed";
    std::vector<std::size_t> at(2 * kPerShare);
    for (std::size_t n = 0; n < visited.size(); ++n) at[visited[n]] = n;
    for (std::uint32_t k = 0; k < kPerShare; ++k) {
        EXPECT_LT(at[kPerShare + k], at[k]) << "pair " << k << " of share 0 came before the pair it needs";
        if (k == 0) continue;
        EXPECT_LT(at[k - 1], at[k]) << "share 0 out of order";
        EXPECT_LT(at[kPerShare + k - 1], at[kPerShare + k]) << "share 1 out of order";
    }
    pass.finish(1, stats);  // already done: returns at once
    EXPECT_EQ(visited.size(), 2 * kPerShare);
}

// Automatic threads measure both counts and keep the faster. Fed wall times as a
// loaded machine gives them (one thread faster), then as a quiet one (two faster).
TEST(AutomaticThreads, GoesBackToOneThreadWhenTwoWereSlowerAndReturnsWhenTheyPayAgain) {
    using physics::AutomaticThreads;
    AutomaticThreads automatic;
    const auto runSteps = [&](int steps, double oneSeconds, double twoSeconds, std::map<int, int>& used) {
        for (int k = 0; k < steps; ++k) {
            automatic.next(2);
            const int threads = automatic.current();
            ++used[threads];
            automatic.record(threads, threads == 1 ? oneSeconds : twoSeconds);
        }
    };
    std::map<int, int> used;
    runSteps(AutomaticThreads::kFirstTry, 0.010, 0.030, used);
    EXPECT_EQ(used[2], AutomaticThreads::kFirstTry) << "the cores' count first";
    runSteps(AutomaticThreads::kSamples, 0.010, 0.030, used);
    EXPECT_EQ(used[1], AutomaticThreads::kSamples) << "then one thread, tried";
    EXPECT_EQ(automatic.current(), 1) << "one was faster: it stays";
    EXPECT_EQ(automatic.slowerCount(), 2) << "the readouts say 'threads: 1 (2 were slower)'";

    used.clear();
    runSteps(AutomaticThreads::kStepsBetweenTries + AutomaticThreads::kSamples, 0.010, 0.030, used);
    EXPECT_EQ(used[2], AutomaticThreads::kSamples) << "two tried again after kStepsBetweenTries steps";
    EXPECT_EQ(automatic.current(), 1) << "still slower: one stays";

    used.clear();
    runSteps(AutomaticThreads::kStepsBetweenTries + AutomaticThreads::kSamples, 0.010, 0.006, used);
    EXPECT_EQ(automatic.current(), 2) << "the load has gone: two are faster again";
    EXPECT_EQ(automatic.slowerCount(), 0);
    used.clear();
    runSteps(AutomaticThreads::kStepsBetweenTries + AutomaticThreads::kSamples, 0.010, 0.006, used);
    EXPECT_EQ(used[1], AutomaticThreads::kSamples) << "one thread tried now and then";
    EXPECT_EQ(automatic.current(), 2);
}

// A median, not a mean: one slow step of two threads (a rebuild of the pairs costs
// ten steps) just before one thread is tried does not make two look slower.
TEST(AutomaticThreads, OneSlowStepDoesNotDecide) {
    physics::AutomaticThreads automatic;
    int oneThreadSteps = 0;
    for (int step = 0; step < 110; ++step) {
        automatic.next(2);
        const int threads = automatic.current();
        oneThreadSteps += threads == 1;
        const double rebuild = step == physics::AutomaticThreads::kFirstTry - 3 ? 10.0 : 1.0;
        automatic.record(threads, (threads == 1 ? 0.010 : 0.006) * rebuild);
    }
    EXPECT_EQ(oneThreadSteps, physics::AutomaticThreads::kSamples) << "one thread was tried once";
    EXPECT_EQ(automatic.current(), 2);
    EXPECT_EQ(automatic.slowerCount(), 0);
}

// The pile of 5000 landing (1 s) in `method` and `order` reaches one state on 1, 2 and 3
// threads.
void expectTheSameStateOnAnyThreadCount(const char* method, const char* order) {
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
    EXPECT_GT(contacts, 2000u) << "the pile has landed";
}

// Each of the lecture's orders under every method (one test an order: the reversed order,
// the index order's code run backwards, is left to the plain build by the sanitized one).
TEST(SolverThreads, EveryMethodInIndexOrderReachesTheSameStateOnAnyThreadCount) {
    for (const char* method : {"position", "velocity", "response-only"}) expectTheSameStateOnAnyThreadCount(method, "index");
}
TEST(SolverThreads, EveryMethodInReversedOrderReachesTheSameStateOnAnyThreadCount) {
    for (const char* method : {"position", "velocity", "response-only"}) expectTheSameStateOnAnyThreadCount(method, "reversed");
}
TEST(SolverThreads, EveryMethodInShuffledOrderReachesTheSameStateOnAnyThreadCount) {
    for (const char* method : {"position", "velocity", "response-only"}) expectTheSameStateOnAnyThreadCount(method, "shuffled");
}

// The colored order (threads take blocks and colours, and never wait) and the reflection
// method (the position stages with their own response).
TEST(SolverThreads, TheColoredOrderAndReflectionReachTheSameStateOnAnyThreadCount) {
    for (const char* method : {"position", "velocity", "response-only", "reflection"}) {
        expectTheSameStateOnAnyThreadCount(method, "colored");
    }
    for (const char* order : {"index", "reversed", "shuffled"}) expectTheSameStateOnAnyThreadCount("reflection", order);
}

// Shock propagation shares out each level's spheres against the frozen level below (each
// moves only itself): the same state on 1, 2 and 3 threads, the pile of 5000 landing
// (1 s), under the position method (its widest level has over 1000 spheres: shared out)
// and the velocity method (whose levels are small then: one thread).
TEST(SolverThreads, ShockPropagationReachesTheSameStateOnAnyThreadCount) {
    for (const char* method : {"method=position", "method=velocity"}) {
        std::set<std::uint64_t> hashes;
        std::uint64_t widestLevel = 0;
        for (const char* threads : {"threads=1", "threads=2", "threads=3"}) {
            const physics::World world = run(pile({method, "shock=on", threads}), 60);
            hashes.insert(physics::stateHash(world));
            const std::vector<std::uint32_t>& starts = world.workspace.contactGraph.levelStart;
            for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
                widestLevel = std::max<std::uint64_t>(widestLevel, starts[k + 1] - starts[k]);
            }
        }
        EXPECT_EQ(hashes.size(), 1u) << method;
        if (std::string(method) == "method=position") {
            EXPECT_GT(widestLevel, 1000u) << "a level is shared out";
        }
    }
}

// Slide 14's global solvers share out whole clusters of touching spheres, each solved in a
// fixed order: the same state on any thread count. A gas of 5000 (small clusters, many;
// 0.5 s) under both, and the landing pile of 5000 (0.67 s, one big cluster) under lcp
// (generalized reflections take 30-50 s there).
TEST(SolverThreads, TheGlobalSolversReachTheSameStateOnAnyThreadCount) {
    struct Case {
        const char* preset;
        std::vector<std::string> settings;
        int steps;
    };
    const std::vector<Case> cases = {
        {"06_gas", {"count=5000", "radius=0.02", "solver=lcp"}, 30},
        {"06_gas", {"count=5000", "radius=0.02", "solver=generalized-reflections"}, 30},
        {"11_pile", {"count=5000", "radius=0.025", "solver=lcp"}, 40},
    };
    for (const Case& c : cases) {
        std::set<std::uint64_t> hashes;
        for (const char* threads : {"1", "2", "3"}) {
            scenes::Scene scene = scenes::loadScene(scenes::presetPath(c.preset));
            for (const std::string& setting : c.settings) ASSERT_EQ(scenes::applySetting(scene, setting), "");
            ASSERT_EQ(scenes::applySetting(scene, std::string("threads=") + threads), "");
            ASSERT_EQ(physics::solverThreads(scenes::buildWorld(scene), scene.params), std::atoi(threads));
            hashes.insert(physics::stateHash(run(scene, c.steps)));
        }
        EXPECT_EQ(hashes.size(), 1u) << c.preset << ", " << c.settings.back();
    }
}

// StepStats' profile: each method times its broad phase and its passes once per
// solver step, inside the step (together at most the step's wall time), on one thread
// and on two. (What it measures is not asserted: only that it is a part of the step.)
TEST(StepProfile, TheBroadPhaseAndThePassesArePartsOfTheStep) {
    for (const char* method : {"position", "velocity", "response-only"}) {
        for (const char* threads : {"1", "2"}) {
            const scenes::Scene scene = pile({std::string("method=") + method, std::string("threads=") + threads});
            physics::World world = run(scene, 30);  // landing: contacts to resolve
            const auto start = std::chrono::steady_clock::now();
            const physics::StepStats stats = physics::step(world, scene.params);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            EXPECT_GT(stats.broadPhaseSeconds, 0.0) << method << ", " << threads << " threads";
            EXPECT_GT(stats.passesSeconds, 0.0) << method << ", " << threads << " threads";
            EXPECT_LE(stats.broadPhaseSeconds + stats.passesSeconds, seconds) << method << ", " << threads << " threads";
        }
    }
}

TEST(SolverThreads, LoggedContactsAreTheSameOnAnyThreadCount) {
    std::vector<std::size_t> counts;
    std::set<std::uint64_t> hashes;
    for (const char* threads : {"1", "2"}) {
        const scenes::Scene scene = pile({std::string("threads=") + threads});
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

// Shared out between three threads, each thread has the pairs of its slab, in
// pass order, and waits where a sphere met another thread's pair last: for exactly
// that pair. Every pair of the pass order is in one share.
TEST(SharedPairs, WaitForThePairThatMetTheirSpheresBefore) {
    const physics::World landed = run(pile({}), 60);
    for (const char* order : {"index", "shuffled"}) {
        physics::World world = landed;
        // The velocity method: the position stages run their pairs by wavefronts instead.
        const physics::Params params = pile({std::string("order=") + order, "threads=3", "method=velocity"}).params;
        physics::StepStats stats;
        physics::findOrderedPairs(world, params, stats);
        const physics::Workspace& ws = world.workspace;
        ASSERT_EQ(ws.shareThreads, 3);
        ASSERT_EQ(ws.sharedPairs.size(), ws.visitOrder.size());
        ASSERT_GT(ws.visitOrder.size(), 5000u);

        // Where each pair of the pass order went: (thread, place in its share).
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> placeOf;
        for (std::uint32_t t = 0; t < 3; ++t) {
            EXPECT_GT(ws.shareStart[t + 1] - ws.shareStart[t], ws.visitOrder.size() / 6) << "thread " << t << " has work";
            for (std::uint32_t k = ws.shareStart[t]; k < ws.shareStart[t + 1]; ++k) {
                placeOf[{ws.sharedPairs[k].i, ws.sharedPairs[k].j}] = {t, k - ws.shareStart[t]};
            }
        }
        ASSERT_EQ(placeOf.size(), ws.visitOrder.size()) << "each pair in one share";
        std::vector<std::pair<std::uint32_t, std::uint32_t>> lastMet(world.size(), {~0u, 0});
        std::vector<std::uint32_t> doneInShare(3, 0);
        std::size_t waits = 0;
        for (const physics::SpherePair& pair : ws.visitOrder) {
            const auto [thread, place] = placeOf.at({pair.i, pair.j});
            ASSERT_EQ(place, doneInShare[thread]++) << "pass order within a share (" << order << ")";
            const std::uint32_t k = ws.shareStart[thread] + place;
            for (int side = 0; side < 2; ++side) {
                auto& last = lastMet[side == 0 ? pair.i : pair.j];
                const physics::Workspace::PairNeed need = ws.pairNeeds[2 * k + std::size_t(side)];
                if (last.first == ~0u || last.first == thread) {
                    EXPECT_EQ(need.done, 0u);
                } else {
                    EXPECT_EQ(need.thread, last.first);
                    EXPECT_EQ(need.done, last.second + 1);
                    ++waits;
                }
                last = {thread, place};
            }
        }
        EXPECT_GT(waits, 0u) << "slabs meet";
        EXPECT_LT(waits, ws.visitOrder.size() / 4) << "slabs meet only at their borders (" << order << ")";
    }
}

// How two threads share a world's pairs out: how often the thread changes from one
// first sphere's number to the next, and the fewest pairs a thread has.
struct ShareOut {
    std::size_t changes = 0;
    std::size_t fewestPairs = 0, pairs = 0;
};
ShareOut shareOutOf(physics::World world) {
    world.workspace = physics::Workspace{};
    const physics::Params params = pile({"threads=2", "method=velocity"}).params;  // as above
    physics::StepStats stats;
    physics::findOrderedPairs(world, params, stats);
    const physics::Workspace& ws = world.workspace;
    EXPECT_EQ(ws.shareThreads, 2);
    std::vector<int> threadOf(world.size(), -1);  // of each first sphere
    for (std::uint32_t t = 0; t < 2; ++t) {
        for (std::uint32_t k = ws.shareStart[t]; k < ws.shareStart[t + 1]; ++k) threadOf[ws.sharedPairs[k].i] = int(t);
    }
    ShareOut share;
    int last = -1;
    for (int t : threadOf) {
        if (t < 0) continue;
        share.changes += last >= 0 && t != last;
        last = t;
    }
    share.fewestPairs = std::min(ws.shareStart[1] - ws.shareStart[0], ws.shareStart[2] - ws.shareStart[1]);
    share.pairs = ws.visitOrder.size();
    return share;
}

// The share-out cuts the box across x or y, whichever cuts the runs of sphere numbers
// less, where each thread gets about half the spheres. The pile's lattice numbers its
// spheres row by row along x, so its shares are slabs of y, and with x and y swapped
// slabs of x. Either way the spheres whose pairs a thread takes come in long runs of
// numbers, broken mostly where the landing mixed the row on the border (about 190
// changes of thread in the landed pile); slabs across the rows change thread at every
// row as well (about 360), and the threads wait for each other as often. Also: a
// lattice of 32 spheres a row (a count of changes taken at every fourth number saw
// none, on either axis), a sphere flung far along y (slabs of equal width left the
// other thread nothing), and every centre at x = 0 (slabs of x: no change, one thread).
TEST(SharedPairs, EachThreadTakesLongRunsOfSphereNumbers) {
    const physics::World landed = run(pile({}), 60);
    physics::World swapped = landed, flung = landed, flat = landed;
    for (glm::dvec3& p : swapped.position) std::swap(p.x, p.y);  // the box is square in x and y
    flung.position[0].y = 50.0;                                     // m, far outside the box
    for (glm::dvec3& p : flat.position) p.x = 0.0;                  // one slab of x holds all
    const std::pair<const char*, physics::World> worlds[] = {
        {"landed", landed},
        {"x and y swapped", swapped},
        {"32 a row", scenes::buildWorld(pile({"radius=0.0275"}))},
        {"one sphere flung", flung},
        {"every x at 0", flat},
    };
    for (const auto& [how, world] : worlds) {
        const ShareOut share = shareOutOf(world);
        EXPECT_LT(share.changes, world.size() / 20) << how;
        EXPECT_GT(share.changes, 2u) << how << ": both threads have pairs all along the numbers";
        EXPECT_GT(share.pairs, world.size()) << how;
        EXPECT_GT(share.fewestPairs, share.pairs / 4) << how;
    }
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

// The movers (step.cpp): a sphere that moved past the cached pairs' skin has its pairs
// found anew from the last build's grid, the others' filtered. A pile of 5000 coming to
// rest (few spheres still move) and another struck by a fast sphere: at every step the
// same state as a fresh build, and the movers' path served steps on its own.
TEST(SolverCache, FindingOnlyTheMoversPairsChangesNoState) {
    const scenes::Scene scene = pile({});
    const physics::World landed = run(scene, 300);  // 5 s: landed, a few still rolling
    for (const bool struck : {false, true}) {
        physics::World cached = landed;
        if (struck) cached.addSphere({-1.0, 0.0, 0.3}, {8.0, 0.0, 0.0}, 0.025, 0.1);
        physics::World fresh = cached;
        int servedByMovers = 0;
        for (int k = 0; k < 60; ++k) {
            const physics::StepStats stats = physics::step(cached, scene.params);
            servedByMovers += stats.broadPhaseBuilds == 0 && !cached.workspace.movers.empty();
            fresh.workspace = physics::Workspace{};
            physics::step(fresh, scene.params);
            ASSERT_EQ(physics::stateHash(cached), physics::stateHash(fresh)) << "step " << k << (struck ? ", struck" : "");
        }
        EXPECT_GT(servedByMovers, 0) << (struck ? "struck" : "at rest");
    }
}
