#include "app/commands/simulate_command.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "app/commands/diagnostics_log.h"
#include "app/commands/progress_line.h"
#include "app/run/comparison.h"
#include "app/run/scene_source.h"
#include "app/teaching/impact_report.h"
#include "physics/step.h"
#include "platform/whole_file.h"
#include "scenes/scene_json.h"

namespace app {
namespace {

void writeState(const std::string& path, const physics::World& world) {
    std::ostringstream text;
    text.precision(17);
    text << "id,px_m,py_m,pz_m,vx_m_s,vy_m_s,vz_m_s,r_m,m_kg\n";
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 &p = world.position[i], &v = world.velocity[i];
        text << i << ',' << p.x << ',' << p.y << ',' << p.z << ',' << v.x << ',' << v.y << ',' << v.z << ','
             << world.radius[i] << ',' << world.mass[i] << '\n';
    }
    if (!platform::writeWholeFile(path, text.str())) {  // not a truncated state that reads as the whole
        throw UsageError("--state " + path + ": cannot be written whole (is the disk full?)");
    }
}

}  // namespace

int runSimulate(const SimulateOptions& options) {
    const scenes::Scene scene = loadSceneWithSettings(options.scene, options.settings);
    if (options.every > 0 && options.out.empty()) throw UsageError("--every needs --out FILE");
    checkWritable("--state", options.state, ".csv");
    checkWritable("--save", options.save, ".json");
    // Before the log opens: a scene it refuses leaves no .part.
    physics::World world = builtWithSettings(options.settings, [&] { return scenes::buildWorld(scene); });
    std::optional<DiagnosticsLog> log;
    if (!options.out.empty()) log.emplace(options.out);
    const std::int64_t every = options.every > 0 ? options.every : options.steps;

    world.measureImpacts = world.size() <= physics::kMostMirroredSpheres;
    ImpactRecord impacts;
    const physics::Params& params = scene.params;
    if (log) log->write(0, world.time, physics::measure(world, params));
    double seconds = 0.0;
    std::optional<ProgressLine> progress(std::in_place, "steps", static_cast<std::uint64_t>(options.steps));
    for (std::int64_t k = 1; k <= options.steps; ++k) {
        const auto start = std::chrono::steady_clock::now();
        impacts.add(physics::step(world, params).impacts);
        scenes::emitDue(scene, world);  // the course's emitter, as the window and capture do
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        // Every K steps, and the last (--steps 7 --every 3 left the final state out).
        if (log && (k % every == 0 || k == options.steps)) {
            log->write(static_cast<std::uint64_t>(k), world.time, physics::measure(world, params));
        }
        progress->update(static_cast<std::uint64_t>(k));
    }
    progress.reset();  // the line goes before the result is printed
    if (log) log->finish();

    const double sphereSteps = static_cast<double>(options.steps) * params.substeps *
                               static_cast<double>(std::max<std::size_t>(world.size(), 1));
    std::printf("%s: %lld steps, t = %.4f s, %zu sphere%s, wall %.3f s, %.1f ns/sphere-step | %s | "
                "outside the box %zu\n",
                options.scene.c_str(), static_cast<long long>(options.steps), world.time,
                world.size(), world.size() == 1 ? "" : "s", seconds,
                options.steps > 0 && world.size() > 0 ? 1e9 * seconds / sphereSteps : 0.0,
                summarize(physics::measure(world, params)).c_str(),
                physics::spheresOutsideBox(world, 0.0));
    if (impacts.total.contacts > 0 || params.method == physics::Method::Continuous) {  // slide 14: what the contacts kept
        std::vector<physics::MirrorAsymmetry> mirrors;
        for (const physics::Plane& m : scene.mirrors) mirrors.push_back(physics::mirrorAsymmetry(world, m));
        std::printf("properties: %s\n", propertiesLine(judgeProperties(impacts, mirrors, params)).c_str());
    }
    if (!scene.compare.empty()) {  // the window opens it side by side: say which view this is
        std::printf("(the scene as given, view A: its side-by-side views, %s, run with --set)\n",
                    joinedOverrides(scene.compare).c_str());
    }
    if (!options.state.empty()) writeState(options.state, world);
    if (!options.save.empty()) scenes::saveScene(options.save, scene, world);
    return 0;
}

}  // namespace app
