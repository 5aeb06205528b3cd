// The app's fixed-step clock: accumulator, clamp, wall-time budget.
#include <gtest/gtest.h>

#include "app/run/simulation.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

app::Simulation pile() { return app::Simulation(scenes::loadScene(scenes::presetPath("11_pile"))); }

}  // namespace

TEST(Simulation, AdvanceSpendsRealTimeInWholeStepsOfH) {
    app::Simulation sim = pile();
    const double h = sim.params().timeStep;
    EXPECT_EQ(sim.advance(2.5 * h), 2);   // 2 steps, half a step left over
    EXPECT_EQ(sim.advance(0.5 * h), 1);   // the half left over completes a third
    EXPECT_EQ(sim.world().stepCount, 3u * static_cast<unsigned>(sim.params().substeps));
    EXPECT_FALSE(sim.behindRealTime());
}

TEST(Simulation, TooMuchTimeIsClampedAndSaidSo) {
    app::Simulation sim = pile();
    const double h = sim.params().timeStep;
    EXPECT_EQ(sim.advance(100 * h), app::Simulation::kMaxStepsPerFrame);
    EXPECT_TRUE(sim.behindRealTime());
    EXPECT_EQ(sim.advance(h), 1);  // the lag was dropped, not carried over
}

TEST(Simulation, AWallBudgetStopsAfterTheFirstStepItExceeds) {
    app::Simulation sim = pile();
    sim.wallBudget = 0.0;  // s: any step exceeds it
    EXPECT_EQ(sim.advance(10 * sim.params().timeStep), 1);
    EXPECT_TRUE(sim.behindRealTime());
    sim.paused = true;
    EXPECT_EQ(sim.advance(10 * sim.params().timeStep), 0);
}
