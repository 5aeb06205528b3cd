// The solver's speed on the pile preset (07_pile) at N = 1k, 10k, 100k: the grid
// broad phase against the lecture's O(N^2) loop (up to 10k). The radius shrinks as
// N^(-1/3) so that the pile keeps its volume. Prints ms per solver step and ns per
// sphere-step, once the pile has landed (3 s of warm-up; the O(N^2) loop is timed
// while it falls, which changes nothing for it).
//   usage: spheres_bench_solver [max N] [passes K]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

scenes::Scene pileOf(int count, int passes, const char* broadPhase) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("07_pile"));
    const double radius = 0.05 * std::cbrt(1000.0 / count);  // m
    for (const std::string& setting :
         {"count=" + std::to_string(count), "radius=" + std::to_string(radius),
          "passes=" + std::to_string(passes), std::string("broadphase=") + broadPhase}) {
        const std::string error = scenes::applySetting(scene, setting);
        if (!error.empty()) {
            std::fprintf(stderr, "bench: %s: %s\n", setting.c_str(), error.c_str());
            std::exit(2);
        }
    }
    return scene;
}

void measure(int count, int passes, const char* broadPhase, int warmup, int timed) {
    const scenes::Scene scene = pileOf(count, passes, broadPhase);
    physics::World world = scenes::buildWorld(scene);
    for (int k = 0; k < warmup; ++k) physics::step(world, scene.params);
    const auto start = std::chrono::steady_clock::now();
    physics::StepStats stats;
    for (int k = 0; k < timed; ++k) stats += physics::step(world, scene.params);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double solverSteps = double(timed) * scene.params.substeps;
    std::printf("%-9s %8d %3d %12.3f %14.1f %9.0f %%\n", broadPhase, count, passes, 1e3 * seconds / solverSteps,
                1e9 * seconds / (solverSteps * count), 100.0 * double(stats.broadPhaseBuilds) / solverSteps);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const int maxCount = argc > 1 ? std::atoi(argv[1]) : 100000;
    const int passes = argc > 2 ? std::atoi(argv[2]) : 4;
    std::printf("pile (07_pile), one thread, h/substeps per solver step\n");
    std::printf("%-9s %8s %3s %12s %14s %10s\n", "broad", "N", "K", "ms/step", "ns/sphere-step", "rebuilds");
    for (int count : {1000, 10000, 100000}) {
        if (count > maxCount) break;
        measure(count, passes, "grid", 180, count >= 100000 ? 10 : 30);
    }
    for (int count : {1000, 10000}) {
        if (count > maxCount) break;
        measure(count, passes, "allpairs", 2, count >= 10000 ? 1 : 10);
    }
    return 0;
}
