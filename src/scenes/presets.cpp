#include "scenes/presets.h"

#include <algorithm>
#include <filesystem>

#include "scenes/scene.h"

namespace scenes {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kExtension = ".json";

fs::path presetDirectory() { return fs::path(assetDirectory()) / "scenes"; }

}  // namespace

std::string assetDirectory() { return SPHERES_ASSET_DIR; }

std::vector<std::string> listPresets() {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(presetDirectory(), error)) {
        if (entry.is_regular_file(error) && entry.path().extension() == kExtension) {
            names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string presetPath(std::string_view name) {
    std::string stem(name);
    if (stem.size() > kExtension.size() &&
        stem.compare(stem.size() - kExtension.size(), kExtension.size(), kExtension) == 0) {
        stem.resize(stem.size() - kExtension.size());
    }
    const std::vector<std::string> presets = listPresets();
    if (std::find(presets.begin(), presets.end(), stem) == presets.end()) {
        std::string known;
        for (const std::string& p : presets) known += (known.empty() ? "" : ", ") + p;
        throw SceneError("unknown preset '" + std::string(name) + "'; presets: " + known);
    }
    return (presetDirectory() / (stem + std::string(kExtension))).string();
}

std::string matchPreset(std::string_view name, std::string& why) {
    why.clear();
    std::vector<std::string> partial;
    for (const std::string& stem : listPresets()) {
        const std::size_t underscore = stem.find('_');
        const std::string bare = underscore == std::string::npos ? stem : stem.substr(underscore + 1);
        if (name == stem || name == bare || name == stem + ".json") return presetPath(stem);
        const std::string_view number = std::string_view(stem).substr(0, underscore);
        const auto digitsOnly = [](std::string_view s) {
            return !s.empty() && s.size() <= 4 && s.find_first_not_of("0123456789") == std::string_view::npos;
        };
        if (digitsOnly(name) && digitsOnly(number) && std::stoi(std::string(name)) == std::stoi(std::string(number))) {
            return presetPath(stem);
        }
        if (!name.empty() && bare.find(name) != std::string::npos) partial.push_back(stem);
    }
    if (partial.size() > 1) {
        why = "more than one preset matches: ";
        for (std::size_t k = 0; k < partial.size(); ++k) why += (k > 0 ? ", " : "") + partial[k];
        return "";
    }
    return partial.size() == 1 ? presetPath(partial.front()) : std::string();
}

}  // namespace scenes
