// libFuzzer target: any bytes as a `--set name=value` on each shipped preset (the
// first byte picks the preset). applySetting must answer "" or one line saying why
// not, never throw, and leave the scene unchanged when it refuses; an accepted value
// must read back (formatValue) to a setting that applies again.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

const std::vector<scenes::Scene>& presets() {
    static const std::vector<scenes::Scene> loaded = [] {
        std::vector<scenes::Scene> list;
        for (const std::string& name : scenes::listPresets()) list.push_back(scenes::loadScene(scenes::presetPath(name)));
        return list;
    }();
    return loaded;
}

std::string allValues(const scenes::Scene& scene) {
    std::string text;
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        if (p.availableIn(scene)) text += std::string(p.name) + "=" + scenes::formatValue(p, scene) + ";";
    }
    return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || presets().empty()) return 0;
    scenes::Scene scene = presets()[data[0] % presets().size()];
    const std::string assignment(reinterpret_cast<const char*>(data) + 1, size - 1);
    const std::string before = allValues(scene);
    const std::string error = scenes::applySetting(scene, assignment);
    if (!error.empty()) {
        if (error.find('\n') != std::string::npos || allValues(scene) != before) std::abort();  // not one line, or changed
        return 0;
    }
    // Accepted: every value reads back to a setting the table takes again.
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        if (!p.availableIn(scene)) continue;
        scenes::Scene again = scene;
        if (!scenes::applySetting(again, std::string(p.name) + "=" + scenes::formatValue(p, scene)).empty()) std::abort();
    }
    return 0;
}
