// Invariant alarms (app/alarms.h): each fires in a case built to trigger it
// (a NaN injected, energy created, a deep overlap), names what it found, and all
// stay silent on every shipped preset at its own settings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "app/teaching/alarms.h"
#include "app/run/simulation.h"
#include "physics/diagnostics.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

using app::AlarmKind;
using app::Simulation;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadius = 0.1;  // m

// One sphere of 1 kg dropped from 1.5 m in a 2 m box.
scenes::Scene dropScene(double beta, physics::Method method) {
    scenes::Scene scene;
    scene.title = "drop";
    scene.box = scenes::Box{};
    scene.params.beta = beta;
    scene.params.method = method;
    scene.spheres.push_back({{0.0, 0.0, 1.5}, {0.0, 0.0, 0.0}, kRadius, 1.0});
    return scene;
}

// Three spheres in a row, no gravity.
scenes::Scene threeSpheres() {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.params.gravity = glm::dvec3(0.0);
    for (int k = 0; k < 3; ++k) scene.spheres.push_back({{-0.5 + 0.5 * k, 0.0, 1.0}, {0.1, 0.0, 0.0}, kRadius, 1.0});
    return scene;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(Alarms, FindNonFiniteNamesTheFirstSphereAndItsField) {
    physics::World world = scenes::buildWorld(threeSpheres());
    EXPECT_FALSE(app::findNonFinite(world).has_value());
    world.velocity[2].y = kNaN;
    world.position[1].z = std::numeric_limits<double>::infinity();
    const auto found = app::findNonFinite(world);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->sphere, 1u);
    EXPECT_EQ(found->field, "position.z");
    EXPECT_EQ(found->count, 2u);
    world.position[1].z = 1.0;
    EXPECT_EQ(app::findNonFinite(world)->field, "velocity.y");
    world.velocity[2].y = 0.0;
    world.mass[0] = kNaN;
    EXPECT_EQ(app::findNonFinite(world)->field, "mass");
}

// The broad phase cannot place a NaN centre: the step must not even start.
TEST(Alarms, InjectedNaNVelocityPausesAndNamesTheSphere) {
    Simulation sim(threeSpheres());
    for (int k = 0; k < 10; ++k) sim.singleStep();
    const std::uint64_t steps = sim.world().stepCount;
    sim.editableWorld().velocity[2].y = kNaN;
    EXPECT_EQ(sim.advance(0.1), 0);
    EXPECT_TRUE(sim.paused);
    EXPECT_EQ(sim.world().stepCount, steps);
    ASSERT_TRUE(sim.alarms().nonFinite());
    EXPECT_EQ(sim.alarms().nonFiniteValue()->sphere, 2u);
    EXPECT_EQ(sim.alarms().nonFiniteValue()->field, "velocity.y");
    const auto lines = sim.alarms().lines(sim.world().time);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0].kind, AlarmKind::NonFinite);
    EXPECT_TRUE(lines[0].lit);
    EXPECT_TRUE(contains(lines[0].text, "sphere 2")) << lines[0].text;
    EXPECT_TRUE(contains(lines[0].text, "velocity.y")) << lines[0].text;
    // Run again, or step: it stays paused and does not step.
    sim.paused = false;
    EXPECT_EQ(sim.advance(0.1), 0);
    EXPECT_TRUE(sim.paused);
    sim.singleStep();
    EXPECT_EQ(sim.world().stepCount, steps);
    // Restart recovers.
    sim.restart();
    EXPECT_FALSE(sim.alarms().nonFinite());
    EXPECT_TRUE(sim.alarms().lines(0.0).empty());
}

// A NaN made inside a step (gravity set to NaN, one sphere: nothing to sort) is
// caught after it, and the simulation pauses at once.
TEST(Alarms, NaNMadeByTheStepPausesAtOnce) {
    Simulation sim(dropScene(0.8, physics::Method::PositionBased));
    sim.editableScene().params.gravity.z = kNaN;
    EXPECT_EQ(sim.advance(0.5), 1);  // 30 steps were due: it stopped after the first
    EXPECT_TRUE(sim.paused);
    ASSERT_TRUE(sim.alarms().nonFinite());
    EXPECT_EQ(sim.alarms().nonFiniteValue()->sphere, 0u);
    EXPECT_EQ(sim.alarms().nonFiniteValue()->field, "position.z");
}

// With several spheres, a NaN made in the first substep breaks the broad phase of
// the next one (it cannot size its grid): still a pause that names the sphere.
TEST(Alarms, NaNMadeByTheStepAmongSeveralSpheresPausesAndNamesIt) {
    scenes::Scene scene = threeSpheres();
    Simulation sim(scene);
    sim.editableScene().params.gravity.z = kNaN;
    sim.singleStep();
    EXPECT_TRUE(sim.paused);
    ASSERT_TRUE(sim.alarms().nonFinite());
    EXPECT_EQ(sim.alarms().nonFiniteValue()->sphere, 0u);
    EXPECT_EQ(sim.alarms().nonFiniteValue()->count, 3u);
}

TEST(Alarms, EnergyRuleOnHandMadeSteps) {
    physics::Params params;  // alpha 1, beta 0.8, mu 0.5
    EXPECT_TRUE(app::energyRuleApplies(params));
    EXPECT_TRUE(app::energyCreated(100.0, 100.2, 100.0, params));     // +0.2 %
    EXPECT_FALSE(app::energyCreated(100.0, 100.05, 100.0, params));   // +0.05 %: below 0.1 %
    EXPECT_FALSE(app::energyCreated(100.0, 90.0, 100.0, params));     // lost: fine
    EXPECT_NEAR(app::relativeEnergyRise(100.0, 100.2, 100.0), 2e-3, 1e-12);
    // A sphere stopped by a static contact: E~ rises by up to m (h g)^2 / 8, no energy made.
    physics::World one = scenes::buildWorld(dropScene(0.8, physics::Method::PositionBased));
    const double hg = params.solverStep() * 9.81;
    EXPECT_NEAR(app::energySlack(one, params), 2 * hg * hg / 8, 1e-15);
    EXPECT_FALSE(app::energyCreated(1.0, 1.0 + hg * hg / 8, 1.0, params, app::energySlack(one, params)));
    EXPECT_TRUE(app::energyCreated(1.0, 1.0 + 1e-3 + 3 * hg * hg / 8, 1.0, params, app::energySlack(one, params)));
    params.beta = 1.2;  // beyond the lecture's range: the rule does not apply
    EXPECT_FALSE(app::energyRuleApplies(params));
    EXPECT_FALSE(app::energyCreated(100.0, 200.0, 100.0, params));

    // Alarms::checkStep on a world whose E~ a hand-made step raised by 5 %.
    physics::World world = scenes::buildWorld(dropScene(0.8, physics::Method::PositionBased));
    physics::Params p;
    const double before = physics::modifiedEnergy(world, p);
    world.velocity[0].z = -std::sqrt(2.0 * 0.05 * before / world.mass[0]);  // +5 % of E~ as kinetic
    const double after = physics::modifiedEnergy(world, p);
    app::Alarms alarms;
    EXPECT_TRUE(alarms.checkStep(world, p, before, after));
    EXPECT_TRUE(alarms.fired(AlarmKind::EnergyCreated));
    EXPECT_NEAR(alarms.worst(AlarmKind::EnergyCreated), (after - before) / before, 1e-12);
    EXPECT_GT(alarms.worst(AlarmKind::EnergyCreated), 0.04);
}

// The lecture's lesson: velocity based at beta = 1 gains about 2 g h / s per floor
// bounce (h the solver step, s the impact speed); the alarm says why.
TEST(Alarms, ElasticVelocityBasedBounceCreatesEnergyAndSaysWhy) {
    Simulation sim(dropScene(1.0, physics::Method::VelocityBased));
    for (int k = 0; k < 60; ++k) sim.singleStep();  // the first bounce is at 0.53 s
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EnergyCreated));
    EXPECT_EQ(sim.alarms().count(AlarmKind::EnergyCreated), 1u);
    // E~ = m g 1.5 m; the gain m g (1.4 m) 2 g h / s with h = 1/240 s, s = sqrt(2 g 1.4 m).
    const double g = 9.81, h = 1.0 / 240.0, s = std::sqrt(2 * g * 1.4);
    const double expected = 1.4 * 2 * g * h / s / 1.5;  // 1.46 %
    EXPECT_NEAR(sim.alarms().worst(AlarmKind::EnergyCreated), expected, 0.2 * expected);
    const auto lines = sim.alarms().lines(sim.world().time);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0].lit);
    EXPECT_TRUE(contains(lines[0].hint, "velocity-based bounce reflects this step's gravity kick")) << lines[0].hint;
    EXPECT_FALSE(sim.paused);  // an energy alarm does not stop the demo

    // Lit for 2 s of simulated time, then dimmed until restart.
    for (int k = 0; k < 150; ++k) sim.singleStep();
    const auto later = sim.alarms().lines(sim.world().time + app::kAlarmHoldSeconds + 1.0);
    ASSERT_EQ(later.size(), 1u);
    EXPECT_FALSE(later[0].lit);
    sim.restart();
    EXPECT_TRUE(sim.alarms().lines(0.0).empty());

    // The same drop, position based: never.
    Simulation projected(dropScene(1.0, physics::Method::PositionBased));
    for (int k = 0; k < 600; ++k) projected.singleStep();
    EXPECT_FALSE(projected.alarms().fired(AlarmKind::EnergyCreated));
}

// Response only, a sphere shot up into the ceiling (preset 01 with F): the response
// reflects this step's gravity kick, which at a ceiling adds m g h |v| (a floor loses
// it). The alarm names that cause instead of asking for a report.
TEST(Alarms, ResponseOnlyBounceOffTheCeilingGainsEnergyAndSaysWhy) {
    scenes::Scene scene = dropScene(1.0, physics::Method::ResponseOnly);
    scene.spheres[0].v = {0.0, 0.0, 10.0};  // m/s, up
    Simulation sim(scene);
    for (int k = 0; k < 6; ++k) sim.singleStep();  // at the ceiling after about 0.04 s
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EnergyCreated));
    // Impact speed u = sqrt(10^2 - 2 g 0.4 m) = 9.6 m/s, h = 1/60 s over 4 substeps:
    // the gain m g h u relative to E~ = m g 1.5 m + m 10^2 / 2.
    const double g = 9.81, h = 1.0 / 240.0, u = std::sqrt(100.0 - 2.0 * g * 0.4);
    const double expected = g * h * u / (g * 1.5 + 50.0);  // 0.61 %
    EXPECT_NEAR(sim.alarms().worst(AlarmKind::EnergyCreated), expected, 0.25 * expected);
    const auto lines = sim.alarms().lines(sim.world().time);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(contains(lines[0].hint, "bounce off the ceiling gains")) << lines[0].hint;
    EXPECT_FALSE(contains(lines[0].hint, "report")) << lines[0].hint;
}

// Spheres that leave the box are an alarm, with how many and when the first left: the
// pile, velocity based, h = 0.1 s and |g| = 50 m/s^2 sinks through its floor.
TEST(Alarms, SpheresThatLeaveTheBoxAreCountedWithTheStepTheFirstLeft) {
    scenes::Scene pile = scenes::loadScene(scenes::presetPath("11_pile"));
    for (const char* setting : {"method=velocity", "h=0.1", "substeps=1", "gravity=50"}) {
        ASSERT_EQ(scenes::applySetting(pile, setting), "") << setting;
    }
    Simulation sim(pile);
    for (int k = 0; k < 100; ++k) sim.singleStep();  // 10 s
    const std::size_t outside = physics::spheresOutsideBox(sim.world(), 0.0);
    ASSERT_GT(outside, 100u);
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::Escaped));
    EXPECT_GE(sim.alarms().worst(AlarmKind::Escaped), double(outside));
    bool shown = false;
    for (const app::AlarmLine& line : sim.alarms().lines(sim.world().time)) {
        if (line.kind != AlarmKind::Escaped) continue;
        shown = true;
        EXPECT_TRUE(contains(line.text, "ESCAPED: " + std::to_string(outside) + " outside the box now")) << line.text;
        EXPECT_TRUE(contains(line.text, "the first had left by solver step 2")) << line.text;
        EXPECT_TRUE(contains(line.hint, "switch method to position")) << line.hint;
    }
    EXPECT_TRUE(shown);
}

// beta > 1 set through the parameters directly (the UI stops at 1): the ball gains
// energy at every bounce, but the rule is for alpha, beta <= 1, so no alarm.
TEST(Alarms, BetaAboveOneGainsEnergyWithoutAlarm) {
    Simulation sim(dropScene(1.0, physics::Method::PositionBased));
    sim.editableScene().params.beta = 1.2;
    const double start = sim.diagnostics().modified;
    for (int k = 0; k < 60; ++k) sim.singleStep();
    EXPECT_GT(sim.diagnostics().modified, 1.2 * start);
    EXPECT_FALSE(sim.alarms().fired(AlarmKind::EnergyCreated));
}

// Energy the app itself puts in (a drag, a throw) is announced and not an alarm.
TEST(Alarms, EnergyInjectedByTheAppIsNotAnAlarm) {
    Simulation sim(dropScene(0.8, physics::Method::PositionBased));
    sim.singleStep();
    sim.editableWorld().velocity[0].x = 3.0;  // a throw
    sim.markEnergyInjected();
    sim.singleStep();
    EXPECT_FALSE(sim.alarms().fired(AlarmKind::EnergyCreated));
}

TEST(Alarms, DeepOverlapFires) {
    physics::Diagnostics d;
    d.maxPenetration = 0.49;
    EXPECT_FALSE(app::penetrationTooDeep(d));
    d.maxPenetration = 0.51;
    EXPECT_TRUE(app::penetrationTooDeep(d));

    // Two spheres pushed 60 % of a radius into each other, with no position
    // correction to undo it (velocity response only) and no motion.
    scenes::Scene scene = threeSpheres();
    scene.params.method = physics::Method::ResponseOnly;
    for (auto& sphere : scene.spheres) sphere.v = glm::dvec3(0.0);
    Simulation sim(scene);
    sim.editableWorld().position[1].x = sim.world().position[0].x + 2 * kRadius - 0.6 * kRadius;
    sim.singleStep();
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::Penetration));
    EXPECT_NEAR(sim.alarms().worst(AlarmKind::Penetration), 0.6, 1e-9);
    const auto lines = sim.alarms().lines(sim.world().time);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(contains(lines[0].text, "PENETRATION: 60.0 % of r at the deepest so far")) << lines[0].text;
    EXPECT_TRUE(contains(lines[0].hint, "response-only")) << lines[0].hint;
    EXPECT_FALSE(sim.paused);
}

// Every shipped preset, at its own settings, for 600 steps (10 s at h = 1/60 s),
// measured after every step. Presets are listed, not named: a new one is checked too.
// A position-based preset raises no alarm. A preset that shows the documented flaw
// of its method may raise that alarm only, with its lesson as the hint: velocity
// based creates energy at elastic bounces and never pushes an overlap apart (the
// pyramid sinks into itself); the velocity response alone sinks into the floor; the
// fast gas, position based beside continuous, overlaps deeply.
// No preset ever makes a value that is not finite.
TEST(Alarms, SilentOnEveryShippedPresetButForItsMethodsLesson) {
    const std::vector<std::string> presets = scenes::listPresets();
    ASSERT_FALSE(presets.empty());
    for (const std::string& name : presets) {
        Simulation sim(scenes::loadScene(scenes::presetPath(name)));
        const physics::Method method = sim.params().method;
        for (int k = 0; k < 600 && !sim.paused; ++k) sim.singleStep();
        EXPECT_FALSE(sim.paused) << name;
        for (const app::AlarmLine& line : sim.alarms().lines(sim.world().time)) {
            const bool lesson =
                (method == physics::Method::VelocityBased &&
                 (line.kind == AlarmKind::EnergyCreated || line.kind == AlarmKind::Penetration) &&
                 contains(line.hint, "velocity")) ||
                (method == physics::Method::ResponseOnly && line.kind == AlarmKind::Penetration &&
                 contains(line.hint, "response-only")) ||
                // A preset that puts methods side by side shows view A's flaw on purpose.
                (!sim.scene().compare.empty() && line.kind == AlarmKind::Penetration &&
                 contains(line.hint, "switch method to continuous"));
            if (lesson) {
                std::printf("[ lesson   ] %s: %s\n", name.c_str(), line.text.c_str());
            } else {
                ADD_FAILURE() << name << ": " << line.text << " (" << line.hint << ")";
            }
        }
    }
}

namespace {

// The pile, velocity based: about 300 spheres come to rest in mid-air, held by slide 13's
// v <- mu v (issue 26): an alarm names them and says how to let them fall. Position
// based, the same pile raises no such alarm.
TEST(Alarms, SpheresHeldInMidAirAreNamedWithTheirCountAndTheRemedy) {
    scenes::Scene pile = scenes::loadScene(scenes::presetPath("11_pile"));
    Simulation position(pile);
    ASSERT_EQ(scenes::applySetting(pile, "method=velocity"), "");
    Simulation velocity(pile);
    std::size_t mostHeld = 0;  // by the position based pile, counted at every step
    for (int k = 0; k < 900; ++k) {  // 15 s, measured every step as the window does once per frame
        velocity.singleStep();
        position.singleStep();
        mostHeld = std::max(mostHeld, physics::spheresHeldInMidAir(position.world(), pile.params));
    }
    EXPECT_FALSE(position.alarms().fired(AlarmKind::HeldInMidAir));
    // The alarm counts every quarter of a second of simulated time, at the frame that ends
    // it: the page's frames (coarser and uneven) counted the landing pile's 10 to 14 held
    // spheres for a second and lit MID-AIR on the text's well-behaved default. So the landing
    // pile's most (39 of 1000, for a moment) stays under the alarm's level, and the velocity
    // pile's 300 above twice it, whenever the counts fall.
    const double least = std::max(double(app::kHeldInMidAirMin), app::kHeldInMidAirShare * double(position.world().size()));
    EXPECT_LT(double(mostHeld), least) << "the landing position based pile";
    ASSERT_TRUE(velocity.alarms().fired(AlarmKind::HeldInMidAir));
    const std::size_t held = physics::spheresHeldInMidAir(velocity.world(), pile.params);
    EXPECT_GT(held, 250u);
    EXPECT_GT(double(held), 2.0 * least);
    bool shown = false;
    for (const app::AlarmLine& line : velocity.alarms().lines(velocity.world().time)) {
        if (line.kind != AlarmKind::HeldInMidAir) continue;
        shown = true;
        EXPECT_TRUE(contains(line.text, "MID-AIR: ")) << line.text;
        EXPECT_TRUE(contains(line.text, "nothing below carrying them")) << line.text;
        EXPECT_TRUE(contains(line.hint, "v ← μ v, so spheres that touch only each other stop")) << line.hint;
        EXPECT_TRUE(contains(line.hint, "switch response to momentum")) << line.hint;
        EXPECT_TRUE(line.lit);
    }
    EXPECT_TRUE(shown);
}

}  // namespace

// The continuous method with epsilon = 0: a sphere bouncing in place at beta = 0.3
// would collide infinitely often within a step (each flight 0.3 times the last; in
// doubles, until its speed rounds to 0: 32 impacts per solver step here). A cap of 20
// per sphere ends each of the 4 solver steps; the alarm counts them and says what to change.
TEST(Alarms, AContinuousStepThatReachesTheImpactCapIsCounted) {
    scenes::Scene scene = dropScene(0.3, physics::Method::Continuous);
    scene.spheres[0].p.z = kRadius;  // on the floor
    scene.params.epsilon = 0.0;
    scene.params.maxEventsPerSphere = 20;
    Simulation sim(scene);
    sim.singleStep();
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EventCap));
    const auto lines = sim.alarms().lines(sim.world().time);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(contains(lines[0].text, "IMPACT CAP: 4 steps reached 20 impacts per sphere")) << lines[0].text;
    EXPECT_TRUE(contains(lines[0].hint, "Raise ε")) << lines[0].hint;
    EXPECT_TRUE(contains(lines[0].hint, "and a smaller h does not help")) << lines[0].hint;  // whole, not cut at 256 bytes
    EXPECT_NEAR(sim.world().position[0].z, kRadius, 1e-9);  // projected: still on the floor

    scene.params.epsilon = 0.1;  // the resting contact is static: one impact a step
    Simulation resting(scene);
    for (int k = 0; k < 60; ++k) resting.singleStep();
    EXPECT_FALSE(resting.alarms().fired(AlarmKind::EventCap));
}


// Bernoulli's problem under the simultaneous solver gains 75 % kinetic energy
// (test_multiple_collisions.cpp): the alarm fires and names the solver's flaw.
TEST(Alarms, TheSimultaneousSolversEnergyIsNamed) {
    scenes::Scene scene;
    scene.params.gravity = glm::dvec3(0.0);
    scene.params.solver = physics::Solver::Simultaneous;
    scene.params.method = physics::Method::VelocityBased;
    scene.params.alpha = scene.params.beta = scene.params.mu = 1.0;
    scene.params.epsilon = 0.0;
    const double s3 = std::sqrt(3.0) / 2.0;
    scene.spheres = {{{0.0, 0.0, 1.0 + 0.2 * s3}, {0.0, 0.0, -1.0}, kRadius, 1.0},
                     {{-0.1, 0.0, 1.0}, {0.0, 0.0, 0.0}, kRadius, 1.0},
                     {{0.1, 0.0, 1.0}, {0.0, 0.0, 0.0}, kRadius, 1.0}};
    Simulation sim(scene);
    sim.singleStep();
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EnergyCreated));
    // +0.375 J of E~ before the step (0.5 J): 75 %, the "1.75 times" of preset 16's text (the
    // alarm said 43 %, over the kinetic energy after, the 18th audit found).
    EXPECT_NEAR(sim.alarms().worst(AlarmKind::EnergyCreated), 0.75, 1e-9);
    const app::AlarmLine line = sim.alarms().lines(sim.world().time)[0];
    EXPECT_TRUE(contains(line.hint, "simultaneous solver"));
    EXPECT_TRUE(contains(line.text, "rose by up to 75 % of itself in one time step h, once, last at t = 0.017 s")) << line.text;
}

// Spheres falling together touch statically (their relative speed is 0). With the
// momentum response, whose mu acts on the relative velocity, nothing holds them and the
// lattice falls: none is counted held (each was, before the count asked for rest,
// |v| <= epsilon). With the lecture's v <- mu v on each sphere's own velocity the upper
// two layers do hover (physics.md, slide 13; the bottom layer parts from them in the
// first step and falls): 18 of the 27, counted.
TEST(Alarms, ALatticeFallingTogetherIsNotHeldInMidAir) {
    for (const auto response : {physics::ResponseModel::MomentumConserving, physics::ResponseModel::LectureAttenuation}) {
        scenes::Scene scene;
        scene.box = scenes::Box{};
        scene.params.response = response;
        for (int x = 0; x < 3; ++x) {
            for (int y = 0; y < 3; ++y) {
                for (int z = 0; z < 3; ++z) {
                    scene.spheres.push_back({{0.2 * x - 0.2, 0.2 * y - 0.2, 1.0 + 0.2 * z}, {}, kRadius, 1.0});
                }
            }
        }
        Simulation sim(scene);
        for (int k = 0; k < 20; ++k) sim.singleStep();  // 0.33 s
        const bool lecture = response == physics::ResponseModel::LectureAttenuation;
        const double fallen = 0.5 * 9.81 * (20.0 / 60.0) * (20.0 / 60.0);  // m in free fall
        EXPECT_NEAR(sim.world().position[1].z, lecture ? 1.2 : 1.2 - fallen, 0.02);  // the middle layer
        EXPECT_EQ(physics::spheresHeldInMidAir(sim.world(), sim.params()), lecture ? 18u : 0u);
    }
}

// 09's text invites mu = 1: the projection of the column then lifts it within some steps
// (E~ up to 0.12 % in a step, test_canonical_checks). The alarm says so and what to move,
// instead of asking for a bug report.
TEST(Alarms, AColumnWithoutStaticDampingIsLiftedByTheProjectionAndTheHintSaysSo) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("09_column"));
    ASSERT_EQ(scenes::applySetting(scene, "mu=1"), "");
    Simulation sim(scene);
    for (int k = 0; k < 600; ++k) sim.singleStep();
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EnergyCreated));
    bool said = false;
    for (const app::AlarmLine& line : sim.alarms().lines(sim.world().time)) {
        if (line.kind != AlarmKind::EnergyCreated) continue;
        said = contains(line.hint, "with little static damping (μ near 1) the projection of a stack can lift it");
        EXPECT_FALSE(contains(line.hint, "report the scene")) << line.hint;
    }
    EXPECT_TRUE(said);
}

// Slide 14's column at one pass squashes (19 % of r); shock propagation switched on in the
// middle of the run stands it up again within a step, and E~ gets back the potential
// energy its sinking lost: the alarm fires, and its why names the change, not a bug. Left
// alone, the squashed column raises no alarm.
TEST(Alarms, ARiseAfterTheSettingsChangedNamesTheChange) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("21_shock_column"));
    scene.compare.clear();
    Simulation sim(scene);
    for (int k = 0; k < 120; ++k) sim.singleStep();
    ASSERT_FALSE(sim.alarms().fired(AlarmKind::EnergyCreated));
    ASSERT_GT(sim.diagnostics().maxPenetration, 0.15);
    ASSERT_EQ(scenes::applySetting(sim.editableScene(), "shock=on"), "");
    sim.singleStep();
    ASSERT_TRUE(sim.alarms().fired(AlarmKind::EnergyCreated));
    for (const app::AlarmLine& line : sim.alarms().lines(sim.world().time)) {
        if (line.kind != AlarmKind::EnergyCreated) continue;
        EXPECT_TRUE(contains(line.hint, "the settings changed at t = 2.000 s (shock = on): the new ones push apart")) << line.hint;
        EXPECT_FALSE(contains(line.hint, "report the scene")) << line.hint;
    }
}
