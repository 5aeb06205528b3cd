// libFuzzer target: any bytes as a scene file. The loader must either return a scene
// or refuse with a SceneError (one line naming the problem); a small scene it accepts
// must also build and step. Anything else (a crash, a sanitizer report, another
// exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "physics/step.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace {
constexpr std::size_t kMostSpheresStepped = 2000;  // larger scenes are parsed only (speed)
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        scenes::Scene scene = scenes::parseScene(text, "fuzz.json");
        if (scenes::builtSphereCount(scene) > kMostSpheresStepped) return 0;
        scene.params.threads = 1;
        physics::World world = scenes::buildWorld(scene);
        for (int k = 0; k < 3; ++k) physics::step(world, scene.params);
    } catch (const scenes::SceneError&) {
        // refused with its reason: what the loader must do with bad input
    }
    return 0;
}
