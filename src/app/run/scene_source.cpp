#include "app/run/scene_source.h"

#include <filesystem>
#include <fstream>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace app {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void checkWritable(const std::string& flag, const std::string& path, const std::string& extension) {
    if (path.empty()) return;
    if (!extension.empty() && !endsWith(path, extension)) {
        throw UsageError(flag + " " + path + ": the file must end in " + extension);
    }
    std::ofstream probe(path, std::ios::app);
    if (!probe) throw UsageError(flag + " " + path + ": cannot open the file for writing");
}

std::string resolveScenePath(const std::string& nameOrPath) {
    if (std::filesystem::is_regular_file(nameOrPath)) return nameOrPath;
    std::string why;
    const std::string preset = scenes::matchPreset(nameOrPath, why);
    // A folder is no scene: a preset of its name wins (`capture --scene cradle --out cradle/`).
    if (std::filesystem::is_directory(nameOrPath) && (preset.empty() || !why.empty())) {
        throw UsageError("--scene " + nameOrPath + ": is a folder, not a scene file");
    }
    if (!why.empty()) throw UsageError("--scene " + nameOrPath + ": " + why);
    return preset;
}

scenes::Scene loadSceneWithSettings(const std::string& nameOrPath,
                                    const std::vector<std::string>& settings) {
    const std::string path = resolveScenePath(nameOrPath);
    if (path.empty()) {
        throw UsageError("--scene " + nameOrPath +
                         ": no such file and no such preset (see `spheres presets`)");
    }
    scenes::Scene scene = scenes::loadScene(path);
    for (const std::string& setting : settings) {
        const std::string error = scenes::applySetting(scene, setting);
        if (!error.empty()) throw UsageError("--set " + setting + ": " + error);
    }
    return scene;
}

}  // namespace app
