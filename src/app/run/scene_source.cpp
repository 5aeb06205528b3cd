#include "app/run/scene_source.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "scenes/overrides.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace app {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Opening the file to append tells whether it can be written, and creates it where it was
// not: a probe that created it removes it again, so a refused run leaves nothing behind.
void checkWritable(const std::string& flag, const std::string& path, const std::string& extension) {
    if (path.empty()) return;
    if (!extension.empty() && !endsWith(path, extension)) {
        throw UsageError(flag + " " + path + ": the file must end in " + extension);
    }
    namespace fs = std::filesystem;
    std::error_code error;
    if (fs::is_directory(path, error)) throw UsageError(flag + " " + path + ": is a folder, not a file");
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, error)) {
        throw UsageError(flag + " " + path + ": its folder " + folder.string() +
                         (fs::exists(folder, error) ? " is a file, not a folder" : " does not exist"));
    }
    const bool existed = fs::exists(path, error);
    std::ofstream probe(path, std::ios::app);
    if (!probe) throw UsageError(flag + " " + path + ": cannot open the file for writing");
    probe.close();
    if (!existed) fs::remove(path, error);
}

std::string resolveScenePath(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(nameOrPath, error);
    if (fs::is_regular_file(status)) return nameOrPath;
    std::string why;
    const std::string preset = scenes::matchPreset(nameOrPath, why);
    const bool presetFound = !preset.empty() && why.empty();
    // A folder is no scene: a preset of its name wins (`capture --scene cradle --out cradle/`).
    if (fs::is_directory(status) && !presetFound) {
        throw UsageError("--scene " + nameOrPath + ": is a folder, not a scene file");
    }
    if (fs::exists(status) && !presetFound) {  // a device, a pipe, a socket
        throw UsageError("--scene " + nameOrPath + ": is not a regular file, so no scene file");
    }
    if (error && error != std::errc::no_such_file_or_directory && !presetFound) {
        const bool tooLong = error == std::errc::filename_too_long;  // then its start names it
        throw UsageError("--scene " + (tooLong ? nameOrPath.substr(0, 60) + "..." : nameOrPath) + ": " + error.message());
    }
    if (!why.empty()) throw UsageError("--scene " + nameOrPath + ": " + why);
    return preset;
}

void checkCompareOption(const scenes::Scene& scene, const std::vector<std::string>& lists) {
    if (lists.empty()) return;
    scenes::Variants variants;
    if (const std::string error = scenes::overrideVariants(scene, lists, variants); !error.empty()) {
        throw UsageError("--compare " + error);
    }
    if (scenes::changesNothing(scene, variants)) {
        std::string written;
        for (const std::string& list : lists) written += (written.empty() ? "" : " ") + list;
        std::fprintf(stderr, "spheres: --compare %s changes nothing in this scene (%s already): the views are the same\n",
                     written.c_str(), scenes::overrideLabel(scene, variants.front()).c_str());
    }
}

std::string withoutGenerator(std::string reason) {
    if (reason.rfind("generate[", 0) == 0 && reason.find("]: ") != std::string::npos) reason.erase(0, reason.find("]: ") + 3);
    return reason;
}

std::string settingsRefusal(const std::vector<std::string>& settings, const std::string& reason) {
    std::string given;
    for (const std::string& setting : settings) given += (given.empty() ? "" : " ") + setting;
    return "--set " + given + ": the scene cannot be built: " + withoutGenerator(reason);
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
    if (const std::string error = scenes::settingsThatActOnNothing(scene, settings); !error.empty()) {
        throw UsageError("--set " + error);
    }
    return scene;
}

}  // namespace app
