// Slide 14's "multiple collisions", answered by each solver (physics.md, "Slide 14, the
// global approach"), on inputs whose outcome is derived by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/diagnostics.h"
#include "physics/step.h"
#include "physics_fixtures.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

using glm::dvec3;
using physics::Method;
using physics::Solver;

namespace {

constexpr double kS3 = 0.8660254037844386;  // sqrt(3) / 2 = cos 30 degrees

physics::Params exact(Solver solver, Method method = Method::PositionBased) {
    physics::Params params = fixtures::exactParams(1.0 / 240.0, dvec3(0.0));
    params.solver = solver;
    params.method = method;
    return params;
}

// Bernoulli's problem: sphere 0 moving down at 1 m/s onto spheres 1 (left) and 2
// (right), which touch each other; all three touch, 1 kg, r = 0.1 m, no gravity. The
// centres form an equilateral triangle: u from 1 to 0 is (1/2, 0, sqrt3/2), from 2 to 0
// (-1/2, 0, sqrt3/2). Mirror symmetric in x. The position based method moves before its
// passes: for it sphere 0 starts one step's travel higher, and touches when they run.
physics::World bernoulli(Method method) {
    const double lift = method == Method::PositionBased ? 1.0 / 240.0 : 0.0;  // m: h times 1 m/s
    physics::World world;
    world.addSphere({0.0, 0.0, 0.2 * kS3 + lift}, {0.0, 0.0, -1.0}, 0.1, 1.0);
    world.addSphere({-0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, 1.0);
    world.addSphere({0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, 1.0);
    return world;
}

void expectVelocity(const physics::World& world, std::size_t i, dvec3 expected) {
    EXPECT_LT(glm::length(world.velocity[i] - expected), 1e-9)
        << "sphere " << i << ": (" << world.velocity[i].x << ", " << world.velocity[i].y << ", " << world.velocity[i].z
        << ")";
}

double kinetic(const physics::World& world) {
    double sum = 0.0;  // J
    for (std::size_t i = 0; i < world.size(); ++i) sum += 0.5 * world.mass[i] * glm::dot(world.velocity[i], world.velocity[i]);
    return sum;
}

}  // namespace

// Sequential, pairs (0,1), (0,2), (1,2) in index order, elastic (equal masses swap their
// normal velocities). Pass 1: (0,1): v0.u = -sqrt3/2, so sphere 0 gets +sqrt3/2 u =
// (sqrt3/4, 0, 3/4) - (0,0,1) = (0.4330, 0, -0.25) and sphere 1 gets -sqrt3/2 u =
// (-0.4330, 0, -0.75). (0,2): v0.u' = -0.4330, so sphere 0 becomes (0.2165, 0, 0.125) and
// sphere 2 (0.2165, 0, -0.375). (1,2) separate. Pass 2: nothing approaches. The energy is
// kept (0.0625 + 0.75 + 0.1875 = 1 = |v|^2 before), but the mirror symmetry is lost:
// sphere 1 leaves at 0.866 m/s, sphere 2 at 0.433, sphere 0 drifts right.
TEST(MultipleCollisions, SequentialBreaksBernoullisSymmetry) {
    for (Solver solver : {Solver::Sequential, Solver::UntilConverged}) {
        physics::World world = bernoulli(Method::PositionBased);
        const physics::StepStats stats = physics::step(world, exact(solver));
        expectVelocity(world, 0, {kS3 / 4, 0.0, 0.125});
        expectVelocity(world, 1, {-kS3 / 2, 0.0, -0.75});
        expectVelocity(world, 2, {kS3 / 4, 0.0, -0.375});
        EXPECT_NEAR(kinetic(world), 0.5, 1e-12);
        EXPECT_NEAR(glm::length(world.velocity[1]) - glm::length(world.velocity[2]), kS3 / 2, 1e-9);
        // Until converged stops after the pass that left nothing approaching: 1 of K = 4.
        EXPECT_EQ(stats.passesUsed, solver == Solver::Sequential ? 4u : 1u);
    }
}

// Simultaneous (Jacobi): both contacts of sphere 0 answered from the same velocities.
// (0,1) alone would give sphere 0 +sqrt3/2 u and (0,2) alone +sqrt3/2 u'; together
// sqrt3/2 (u + u') = sqrt3/2 (0, 0, sqrt3) = (0, 0, 3/2): sphere 0 leaves upward at
// 0.5 m/s, spheres 1 and 2 at -sqrt3/2 u = (-sqrt3/4, 0, -3/4) and its mirror image.
// Symmetric, but both contacts gave
// sphere 0 the whole of its approach back: the kinetic energy is 1.75 times what it was
// (0.25 + 0.75 + 0.75 = 1.75), the flaw of summing impulses that each assume they are alone.
TEST(MultipleCollisions, SimultaneousKeepsTheSymmetryAndCreatesEnergy) {
    for (Method method : {Method::PositionBased, Method::VelocityBased}) {
        physics::World world = bernoulli(method);
        physics::step(world, exact(Solver::Simultaneous, method));
        expectVelocity(world, 0, {0.0, 0.0, 0.5});
        expectVelocity(world, 1, {-kS3 / 2, 0.0, -0.75});
        expectVelocity(world, 2, {kS3 / 2, 0.0, -0.75});
        EXPECT_NEAR(kinetic(world) / 0.5, 1.75, 1e-12);
        EXPECT_EQ(world.velocity[1].x, -world.velocity[2].x);  // mirror images, bit for bit
        EXPECT_EQ(world.velocity[1].z, world.velocity[2].z);
    }
}

// The cradle in reversed order needs one pass per contact (slide 14): with K = 100
// until-converged takes the 4 it needs and stops; with K = 2 it stops at the cap with
// the speed on sphere 2 and says so.
TEST(MultipleCollisions, UntilConvergedTakesThePassesTheCradleNeedsAndReportsTheCap) {
    physics::Params params = exact(Solver::UntilConverged);
    params.order = physics::PairOrder::Reversed;
    params.passes = 100;
    physics::World world = fixtures::cradle(2.0);
    physics::StepStats stats = physics::step(world, params);
    EXPECT_EQ(stats.passesUsed, 4u);
    EXPECT_EQ(stats.passCapHits, 0u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(world.velocity[k].x, k == 4 ? 2.0 : 0.0, 1e-12) << k;
    params.passes = 2;
    world = fixtures::cradle(2.0);
    stats = physics::step(world, params);
    EXPECT_EQ(stats.passesUsed, 2u);
    EXPECT_EQ(stats.passCapHits, 1u);
    EXPECT_NEAR(world.velocity[2].x, 2.0, 1e-12);
}

// Velocity based, reversed, one pass: stage C meets spheres the pass has not reached
// and cancels their approach, 2 J -> 0.69 J. Until converged the passes carry the speed
// to the end first, and C finds nothing approaching: the 2 J stay.
TEST(MultipleCollisions, UntilConvergedSavesTheVelocityMethodsCradle) {
    physics::Params params = exact(Solver::UntilConverged, Method::VelocityBased);
    params.order = physics::PairOrder::Reversed;
    params.passes = 10;
    physics::World world = fixtures::cradle(2.0);
    for (int k = 0; k < 60; ++k) physics::step(world, params);
    EXPECT_NEAR(kinetic(world), 2.0, 1e-12);
    EXPECT_NEAR(world.velocity[4].x, 2.0, 1e-12);
}

// The global solve on Bernoulli's problem, elastic. By symmetry lambda_1 = lambda_2 =
// lambda on the contacts of sphere 0, and the contact between 1 and 2 separates (its
// c+ = lambda + 2 lambda_3 > 0), so lambda_3 = 0. Then c+_1 = 5/2 lambda - sqrt3/2 must be
// +sqrt3/2: lambda = 2 sqrt3 / 5. Sphere 0: (0, 0, -1 + sqrt3 lambda) = (0, 0, 0.2);
// spheres 1 and 2: -lambda u = (-/+ sqrt3/5, 0, -0.6). Momentum (0, 0, -1) and energy
// (0.04 + 2 x 0.48 = 1) kept, the mirror symmetry too: all that Bernoulli asks.
TEST(MultipleCollisions, TheGlobalSolveAnswersBernoulliExactly) {
    for (Method method : {Method::PositionBased, Method::VelocityBased}) {
        physics::World world = bernoulli(method);
        const physics::StepStats stats = physics::step(world, exact(Solver::Lcp, method));
        const double s3 = 2.0 * kS3;
        expectVelocity(world, 0, {0.0, 0.0, 0.2});
        expectVelocity(world, 1, {-s3 / 5, 0.0, -0.6});
        expectVelocity(world, 2, {s3 / 5, 0.0, -0.6});
        EXPECT_NEAR(kinetic(world), 0.5, 1e-12);
        // Mirror images to the tolerance (the sweeps visit contact (0, 1) before (0, 2)).
        EXPECT_NEAR(world.velocity[1].x, -world.velocity[2].x, 1e-12);
        EXPECT_GT(stats.lcpSweeps, 0u);
        EXPECT_LE(stats.lcpResidual, 1e-12);
    }
}

// The global solve on the touching cradle keeps momentum and energy but not break-away:
// contact (0, 1) must part at v0 and the others not approach, so all four push and spheres
// 1-4 leave together at a, sphere 0 at a - v0; momentum gives 5 a - v0 = v0, a = 2/5 v0:
// sphere 0 bounces back at -0.6 v0, the row moves off at 0.4 v0 (energy 0.36 + 4 x 0.16 = 1).
// A real cradle sends the last ball alone: the flaw Smith et al. name, asserted here.
TEST(MultipleCollisions, TheGlobalSolveMovesTheWholeCradleTogether) {
    physics::World world = fixtures::cradle(2.0);
    physics::step(world, exact(Solver::Lcp, Method::VelocityBased));
    EXPECT_NEAR(world.velocity[0].x, -0.6 * 2.0, 1e-9);
    for (int k = 1; k < 5; ++k) EXPECT_NEAR(world.velocity[k].x, 0.4 * 2.0, 1e-9) << k;
    EXPECT_NEAR(kinetic(world), 2.0, 1e-9);
}

// Generalized reflections on Bernoulli's problem: the first active set is the two contacts
// of sphere 0 (the one between 1 and 2 does not approach), and the elastic solve on them
// is the global solve's above (lambda = 2 sqrt3 / 5 each); afterwards 1 and 2 part, so
// the second round finds nothing approaching. The same velocities, in one round.
TEST(MultipleCollisions, GeneralizedReflectionsAnswerBernoulliAsTheGlobalSolve) {
    for (Method method : {Method::PositionBased, Method::VelocityBased}) {
        physics::World world = bernoulli(method);
        physics::Params params = exact(Solver::GeneralizedReflections, method);
        params.passes = 1;
        const physics::StepStats stats = physics::step(world, params);
        const double s3 = 2.0 * kS3;
        expectVelocity(world, 0, {0.0, 0.0, 0.2});
        expectVelocity(world, 1, {-s3 / 5, 0.0, -0.6});
        expectVelocity(world, 2, {s3 / 5, 0.0, -0.6});
        EXPECT_NEAR(kinetic(world), 0.5, 1e-12);
        EXPECT_EQ(stats.reflectionRounds, 1u);
        EXPECT_EQ(stats.reflectionCapHits, 0u);
    }
}

// Generalized reflections on the touching cradle: round 1's active set is contact (0, 1)
// alone (the others do not approach): equal masses, elastic, they swap: 0 stops, 1 takes
// v0. Round 2: (1, 2) alone approaches, and so on; round 4 leaves sphere 4 at v0, the
// others at rest, and round 5 finds nothing approaching. Break-away, where the global
// solve moved the whole row at 0.4 v0.
TEST(MultipleCollisions, GeneralizedReflectionsSendTheCradlesLastBallAlone) {
    physics::World world = fixtures::cradle(2.0);
    physics::Params params = exact(Solver::GeneralizedReflections, Method::VelocityBased);
    params.passes = 1;
    const physics::StepStats stats = physics::step(world, params);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(world.velocity[k].x, k == 4 ? 2.0 : 0.0, 1e-12) << k;
    EXPECT_EQ(stats.reflectionRounds, 4u);
    EXPECT_NEAR(kinetic(world), 2.0, 1e-12);
}

// The same cradle at beta = 0.5: each round's impulse is the blend of the inelastic
// answer (the pair moves on together at v/2) and the elastic one (they swap):
// lambda = (1 - beta) v/2 + beta v = 3v/4. Round 1: sphere 0 keeps v/4, 1 takes 3v/4.
// Round 2: (1, 2) approaches at 3v/4: 1 keeps 3v/16, 2 takes 9v/16. Then (0, 1) approaches
// (v/4 > 3v/16), and so on: the rounds run until the row is ordered by speed.
TEST(MultipleCollisions, GeneralizedRestitutionBlendsTheInelasticAndElasticAnswers) {
    physics::World world = fixtures::cradle(2.0);
    physics::Params params = exact(Solver::GeneralizedReflections, Method::VelocityBased);
    params.beta = 0.5;
    params.passes = 1;
    physics::Params one = params;
    physics::World pair;  // two touching spheres: one round, v/4 and 3v/4
    pair.addSphere({0, 0, 0}, {2.0, 0, 0}, 0.125, 1.0);
    pair.addSphere({0.25, 0, 0}, {0, 0, 0}, 0.125, 1.0);
    physics::step(pair, one);
    EXPECT_NEAR(pair.velocity[0].x, 0.5, 1e-12);
    EXPECT_NEAR(pair.velocity[1].x, 1.5, 1e-12);
    const physics::StepStats stats = physics::step(world, params);
    for (int k = 0; k + 1 < 5; ++k) EXPECT_LE(world.velocity[k].x, world.velocity[k + 1].x + 1e-9) << k;
    EXPECT_NEAR(world.velocity[0].x + world.velocity[1].x + world.velocity[2].x + world.velocity[3].x +
                    world.velocity[4].x, 2.0, 1e-12);
    EXPECT_LT(kinetic(world), 2.0);
    EXPECT_GT(stats.reflectionRounds, 4u);
    EXPECT_EQ(stats.reflectionCapHits, 0u);
}

// The continuous method meets both impacts of Bernoulli's problem at one instant (sphere 0
// starts 0.5 mm above the others, at 1 m/s: t* = 0.5 ms into the step). Taken one after the
// other (sequential), the first breaks the symmetry as in the methods above: at t* sphere 1
// gets (-s3/4, 0, -3/4), then sphere 2 (s3/8, 0, -3/8). With lcp or generalized reflections
// they are answered together: the global solve's answer, (0, 0, 0.2) and (-/+s3/5, 0, -0.6);
// with simultaneous, the responses summed: (0, 0, 0.5) and (-/+s3/4, 0, -0.75), energy x1.75.
TEST(MultipleCollisions, TheContinuousMethodAnswersImpactsAtOneInstantTogether) {
    const double s3 = 2.0 * kS3;
    for (Solver solver : {Solver::Sequential, Solver::Simultaneous, Solver::Lcp, Solver::GeneralizedReflections}) {
        physics::World world;
        world.addSphere({0.0, 0.0, 0.2 * kS3 + 0.0005}, {0.0, 0.0, -1.0}, 0.1, 1.0);
        world.addSphere({-0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, 1.0);
        world.addSphere({0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, 1.0);
        physics::Params params = exact(solver, Method::Continuous);
        const physics::StepStats stats = physics::step(world, params);
        EXPECT_EQ(stats.events, 2u);
        if (solver == Solver::Sequential) {
            expectVelocity(world, 1, {-s3 / 4, 0.0, -0.75});
            expectVelocity(world, 2, {s3 / 8, 0.0, -0.375});
        } else if (solver == Solver::Simultaneous) {
            expectVelocity(world, 0, {0.0, 0.0, 0.5});
            expectVelocity(world, 1, {-s3 / 4, 0.0, -0.75});
            expectVelocity(world, 2, {s3 / 4, 0.0, -0.75});
            EXPECT_NEAR(kinetic(world), 0.875, 1e-12);
            continue;
        } else {
            expectVelocity(world, 0, {0.0, 0.0, 0.2});
            expectVelocity(world, 1, {-s3 / 5, 0.0, -0.6});
            expectVelocity(world, 2, {s3 / 5, 0.0, -0.6});
        }
        EXPECT_NEAR(kinetic(world), 0.5, 1e-12);
    }
}

// Every preset (at most 300 spheres), position based, under until-converged, lcp and
// generalized reflections, for 2 s without its emitter: E~ never rises (simultaneous can,
// on purpose: see above). The lcp solver leaves out contacts that separate faster than
// epsilon: held at c+ >= 0 with them, the fast gas gained 11.3 % in 2 s and the two
// strikers 192 % (measured before the change). Every run prints the caps its solver
// reached (until-converged: solver steps that ran K passes; generalized reflections:
// clusters stopped at a cap) and its most rounds in a step: they terminate on every preset.
// Generalized reflections never reach their work cap: before resting contacts were solved
// to 1e-12 m/s (clusterTolerance) they reached it on the pyramid, the pile and the rain,
// and before the cap was raised to 10^7 visits, once on the column of 20 as it first
// settles (an impact along a chain of 20 contacts: 5.3 x 10^6 visits in 696 rounds).
TEST(MultipleCollisions, NoPresetCreatesEnergyUnderTheConvergedAndGlobalSolvers) {
    for (const std::string& name : scenes::listPresets()) {
        for (const char* solver : {"solver=until-converged", "solver=lcp", "solver=generalized-reflections"}) {
            scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
            ASSERT_EQ(scenes::applySetting(scene, "method=position"), "");
            ASSERT_EQ(scenes::applySetting(scene, solver), "");
            if (!scene.generators.empty()) {  // at most 300 spheres: time
                ASSERT_EQ(scenes::applySetting(scene, "count=300"), "");
            }
            const physics::Params& params = scene.params;
            if (params.alpha > 1.0 || params.beta > 1.0 || params.mu > 1.0) continue;
            physics::World world = scenes::buildWorld(scene);
            const double start = physics::modifiedEnergy(world, params);
            physics::StepStats worst;  // the caps the solvers reached, and their most rounds
            for (double t = 0.0; t < 2.0; t += params.timeStep) {
                const physics::StepStats stats = physics::step(world, params);
                worst.passCapHits += stats.passCapHits;
                worst.reflectionCapHits += stats.reflectionCapHits;
                worst.reflectionRounds = std::max(worst.reflectionRounds, stats.reflectionRounds);
            }
            const double rise = (physics::modifiedEnergy(world, params) - start) / std::max(std::abs(start), 1e-12);
            EXPECT_LE(rise, 1e-9) << name << " " << solver;
            EXPECT_EQ(worst.reflectionCapHits, 0u) << name << " " << solver;
            std::printf("%-24s %-32s solver steps at K %5llu, capped clusters %5llu, most rounds a step %llu\n",
                        name.c_str(), solver, static_cast<unsigned long long>(worst.passCapHits),
                        static_cast<unsigned long long>(worst.reflectionCapHits),
                        static_cast<unsigned long long>(worst.reflectionRounds));
        }
    }
}

// Positivity at the step's end, the fifth property, where the global solvers meet a pile:
// alpha and mu act after each normal solve, and at a sphere with several contacts they tilt
// its velocity into another; the shock sweep answers against frozen spheres. Before
// endWithPositivity the 1k pile under the position method ended steps with a contact
// approaching at 0.85 m/s, 22_shock_pyramid with shock at 1.1e-3 m/s. Now no touching
// contact approaches faster than kConvergedApproachSpeed at any step's end, under each
// method, landing (a pile of 300) and resting (the pyramid, shock on). Simultaneous, the
// pairwise Jacobi, does not answer them so: the landing pile of 600 ends steps approaching
// at up to 2.7 m/s (position) and 0.09 m/s (velocity), the size asserted. (The global
// solvers' pile was 600 too: generalized reflections took 29 and 18 s on it, 2 and 8 s on
// 300, which still fails them without endWithPositivity, checked on 2026-11-29.)
namespace {

double fastestApproachLeft(const char* preset, std::initializer_list<std::string> settings, int steps) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath(preset));
    for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
    physics::World world = scenes::buildWorld(scene);
    world.measureImpacts = true;
    double fastest = 0.0;  // m/s
    for (int k = 0; k < steps; ++k) {
        fastest = std::max(fastest, physics::step(world, scene.params).impacts.fastestApproachAfter);
    }
    return fastest;
}

void expectPositivityUnderTheGlobalSolvers(const std::string& method) {
    for (const std::string solver : {"solver=lcp", "solver=generalized-reflections"}) {
        SCOPED_TRACE(method + " " + solver);
        EXPECT_LE(fastestApproachLeft("11_pile", {method, solver, "count=300"}, 150), physics::kConvergedApproachSpeed);
        EXPECT_LE(fastestApproachLeft("22_shock_pyramid", {method, solver, "shock=on"}, 240),
                  physics::kConvergedApproachSpeed);
    }
}

}  // namespace

TEST(MultipleCollisions, TheGlobalSolversLeaveNothingApproachingUnderThePositionMethod) {
    expectPositivityUnderTheGlobalSolvers("method=position");
    EXPECT_NEAR(fastestApproachLeft("11_pile", {"solver=simultaneous", "count=600"}, 150), 2.68, 0.05);
}

TEST(MultipleCollisions, TheGlobalSolversLeaveNothingApproachingUnderTheVelocityMethod) {
    expectPositivityUnderTheGlobalSolvers("method=velocity");
    EXPECT_NEAR(fastestApproachLeft("11_pile", {"method=velocity", "solver=simultaneous", "count=600"}, 150), 0.0945,
                0.005);
}

TEST(MultipleCollisions, TheGlobalSolversLeaveNothingApproachingUnderTheReflectionMethod) {
    expectPositivityUnderTheGlobalSolvers("method=reflection");
}

// The most kinetic energy after / before of the clusters `steps` steps of `preset` (with
// `settings`) struck, their most momentum change / sum m |v| (those free of walls), and how
// many contacts were struck.
struct StruckClusters {
    double energy = 0.0, momentum = 0.0;
    std::uint64_t struck = 0;
    int momentumMeasured = 0;  // steps with a struck cluster free of walls
};
StruckClusters struckClusters(const std::string& preset, const std::vector<std::string>& settings, int steps) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath(preset));
    for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
    physics::World world = scenes::buildWorld(scene);
    world.measureImpacts = true;
    StruckClusters most;
    for (int k = 0; k < steps; ++k) {
        const physics::ImpactProperties p = physics::step(world, scene.params).impacts;
        if (p.kineticBefore > 0.0) most.energy = std::max(most.energy, p.kineticAfter / p.kineticBefore);
        if (p.momentumScale > 0.0) most.momentum = std::max(most.momentum, p.momentumChange / p.momentumScale);
        most.momentumMeasured += p.momentumScale > 0.0;
        most.struck += p.struck;
    }
    return most;
}

// The energy and momentum properties are measured over the clusters a step struck,
// together with the spheres the step brought into contact with them: a falling sphere
// projected onto the landing pile gives it energy and momentum. Counted without it, 300
// spheres landing under lcp showed the struck clusters' kinetic energy rising 0.018 % in
// a step (energy ✗) while the whole world's fell.
TEST(MultipleCollisions, AFallingSphereThatJoinsAStruckClusterIsCountedWithIt) {
    for (const char* solver : {"solver=lcp", "solver=generalized-reflections"}) {
        SCOPED_TRACE(solver);
        const StruckClusters most = struckClusters("11_pile", {solver, "count=300"}, 120);
        EXPECT_GT(most.struck, 1000u);
        EXPECT_LE(most.energy, 1.0 + 1e-9);
        EXPECT_LT(most.momentum, 1e-12);
    }
}

// So is a pair the passes brought together and then carried apart: in the fast gas (15),
// whose overlaps reach 200 % of r, the later passes' projections left such a pair beyond the
// margin, and the lecture's elastic exchange, exact for the whole world, read "✗ momentum
// ✗ energy" on view A from step 685 (0.9956 to 1.0005 of the energy, 8 % of the momentum).
TEST(MultipleCollisions, APairThePassesMetAndCarriedApartIsCountedTogether) {
    const StruckClusters most = struckClusters("15_fast_gas", {}, 900);
    EXPECT_GT(most.struck, 10000u);
    EXPECT_GT(most.momentumMeasured, 850) << "joined to the walls' clusters, the free ones went unmeasured";
    EXPECT_LE(most.energy, 1.0 + 1e-9);
    EXPECT_LT(most.momentum, 1e-12);
}

// Break-away is tested only where an impact struck (a contact faster than epsilon): a
// column at rest has nothing that should part (09 showed ✗ "0 of 2408 resting pairs
// parted"); Bernoulli's struck pair is counted.
TEST(MultipleCollisions, AStackAtRestTestsNoBreakAway) {
    const auto restingPairs = [](const char* preset, int steps) {
        scenes::Scene scene = scenes::loadScene(scenes::presetPath(preset));
        physics::World world = scenes::buildWorld(scene);
        world.measureImpacts = true;
        std::uint64_t pairs = 0;
        for (int k = 0; k < steps; ++k) pairs += physics::step(world, scene.params).impacts.restingPairs;
        return pairs;
    };
    EXPECT_EQ(restingPairs("09_column", 600), 0u);
    EXPECT_EQ(restingPairs("16_bernoulli", 1), 1u);
}
