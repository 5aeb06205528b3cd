#pragma once
// The state the app owns: the scene (its parameters are what the UI edits), the
// world built from it, and the fixed-step clock. The window and the capture mode
// both advance it through advance(), so they step exactly alike.
#include <cstdint>

#include "app/history.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/scene.h"

namespace app {

class Simulation {
public:
    explicit Simulation(scenes::Scene scene);

    // Rebuilds the world from the scene (same seed, same initial state).
    void restart();
    void setScene(scenes::Scene scene);

    // Real seconds since the last frame: scaled by timeScale, accumulated, and spent
    // in whole steps of h. At most kMaxStepsPerFrame run per call; time beyond that
    // is dropped (the "spiral of death" guard) and behindRealTime() says so.
    // Returns the number of steps run. Does nothing while paused.
    int advance(double realSeconds);
    void singleStep();  // one step of h, paused or not

    const scenes::Scene& scene() const { return scene_; }
    scenes::Scene& editableScene() { return scene_; }  // live parameters apply at the next step
    const physics::World& world() const { return world_; }
    physics::World& editableWorld() { return world_; }
    const physics::Params& params() const { return scene_.params; }

    bool paused = false;
    double timeScale = 1.0;  // simulated seconds per real second

    const physics::StepStats& lastStepStats() const { return lastStats_; }
    double lastStepMilliseconds() const { return lastStepMs_; }  // ms of wall time, one step
    bool behindRealTime() const { return behind_; }
    const History& history() const { return history_; }
    const physics::Diagnostics& diagnostics() const { return diagnostics_; }

    static constexpr int kMaxStepsPerFrame = 32;

private:
    void stepOnce();
    void measureNow();

    scenes::Scene scene_;
    physics::World world_;
    double accumulator_ = 0.0;  // s of simulated time not yet stepped
    physics::StepStats lastStats_;
    double lastStepMs_ = 0.0;
    bool behind_ = false;
    History history_;
    physics::Diagnostics diagnostics_;
};

}  // namespace app
