#include "web/web_scenes.h"

#include <sstream>
#include <stdexcept>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace web {

scenes::Scene sceneWithSettings(const std::string& name, const std::string& settings) {
    std::string why;
    const std::string path = scenes::matchPreset(name, why);
    if (path.empty()) {
        throw std::runtime_error("scene " + name + ": " + (why.empty() ? "no such preset" : why));
    }
    scenes::Scene scene = scenes::loadScene(path);
    std::istringstream lines(settings);
    for (std::string setting; std::getline(lines, setting);) {
        if (setting.empty()) continue;
        if (const std::string error = scenes::applySetting(scene, setting); !error.empty()) {
            throw std::runtime_error(setting + ": " + error);
        }
    }
    return scene;
}

}  // namespace web
