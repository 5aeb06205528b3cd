#include "app/simulation.h"

#include <chrono>
#include <utility>

namespace app {

Simulation::Simulation(scenes::Scene scene) : scene_(std::move(scene)) { restart(); }

void Simulation::setScene(scenes::Scene scene) {
    scene_ = std::move(scene);
    restart();
}

void Simulation::restart() {
    world_ = scenes::buildWorld(scene_);
    accumulator_ = 0.0;
    lastStats_ = {};
    behind_ = false;
    history_.clear();
    measureNow();
}

int Simulation::advance(double realSeconds) {
    if (paused) return 0;
    const double h = scene_.params.timeStep;
    accumulator_ += realSeconds * timeScale;
    int steps = 0;
    while (accumulator_ >= h && steps < kMaxStepsPerFrame) {
        stepOnce();
        accumulator_ -= h;
        ++steps;
    }
    behind_ = accumulator_ >= h;
    if (behind_) accumulator_ = 0.0;
    if (steps > 0) measureNow();
    return steps;
}

void Simulation::singleStep() {
    stepOnce();
    measureNow();
}

void Simulation::stepOnce() {
    const auto start = std::chrono::steady_clock::now();
    lastStats_ = physics::step(world_, scene_.params);
    lastStepMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Simulation::measureNow() {
    diagnostics_ = physics::measure(world_, scene_.params);
    history_.add(world_.time, diagnostics_);
}

}  // namespace app
