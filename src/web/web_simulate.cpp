// The page's runs without a view, called from index.html (Module.ccall): the same code
// as `spheres simulate` (the preset named as on the command line, the settings as --set
// takes them, then `steps` time steps h, each of `substeps` solver steps, with the scene's
// emitters), and the presets.
// Each returns JSON text (valid until the next call).
#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"
#include "web/web_scenes.h"

namespace {

using web::answer;
using web::Json;

constexpr std::int64_t kMostSteps = 1000000;  // a page asks for a run, not a day's

}  // namespace

extern "C" {

// [{"name": "01_bounce_response_only", "title": "...", "slide": "Rigid spheres 5–6/14: ..."}, ...]
EMSCRIPTEN_KEEPALIVE const char* spheres_presets() {
    Json list = Json::array();
    for (const std::string& name : scenes::listPresets()) {
        const scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
        list.push_back({{"name", name}, {"title", scenes::withCount(scene.title, scene)}, {"slide", scene.slide}});
    }
    return answer(list);
}

// {"scene", "steps", "time_s", "spheres", "hash", "kinetic_J", "potential_J", "total_J",
//  "modified_J", "penetration_r"} after `steps` steps, or {"error": "..."}.
EMSCRIPTEN_KEEPALIVE const char* spheres_simulate(const char* name, const char* settings, int steps) {
    try {
        if (steps < 0 || steps > kMostSteps) throw std::runtime_error("steps must be between 0 and 1000000");
        const scenes::Scene scene = web::sceneWithSettings(name, settings);
        physics::World world = scenes::buildWorld(scene);
        world.measureImpacts = world.size() <= physics::kMostMirroredSpheres;  // as `spheres simulate`
        for (int k = 0; k < steps; ++k) {
            physics::step(world, scene.params);
            scenes::emitDue(scene, world);
        }
        const physics::Diagnostics d = physics::measure(world, scene.params);
        return answer({{"scene", scenes::withCount(scene.title, scene)},
                       {"steps", steps},
                       {"time_s", world.time},
                       {"spheres", world.size()},
                       {"hash", web::hexHash(d.hash)},
                       {"kinetic_J", d.kinetic},
                       {"potential_J", d.potential},
                       {"total_J", d.total},
                       {"modified_J", d.modified},
                       {"penetration_r", d.maxPenetration}});
    } catch (const std::exception& e) {
        return answer({{"error", e.what()}});
    }
}

}  // extern "C"
