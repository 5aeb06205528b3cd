#include "web/web_scenes.h"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace web {

const char* answer(const Json& json) {
    static std::string text;
    text = json.dump();
    return text.c_str();
}

std::string hexHash(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::string presetName(const std::string& name) {
    std::string why;
    return std::filesystem::path(scenes::matchPreset(name, why)).stem().string();
}

scenes::Scene sceneWithSettings(const std::string& name, const std::string& settings) {
    std::string why;
    const std::string path = scenes::matchPreset(name, why);
    if (path.empty()) {
        throw std::runtime_error("scene " + name + ": " + (why.empty() ? "no such preset" : why));
    }
    scenes::Scene scene = scenes::loadScene(path);
    std::istringstream lines(settings);
    std::vector<std::string> applied;
    for (std::string setting; std::getline(lines, setting);) {
        if (setting.empty()) continue;
        if (const std::string error = scenes::applySetting(scene, setting); !error.empty()) {
            throw std::runtime_error(setting + ": " + error);
        }
        applied.push_back(setting);
    }
    if (const std::string error = scenes::settingsThatActOnNothing(scene, applied); !error.empty()) {
        throw std::runtime_error(error);
    }
    return scene;
}

}  // namespace web
