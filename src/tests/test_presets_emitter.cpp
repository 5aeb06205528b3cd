// The scene keys the presets needed: the course's emitter ("emitters", the
// emit_period parameter, scenes::emitDue) and thin walls ("thickness" on a plane).
#include <gtest/gtest.h>

#include "scene_error_checks.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/scene_json.h"

namespace {

using scenes::Scene;

void stepAndEmit(const Scene& scene, physics::World& world, int steps) {
    for (int k = 0; k < steps; ++k) {
        physics::step(world, scene.params);
        scenes::emitDue(scene, world);
    }
}

// A box without gravity and one emitter shooting along +x.
Scene shooter(double period, int max) {
    return scenes::parseScene(R"({
  "box": {"size": [2, 2, 2]},
  "parameters": {"gravity": 0},
  "emitters": [{"period": )" + std::to_string(period) +
                                  R"(, "position": [-0.8, 0, 1], "velocity": [2, 0, 0],
                "radius": 0.05, "max": )" +
                                  std::to_string(max) + R"(}]
})",
                              "shooter.json");
}

// --- reading ---

TEST(Emitters, ReadsEveryKey) {
    const Scene s = scenes::parseScene(R"({
  "box": {"size": [2, 2, 2]},
  "seed": 5,
  "emitters": [{"period": 0.25, "position": [0, 0, 1.5], "velocity": [0, 0, -1], "spread": 0.3,
                "radius": [0.03, 0.05], "mass": 0.2, "max": 40, "emitted": 3},
               {"period": 1, "position": [0.5, 0, 1.5]}]
})",
                                       "good.json");
    ASSERT_EQ(s.emitters.size(), 2u);
    const scenes::Emitter& e = s.emitters[0];
    EXPECT_EQ(e.period, 0.25);
    EXPECT_EQ(e.position, glm::dvec3(0, 0, 1.5));
    EXPECT_EQ(e.velocity, glm::dvec3(0, 0, -1));
    EXPECT_EQ(e.spread, 0.3);
    EXPECT_EQ(e.radiusMin, 0.03);
    EXPECT_EQ(e.radiusMax, 0.05);
    EXPECT_EQ(e.massRule, scenes::MassRule::Fixed);
    EXPECT_EQ(e.mass, 0.2);
    EXPECT_EQ(e.max, 40);
    EXPECT_EQ(e.emitted, 3);
    const scenes::Emitter defaults;
    EXPECT_EQ(s.emitters[1].velocity, defaults.velocity);
    EXPECT_EQ(s.emitters[1].radiusMax, defaults.radiusMax);
    EXPECT_EQ(s.emitters[1].density, defaults.density);
    EXPECT_EQ(s.emitters[1].max, defaults.max);
    EXPECT_EQ(s.emitters[1].emitted, 0);
    EXPECT_EQ(scenes::buildWorld(s).size(), 0u);  // emitters add spheres only as time passes
}

TEST(Emitters, EmitPeriodSetsTheFirstEmitterAndNeedsOne) {
    Scene s = scenes::parseScene(R"({"box": {}, "parameters": {"emit_period": 2},
  "emitters": [{"period": 0.5, "position": [0, 0, 1]}, {"period": 0.5, "position": [0.5, 0, 1]}]})",
                                 "good.json");
    EXPECT_EQ(s.emitters[0].period, 2.0);  // the parameter wins over the emitter's own period
    EXPECT_EQ(s.emitters[1].period, 0.5);
    const scenes::Parameter& p = *scenes::findParameter("emit_period");
    EXPECT_EQ(p.applies, scenes::Applies::Live);
    EXPECT_EQ(p.unit, "s");
    EXPECT_TRUE(contains(std::string(p.tooltip), "course's emitter"));
    EXPECT_EQ(p.get(s), 2.0);
    EXPECT_EQ(scenes::applySetting(s, "emit_period=0.1"), "");
    EXPECT_EQ(s.emitters[0].period, 0.1);
    expectError("{\n  \"parameters\": {\"emit_period\": 1}\n}", "2:33", {"scene has no emitter"});
}

TEST(Emitters, RefusesBadEmittersAtTheirLine) {
    expectError("{\"emitters\": [{\"position\": [0, 0, 1]}]}", "1:15",
                {"emitters[0] needs \"period\""});
    expectError("{\"emitters\": [{\"period\": 1}]}", "1:15", {"emitters[0] needs \"position\""});
    expectError("{\"emitters\": [\n  {\"period\": 0, \"position\": [0, 0, 1]}]}", "2:14",
                {"emitters[0].period = 0 is out of range [0.01, 60]"});
    expectError("{\"emitters\": [{\"period\": 1, \"position\": [0, 0, 1], \"rate\": 3}]}", "1:52",
                {"unknown key 'rate'", "emitters[0]"});
    expectError("{\"emitters\": [{\"period\": 1, \"position\": [0, 0, 1], \"spread\": -1}]}",
                "1:62", {"emitters[0].spread = -1 must be >= 0 (m/s)"});
    expectError(
        "{\"emitters\": [{\"period\": 1, \"position\": [0, 0, 1], \"max\": 2, \"emitted\": 3}]}",
        "1:73", {"emitters[0].emitted = 3 is out of range [0, 2]"});
    expectError("{\"emitters\": [{\"period\": 1, \"position\": [0, 0, 1], \"max\": 1.5}]}", "1:59",
                {"emitters[0].max = 1.5 must be a whole number"});
    expectError(
        "{\"emitters\": [{\"period\": 1, \"position\": [0, 0, 1], \"mass\": 1, \"density\": 9}]}",
        "1:52", {"gives both density and mass"});
    expectError(
        "{\"box\": {},\n \"emitters\": [{\"period\": 1, \"position\": [0, 0, 1.98], \"radius\": "
        "0.05}]}",
        "2:41",
        {"emitters[0] at (0, 0, 1.98) cannot hold a sphere of radius 0.05 m", "the box's ceiling"});
}

// --- emitting ---

TEST(Emitters, EmitOneSphereEveryPeriodUpToMax) {
    const Scene scene = shooter(0.25, 5);
    physics::World w = scenes::buildWorld(scene);
    stepAndEmit(scene, w, 14);  // t = 0.233 s
    EXPECT_EQ(w.size(), 0u);
    stepAndEmit(scene, w, 1);  // t = 0.25 s: the first one, at the emitter
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w.position[0], glm::dvec3(-0.8, 0, 1));
    EXPECT_EQ(w.velocity[0], glm::dvec3(2, 0, 0));
    EXPECT_EQ(w.radius[0], 0.05);
    EXPECT_NEAR(w.mass[0], 1000.0 * 4.0 / 3.0 * M_PI * std::pow(0.05, 3), 1e-15);
    stepAndEmit(scene, w, 45);  // t = 1 s
    EXPECT_EQ(w.size(), 4u);
    stepAndEmit(scene, w, 120);  // t = 3 s: max reached
    EXPECT_EQ(w.size(), 5u);
    EXPECT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{5});
}

// A sphere added another way (shot from the camera, thrown) is not an emission: the
// emitter keeps its own count and schedule.
TEST(Emitters, SpheresAddedOtherwiseAreNotCountedAsEmissions) {
    const Scene scene = shooter(0.25, 5);
    physics::World w = scenes::buildWorld(scene);
    stepAndEmit(scene, w, 15);  // t = 0.25 s: the first emission
    ASSERT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{1});
    w.addSphere({0.5, 0.5, 1.5}, {0, 0, 0}, 0.05, 1.0);  // a shot
    w.addSphere({0.5, -0.5, 1.5}, {0, 0, 0}, 0.05, 1.0);
    EXPECT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{1});
    stepAndEmit(scene, w, 45);  // t = 1 s: emissions 2, 3 and 4 still come, on time
    EXPECT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{4});
    EXPECT_EQ(w.size(), 6u);
}

TEST(Emitters, WaitWhileTheSpotIsTakenThenCatchUp) {
    Scene scene = shooter(0.1, 10);
    scene.spheres.push_back({{-0.8, 0.0, 1.05}, {0.0, 0.0, 0.0}, 0.05, 1.0});  // on the spot
    physics::World w = scenes::buildWorld(scene);
    stepAndEmit(scene, w, 60);
    EXPECT_EQ(w.size(), 1u);  // ten emissions due, none placed
    EXPECT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{0});
    w.position[0].z = 1.8;  // the spot is free again
    stepAndEmit(scene, w, 1);
    EXPECT_EQ(w.size(), 2u);
    stepAndEmit(scene, w, 60);  // one per step while the spot clears, up to max
    EXPECT_EQ(w.size(), 11u);
    EXPECT_EQ(scenes::emittedCounts(scene, w), std::vector<int>{10});
}

TEST(Emitters, SameSeedSameRainAnotherSeedAnotherRain) {
    const Scene scene = scenes::parseScene(R"({"box": {}, "seed": 3,
  "emitters": [{"period": 0.1, "position": [0, 0, 1.8], "velocity": [0, 0, -2], "spread": 1,
                "radius": [0.03, 0.06], "max": 100}]})",
                                           "rain.json");
    physics::World a = scenes::buildWorld(scene), b = scenes::buildWorld(scene);
    stepAndEmit(scene, a, 120);
    stepAndEmit(scene, b, 120);
    ASSERT_GT(a.size(), 10u);
    EXPECT_EQ(physics::stateHash(a), physics::stateHash(b));
    EXPECT_NE(a.radius[0], a.radius[1]);
    EXPECT_NE(a.velocity[0], a.velocity[1]);
    Scene other = scene;
    other.seed = 4;
    physics::World c = scenes::buildWorld(other);
    stepAndEmit(other, c, 120);
    EXPECT_NE(physics::stateHash(c), physics::stateHash(a));
}

TEST(Emitters, SeveralEmittersTakeTurnsInTheOrderTheyFallDue) {
    // They fall away from their spots, so no emission ever waits.
    const Scene scene = scenes::parseScene(R"({"box": {},
  "emitters": [{"period": 0.5, "position": [-0.5, 0, 1.8], "max": 3},
               {"period": 0.2, "position": [0.5, 0, 1.8], "max": 16}]})",
                                           "two.json");
    physics::World w = scenes::buildWorld(scene);
    stepAndEmit(scene, w, 60);  // t = 1 s: 2 of the first, 5 of the second
    EXPECT_EQ(scenes::emittedCounts(scene, w), (std::vector<int>{2, 5}));
    EXPECT_EQ(w.size(), 7u);
    stepAndEmit(scene, w, 120);  // t = 3 s: the first stops at max = 3
    EXPECT_EQ(scenes::emittedCounts(scene, w), (std::vector<int>{3, 15}));
    // A saved state keeps both counts and emits on the same schedule.
    const Scene back = scenes::parseScene(scenes::sceneText(scene, w), "saved.json");
    EXPECT_EQ(back.emitters[0].emitted, 3);
    EXPECT_EQ(back.emitters[1].emitted, 15);
    physics::World again = scenes::buildWorld(back);
    stepAndEmit(scene, w, 60);
    stepAndEmit(back, again, 60);
    EXPECT_EQ(physics::stateHash(again), physics::stateHash(w));
    EXPECT_EQ(scenes::emittedCounts(back, again), (std::vector<int>{3, 16}));  // max
}

TEST(Emitters, ALowerPeriodCatchesUpWithFloorOfTOverT) {
    // Spheres dropped from 1.8 m: the spot is free again 0.14 s after an emission.
    Scene scene = scenes::parseScene(
        R"({"box": {}, "emitters": [{"period": 1, "position": [0, 0, 1.8], "max": 100}]})",
        "drop.json");
    physics::World w = scenes::buildWorld(scene);
    stepAndEmit(scene, w, 120);  // t = 2 s
    EXPECT_EQ(w.size(), 2u);
    ASSERT_EQ(scenes::applySetting(scene, "emit_period=0.5"), "");  // live: 4 are due now
    stepAndEmit(scene, w, 1);
    EXPECT_EQ(w.size(), 2u);    // the one emitted at t = 2 s still takes the spot
    stepAndEmit(scene, w, 29);  // t = 2.5 s: two caught up as the spot cleared, one due
    EXPECT_EQ(w.size(), 5u);
    stepAndEmit(scene, w, 30);  // t = 3 s
    EXPECT_EQ(w.size(), 6u);
}

// --- thin walls ---

TEST(ThinWalls, ReadsWritesAndChecksTheThickness) {
    const Scene s = scenes::parseScene(R"({"box": {},
  "planes": [{"point": [0, 0, 1], "normal": [1, 0, 0], "thickness": 0.05}],
  "spheres": [{"p": [-0.5, 0, 1], "r": 0.1}, {"p": [0.5, 0, 1], "r": 0.1}]})",
                                       "wall.json");
    ASSERT_EQ(s.planes.size(), 1u);
    EXPECT_EQ(s.planes[0].thickness, 0.05);
    const physics::World w = scenes::buildWorld(s);
    EXPECT_EQ(w.planes.back().thickness, 0.05);  // spheres on both sides are fine
    const Scene back = scenes::parseScene(scenes::sceneText(s, w), "saved.json");
    EXPECT_EQ(back.planes[0].thickness, 0.05);
    expectError("{\"planes\": [{\"point\": [0, 0, 1], \"normal\": [1, 0, 0], \"thickness\": -1}]}",
                "1:68", {"planes[0].thickness = -1 must be >= 0 (m)"});
    expectError(R"({"box": {},
  "planes": [{"point": [0, 0, 1], "normal": [1, 0, 0], "thickness": 0.05}],
  "spheres": [{"p": [0.1, 0, 1], "r": 0.1}]})",
                "3:21", {"spheres[0]", "crosses planes[0]"});
    const Scene plain = scenes::parseScene(
        R"({"planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}], "spheres": [{"p": [0, 0, 1]}]})",
        "plain.json");
    EXPECT_EQ(plain.planes[0].thickness, 0.0);
    const std::string text = scenes::sceneText(plain, scenes::buildWorld(plain));
    EXPECT_FALSE(contains(text, "thickness"));  // a half-space is written as before
}

}  // namespace
