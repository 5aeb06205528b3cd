// The solver's speed on the pile preset (the shipped preset with "pile" in its name)
// at N = 1k, 10k, 100k: the grid broad phase against the lecture's O(N^2) loop (up
// to 10k). The radius shrinks as N^(-1/3) so that the pile keeps its volume. Prints
// ms per solver step and ns per sphere-step, once the pile has landed (3 s of
// warm-up; the O(N^2) loop is timed while it falls, which changes nothing for it).
//   usage: spheres_bench_solver [max N] [passes K]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench/bench_common.h"
#include "physics/step.h"

namespace {

scenes::Scene pileOf(int count, int passes, const char* broadPhase) {
    scenes::Scene scene = bench::pileOf(count);
    bench::set(scene, "passes=" + std::to_string(passes));
    bench::set(scene, std::string("broadphase=") + broadPhase);
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
    std::printf("pile (%s), one thread, h/substeps per solver step\n",
                bench::presetContaining("pile").c_str());
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
