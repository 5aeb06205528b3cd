#pragma once
// Where the app's scene comes from: a file or a shipped preset, plus --set overrides.
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace app {

// Thrown for bad command-line input; main prints what() and exits with code 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws UsageError "FLAG PATH: ..." unless `path` is empty or can be written: it cannot
// be written, its folder does not exist, it is a folder, or it does not end in EXTENSION (a
// CSV written into x.json). Output files are checked before any work; the check leaves
// nothing behind.
void checkWritable(const std::string& flag, const std::string& path, const std::string& extension = "");

// Whether `s` ends in `suffix`.
bool endsWith(const std::string& s, const std::string& suffix);

// A scene's refusal without the generator it names ("generate[0]: the region holds only
// ..." reads "the region holds only ..."), where the file's place is not news.
std::string withoutGenerator(std::string reason);

// "--set count=1000000: the scene cannot be built: the region holds only ...": the refusal
// of a scene that `settings` left unbuildable, as theirs.
std::string settingsRefusal(const std::vector<std::string>& settings, const std::string& reason);

// Returns build() (which builds the world of a scene loaded with `settings`); a scene the
// settings leave unbuildable (a count its region cannot hold) is refused as theirs
// (UsageError), not as the file's. The world is built once, where it is used.
template <class Build>
auto builtWithSettings(const std::vector<std::string>& settings, Build build) -> decltype(build()) {
    try {
        return build();
    } catch (const scenes::SceneError& e) {
        if (settings.empty()) throw;
        throw UsageError(settingsRefusal(settings, e.what()));
    }
}

// `nameOrPath` is a file, or a preset name with or without its number and .json
// ("pile", "11_pile"). Then every "name=value" of `settings` is applied, in order.
// Throws scenes::SceneError (file:line:col) or UsageError.
scenes::Scene loadSceneWithSettings(const std::string& nameOrPath,
                                    const std::vector<std::string>& settings);

// --compare's lists for `scene`: throws UsageError "--compare ..." naming what is refused;
// where they change nothing in it (beta=1 where beta is 1), says so in one line on stderr.
void checkCompareOption(const scenes::Scene& scene, const std::vector<std::string>& lists);

// The file behind a preset name or path; empty when there is none. Throws
// UsageError when a fragment matches several presets.
std::string resolveScenePath(const std::string& nameOrPath);

}  // namespace app
