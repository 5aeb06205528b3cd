// Step back (app/rewind_buffer.h, app/session.h): a restored state recomputes the
// same future, hash for hash, because the solver's next state is a function of the
// current one; the buffer's memory stays within its caps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "app/run/rewind_buffer.h"
#include "app/run/scene_source.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

scenes::Scene preset(const std::string& name, const std::vector<std::string>& settings = {}) {
    return app::loadSceneWithSettings(name, settings);
}

// Steps `steps` times from the buffer's entry `from` and expects the hashes the
// original run had at the entries after it.
void expectSameFuture(const scenes::Scene& scene, int steps, int from) {
    physics::World world = scenes::buildWorld(scene);
    app::RewindBuffer buffer;
    std::vector<std::uint64_t> hashes{physics::stateHash(world)};
    buffer.push(world);
    for (int s = 0; s < steps; ++s) {
        physics::step(world, scene.params);
        hashes.push_back(physics::stateHash(world));
        buffer.push(world);
    }
    ASSERT_EQ(buffer.size(), std::size_t(steps + 1));
    ASSERT_TRUE(buffer.restore(std::size_t(from), world));
    EXPECT_EQ(physics::stateHash(world), hashes[std::size_t(from)]);
    EXPECT_EQ(world.stepCount, buffer.at(std::size_t(from)).stepCount);
    for (int s = from + 1; s <= steps; ++s) {
        physics::step(world, scene.params);
        ASSERT_EQ(physics::stateHash(world), hashes[std::size_t(s)]) << "step " << s << " after restoring " << from;
    }
}

TEST(Rewind, ARestoredPileRecomputesTheSameFuture) {
    expectSameFuture(preset("pile"), 90, 30);
}

TEST(Rewind, ShuffledPairOrderAndVelocityMethodToo) {
    // The shuffle draws from the seed and the step count: both are part of the state.
    expectSameFuture(preset("pile", {"order=shuffled", "method=velocity", "count=300"}), 60, 25);
    expectSameFuture(preset("gas", {"broadphase=allpairs"}), 60, 10);
}

TEST(Rewind, TheSessionScrubsBackAndResumesWithTheOriginalHashes) {
    // Rain: the emitter adds spheres as time goes on, so the sphere count changes too.
    app::Simulation simulation(preset("rain"));
    simulation.paused = true;
    app::Session session(simulation);
    std::vector<std::uint64_t> hashes{physics::stateHash(simulation.world())};
    std::vector<std::size_t> counts{simulation.world().size()};
    for (int s = 0; s < 150; ++s) {
        session.singleStep();
        hashes.push_back(physics::stateHash(simulation.world()));
        counts.push_back(simulation.world().size());
    }
    ASSERT_GT(counts.back(), counts.front()) << "the rain scene should have emitted spheres";
    ASSERT_EQ(session.timeline().size(), hashes.size());
    session.scrubTo(40);
    EXPECT_TRUE(simulation.paused);
    EXPECT_EQ(physics::stateHash(simulation.world()), hashes[40]);
    EXPECT_EQ(simulation.world().size(), counts[40]);
    EXPECT_EQ(session.diagnostics(0).hash, hashes[40]);  // the readouts show the restored state
    session.stepBack();
    EXPECT_EQ(session.timeline().cursor(), 39u);
    session.stepForward();
    session.stepForward();
    EXPECT_EQ(physics::stateHash(simulation.world()), hashes[41]);
    // Resume: the future after the cursor is dropped and recomputed, identically.
    for (std::size_t s = 42; s < hashes.size(); ++s) {
        session.singleStep();
        ASSERT_EQ(physics::stateHash(simulation.world()), hashes[s]) << "step " << s;
    }
    EXPECT_EQ(session.timeline().size(), hashes.size());
    EXPECT_TRUE(session.timeline().atNewest());
}

// What the panel measured is shown as it was at the frame the timeline shows: stepped back
// before 02's first bounce, the beta^2 readout had kept the later bounces, and stepping on
// counted the same bounce twice; the cradle's slide 14 marks had kept a later step's verdict.
TEST(Rewind, TheMeasuredBouncesAndTheSlideFourteenMarksFollowTheTimeline) {
    app::Simulation simulation(preset("02_bounce_projection"));
    app::Session session(simulation);
    std::vector<std::uint64_t> measured{simulation.restitution().measuredCount()};
    while (simulation.restitution().measuredCount() < 3) {
        session.singleStep();
        measured.push_back(simulation.restitution().measuredCount());
    }
    const std::vector<app::BounceMeasurement> kept(simulation.restitution().last().begin(),
                                                   simulation.restitution().last().end());
    const std::size_t newest = session.timeline().cursor();
    const std::size_t firstBounce = std::size_t(std::find(measured.begin(), measured.end(), 1u) - measured.begin());
    session.scrubTo(firstBounce - 1);
    EXPECT_EQ(simulation.restitution().measuredCount(), 0u);
    EXPECT_TRUE(simulation.restitution().last().empty());
    EXPECT_FALSE(simulation.restitution().latest());
    session.scrubTo(newest);  // forward again through the kept frames
    ASSERT_EQ(simulation.restitution().last().size(), kept.size());
    EXPECT_EQ(simulation.restitution().last().back().time, kept.back().time);
    session.scrubTo(1);  // in the first fall (a bounce under way when the timeline restores is not measured)
    for (std::size_t s = 2; s <= newest; ++s) session.singleStep();  // run on: the same bounces again
    EXPECT_EQ(simulation.restitution().measuredCount(), 3u);
    ASSERT_EQ(simulation.restitution().last().size(), kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(simulation.restitution().last()[k].ratio(), kept[k].ratio());

    app::Simulation cradle(preset("08_newtons_cradle"));
    app::Session cradleSession(cradle);
    for (int s = 0; s < 20; ++s) cradleSession.singleStep();
    const std::uint64_t struck = cradle.impacts().total.struck;
    ASSERT_GT(struck, 0u);
    cradleSession.scrubTo(0);
    EXPECT_EQ(cradle.impacts().total.struck, 0u) << "nothing was struck before the first step";
    EXPECT_EQ(cradle.impacts().worstEnergyRatio, -1.0);
    cradleSession.scrubTo(20);
    EXPECT_EQ(cradle.impacts().total.struck, struck);
}

// The text's claims go on through the timeline: stepped back and run on at the same
// settings, the steps come out as the claims saw them (checked by their hashes), and they
// measure on from the newest, giving what a run never stepped back gives. A sphere moved
// by hand in the replay stops them at the next step, as it does in a run going forward.
TEST(Rewind, TheTextsClaimsMeasureOnThroughStepsBackAndStopWhenTheReplayDiffers) {
    const auto runTo = [](app::Session& session, double time) {
        while (session.run(0).world().time < time) session.singleStep();
    };
    app::Simulation straight(preset("02_bounce_projection"));
    app::Session straightSession(straight);
    runTo(straightSession, 3.0);

    app::Simulation simulation(preset("02_bounce_projection"));
    app::Session session(simulation);
    runTo(session, 1.5);
    session.scrubTo(session.timeline().cursor() / 3);  // back into the first fall
    ASSERT_LT(simulation.world().time, 0.6);
    runTo(session, 2.0);
    session.scrubTo(session.timeline().cursor() - 20);  // and back again, past the newest step the claims saw
    runTo(session, 3.0);
    EXPECT_FALSE(simulation.claimsInterrupted());
    const std::vector<scenes::ClaimCheck> measured = simulation.measuredClaims(), expected = straight.measuredClaims();
    ASSERT_EQ(measured.size(), expected.size());
    EXPECT_GE(measured.size(), 6u);
    for (std::size_t k = 0; k < measured.size(); ++k) {
        EXPECT_EQ(measured[k].measured, expected[k].measured) << measured[k].claim->says;
        EXPECT_EQ(measured[k].samples, expected[k].samples) << measured[k].claim->says;
    }

    session.scrubTo(session.timeline().cursor() - 10);
    simulation.editableWorld().velocity[0].z += 0.5;  // the ball thrown up by hand
    session.singleStep();
    EXPECT_TRUE(simulation.claimsInterrupted());
    EXPECT_EQ(simulation.claimsWatched(), 0u);
    // Back at the start, run on: the claims are watched again, as a restart would watch them.
    session.scrubTo(0);
    ASSERT_EQ(simulation.world().stepCount, 0u);
    session.singleStep();
    EXPECT_FALSE(simulation.claimsInterrupted());
    EXPECT_EQ(simulation.claimsWatched(), straight.claimsWatched());
}

TEST(Rewind, SteppingFromAnEarlierFrameDropsTheFramesAfterIt) {
    app::Simulation simulation(preset("03_head_on"));
    app::Session session(simulation);
    for (int s = 0; s < 10; ++s) session.singleStep();
    session.scrubTo(3);
    EXPECT_EQ(session.timeline().size(), 11u);  // still there while scrubbing
    session.singleStep();
    EXPECT_EQ(session.timeline().size(), 5u);  // 0..3, then the new step 4
    EXPECT_EQ(session.timeline().cursor(), 4u);
}

TEST(Rewind, MemoryStaysWithinTheCaps) {
    physics::World world = scenes::buildWorld(preset("pile"));
    app::RewindBuffer probe;
    probe.push(world);
    const std::size_t one = probe.bytes();
    EXPECT_GE(one, world.size() * (2 * sizeof(glm::dvec3) + 2 * sizeof(double)));

    app::RewindBuffer byBytes(1000, 3 * one + one / 2);
    for (int s = 0; s < 10; ++s) byBytes.push(world);
    EXPECT_EQ(byBytes.size(), 3u);
    EXPECT_LE(byBytes.bytes(), 3 * one + one / 2);

    app::RewindBuffer byFrames(4, std::size_t(1) << 40);
    for (int s = 0; s < 10; ++s) {
        world.time = s;  // tells the entries apart
        byFrames.push(world);
    }
    EXPECT_EQ(byFrames.size(), 4u);
    EXPECT_EQ(byFrames.at(0).time, 6.0);  // the oldest went first
    EXPECT_EQ(byFrames.at(3).time, 9.0);

    app::RewindBuffer tiny(10, 1);  // smaller than one entry: the newest is kept anyway
    tiny.push(world);
    tiny.push(world);
    EXPECT_EQ(tiny.size(), 1u);
    // The default caps: at most 600 frames and 200 MiB.
    EXPECT_EQ(app::RewindBuffer::kDefaultFrames, 600u);
    EXPECT_EQ(app::RewindBuffer::kDefaultBytes, std::size_t(200) << 20);
}

TEST(Rewind, KeepsTheContactsOfTheChosenSphereOnly) {
    physics::World world = scenes::buildWorld(preset("pile"));
    world.recordContacts = true;
    for (int s = 0; s < 100; ++s) physics::step(world, preset("pile").params);
    ASSERT_FALSE(world.contacts.empty());
    const int chosen = static_cast<int>(world.contacts.front().i);
    app::WorldState state;
    app::saveState(world, chosen, state);
    ASSERT_FALSE(state.contacts.empty());
    for (const physics::ContactEvent& e : state.contacts) {
        EXPECT_TRUE(static_cast<int>(e.i) == chosen || e.other == chosen);
    }
    app::saveState(world, -1, state);
    EXPECT_TRUE(state.contacts.empty());
}

}  // namespace
