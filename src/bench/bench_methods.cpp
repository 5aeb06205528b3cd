// Slide 7 says going back in time is "computationally heavy": how heavy, measured.
// The gas and the pile presets scaled to N spheres (the radius as N^(-1/3), so each
// keeps its volume), advanced by each method from one state: position (projection),
// reflection, continuous with the closed-form instant and with the slide's bisection.
// The pile lands first (--warm-up simulated seconds, position based). A row gives ms
// per solver step (median of the repetitions), impacts and bisection iterations per
// solver step, and the ratio to the position method on the same state.
// With --solvers: slide 14's solvers instead, position based, on the same states
// (until-converged with K = 100), with passes and LCP sweeps per solver step.
//   usage: spheres_bench_methods --help
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_common.h"
#include "physics/step.h"

namespace {

struct Options {
    std::vector<int> counts{1000, 10000};
    std::vector<std::string> scenes{"gas", "pile"};
    double warmUp = 1.5;  // s simulated: the pile has landed
    double block = 1.0;   // s of wall time per repetition (at least 3 time steps)
    int repetitions = 3;
    bool solvers = false;  // slide 14's solvers instead of slide 7's answers
};

const bench::Usage kUsage{"spheres_bench_methods",
    "usage: spheres_bench_methods [options]\n"
    "Times slide 7's answers (position, reflection, continuous closed-form and bisection)\n"
    "on the gas and the pile; prints a markdown table.\n"
    "  --n LIST       sphere counts (default 1k,10k)\n"
    "  --scene NAME   gas or pile (default both)\n"
    "  --warm-up S    simulated seconds of the pile before timing (default 1.5)\n"
    "  --reps R       timed repetitions (default 3)\n"
    "  --solvers      slide 14's solvers (sequential, until-converged, simultaneous, lcp,\n"
    "                generalized-reflections) instead\n"};

[[noreturn]] void usageError(const std::string& why) { bench::usageError(kUsage, why); }

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string option = argv[k];
        bench::helpIfAsked(kUsage, option);
        if (option == "--solvers") {
            o.solvers = true;
            continue;
        }
        if (k + 1 >= argc) usageError(option + ": expected a value after it");
        const std::string value = argv[++k];
        std::vector<int> numbers;
        if (option == "--n") {
            if (!bench::parseCounts(value, o.counts)) usageError("--n " + value + ": expected numbers such as 1k,10k");
        } else if (option == "--scene") {
            if (value != "gas" && value != "pile") usageError("--scene " + value + ": expected gas or pile");
            o.scenes = {value};
        } else if (option == "--warm-up") {
            if (!bench::parseSimulatedSeconds(value, o.warmUp)) usageError("--warm-up " + value + ": expected 0 to 600 s");
        } else if (option == "--reps") {
            if (!bench::parseCounts(value, numbers)) usageError("--reps " + value + ": expected a number");
            o.repetitions = numbers.front();
        } else {
            usageError("unknown option " + option);
        }
    }
    return o;
}

scenes::Scene sceneOf(const std::string& name, int count) {
    if (name == "pile") return bench::pileOf(count);
    scenes::Scene scene = bench::loadPreset(bench::presetContaining("gas"));
    bench::set(scene, "count=" + std::to_string(count));
    bench::set(scene, "radius=" + scenes::formatNumber(bench::scaledRadius(0.05, 300, count)));
    return scene;
}

struct Method {
    const char* label;
    std::vector<std::string> settings;
};

const std::vector<Method> kSolvers = {
    {"sequential, K = 4 (the lecture's)", {"solver=sequential"}},
    {"until-converged, K = 100", {"solver=until-converged", "passes=100"}},
    {"simultaneous, K = 4", {"solver=simultaneous"}},
    {"lcp", {"solver=lcp"}},
    {"generalized-reflections", {"solver=generalized-reflections"}},
};

const std::vector<Method> kMethods = {
    {"position (projection)", {"method=position"}},
    {"reflection", {"method=reflection"}},
    {"continuous, closed-form", {"method=continuous", "toi=closed-form"}},
    {"continuous, bisection", {"method=continuous", "toi=bisection"}},
};

struct Timing {
    double msPerStep = 0.0;  // ms per solver step, median
    double events = 0.0, iterations = 0.0, capped = 0.0;  // per solver step
    double passes = 0.0, sweeps = 0.0, rounds = 0.0;      // per solver step
    std::uint64_t roundCaps = 0;                          // passes that reached the cap of rounds
};

Timing timeMethod(const scenes::Scene& base, const Method& method, const physics::World& start, const Options& o) {
    scenes::Scene scene = base;
    for (const std::string& setting : method.settings) bench::set(scene, setting);
    std::vector<double> perStep;
    Timing timing;
    for (int rep = 0; rep < o.repetitions; ++rep) {
        physics::World world = start;
        physics::step(world, scene.params);  // warm the workspace, untimed
        physics::StepStats stats;
        int steps = 0;
        const auto began = std::chrono::steady_clock::now();
        while (steps < 3 || bench::secondsSince(began) < o.block) {
            stats += physics::step(world, scene.params);
            ++steps;
        }
        const double solverSteps = double(steps) * scene.params.substeps;
        perStep.push_back(1e3 * bench::secondsSince(began) / solverSteps);
        timing.events = double(stats.events) / solverSteps;
        timing.iterations = double(stats.toiIterations) / solverSteps;
        timing.capped = double(stats.cappedSteps) / solverSteps;
        timing.passes = double(stats.passesUsed) / solverSteps;
        timing.sweeps = double(stats.lcpSweeps) / solverSteps;
        timing.rounds = double(stats.reflectionRounds) / solverSteps;
        timing.roundCaps = stats.reflectionCapHits;
    }
    timing.msPerStep = bench::median(perStep);
    return timing;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    const std::vector<Method>& rows = o.solvers ? kSolvers : kMethods;
    std::printf("%s, one thread; %s; load %s\n\n", o.solvers ? "Slide 14's solvers" : "Slide 7's answers",
                bench::cpuModel().c_str(), bench::loadAverage().c_str());
    if (o.solvers) {
        std::printf("| scene | N | solver | ms per solver step | × sequential | passes per step | LCP sweeps per step | "
                    "reflection rounds per step (capped passes) |\n");
        std::printf("|---|---:|---|---:|---:|---:|---:|---:|\n");
    } else {
        std::printf("| scene | N | method | ms per solver step | × position | impacts per step | bisection iterations per step | capped steps |\n");
        std::printf("|---|---:|---|---:|---:|---:|---:|---:|\n");
    }
    for (const std::string& name : o.scenes) {
        for (int count : o.counts) {
            scenes::Scene scene = sceneOf(name, count);
            bench::set(scene, "threads=1");
            physics::World start = scenes::buildWorld(scene);
            if (name == "pile") {
                for (double t = 0.0; t < o.warmUp; t += scene.params.timeStep) physics::step(start, scene.params);
            }
            double position = 0.0;
            for (const Method& method : rows) {
                const Timing t = timeMethod(scene, method, start, o);
                if (position == 0.0) position = t.msPerStep;
                if (o.solvers) {
                    std::printf("| %s | %s | %s | %.3f | %.2f | %.1f | %.0f | %.1f (%llu) |\n", name.c_str(),
                                bench::grouped(count).c_str(), method.label, t.msPerStep, t.msPerStep / position,
                                t.passes, t.sweeps, t.rounds, static_cast<unsigned long long>(t.roundCaps));
                } else {
                    std::printf("| %s | %s | %s | %.3f | %.2f | %.1f | %.0f | %.0f %% |\n", name.c_str(),
                                bench::grouped(count).c_str(), method.label, t.msPerStep, t.msPerStep / position,
                                t.events, t.iterations, 100.0 * t.capped);
                }
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
