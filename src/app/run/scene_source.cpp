#include "app/run/scene_source.h"

#include <filesystem>
#include <fstream>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace app {

// A preset matches by its full name ("11_pile"), without its number ("pile"), or by
// any part of its name that no other preset shares ("cradle").
void checkWritable(const std::string& flag, const std::string& path) {
    if (path.empty()) return;
    std::ofstream probe(path, std::ios::app);
    if (!probe) throw UsageError(flag + " " + path + ": cannot open the file for writing");
}

std::string resolveScenePath(const std::string& nameOrPath) {
    if (std::filesystem::is_regular_file(nameOrPath)) return nameOrPath;
    if (std::filesystem::is_directory(nameOrPath)) {
        throw UsageError("--scene " + nameOrPath + ": is a folder, not a scene file");
    }
    std::vector<std::string> partial;
    for (const std::string& stem : scenes::listPresets()) {
        const std::size_t underscore = stem.find('_');
        const std::string bare = underscore == std::string::npos ? stem : stem.substr(underscore + 1);
        if (nameOrPath == stem || nameOrPath == bare || nameOrPath == stem + ".json") {
            return scenes::presetPath(stem);
        }
        if (!nameOrPath.empty() && bare.find(nameOrPath) != std::string::npos) partial.push_back(stem);
    }
    if (partial.size() > 1) {
        std::string names;
        for (const std::string& stem : partial) names += (names.empty() ? "" : ", ") + stem;
        throw UsageError("--scene " + nameOrPath + ": more than one preset matches: " + names);
    }
    return partial.size() == 1 ? scenes::presetPath(partial.front()) : std::string();
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
