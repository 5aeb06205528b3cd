#include "app/commands/claims_command.h"

#include <cstdio>

#include "app/run/scene_source.h"
#include "scenes/claims.h"
#include "scenes/presets.h"

namespace app {
namespace {

// " (with beta=0.5, mu=1)" for a claim about the scene with other settings; "" for its own.
std::string withSettings(const std::vector<std::string>& settings) {
    std::string text;
    for (const std::string& setting : settings) text += (text.empty() ? " (with " : ", ") + setting;
    return text.empty() ? text : text + ")";
}

}  // namespace

namespace {

// What a claim may measure, for a teacher writing one: name, unit, meaning.
int listMeasures() {
    for (const scenes::ClaimMeter& m : scenes::claimMeters()) {
        const std::string unit = m.unit.empty() ? "" : " (" + std::string(m.unit) + ")";
        std::printf("%s%s: %s\n", std::string(m.name).c_str(), unit.c_str(), std::string(m.what).c_str());
    }
    return 0;
}

}  // namespace

int runClaims(const ClaimsOptions& options) {
    if (options.measures) return listMeasures();
    const std::vector<std::string> names = options.scenes.empty() ? scenes::listPresets() : options.scenes;
    std::vector<scenes::Scene> loaded;  // all loaded first: a bad name ends the command before any run
    for (const std::string& name : names) loaded.push_back(loadSceneWithSettings(name, {}));
    int held = 0, failed = 0;
    std::vector<std::string> failures;  // repeated at the end: a long log's ✗ lines are far above it
    for (std::size_t k = 0; k < names.size(); ++k) {
        const scenes::Scene& scene = loaded[k];
        std::printf("%s  %s\n", names[k].c_str(), scene.title.c_str());
        if (scene.claims.empty()) std::printf("  (its text claims nothing a run can measure)\n");
        for (const scenes::ClaimCheck& check : scenes::checkClaims(scene)) {
            std::printf("  %s \"%s\"%s: %s\n", check.holds ? "\u2713" : "\u2717",
                        scenes::withCount(check.claim->says, scene).c_str(),
                        withSettings(check.claim->settings).c_str(), check.measured.c_str());
            (check.holds ? held : failed) += 1;
            if (!check.holds) failures.push_back(names[k] + ": \"" + scenes::withCount(check.claim->says, scene) + "\"");
        }
        std::fflush(stdout);
    }
    if (!failures.empty()) std::printf("Failed:\n");
    for (const std::string& failure : failures) std::printf("  \u2717 %s\n", failure.c_str());
    std::printf("The text, measured: %d \u2713 %d \u2717 of %d claims in %zu scene%s\n", held, failed, held + failed,
                names.size(), names.size() == 1 ? "" : "s");
    return failed == 0 ? 0 : 1;
}

}  // namespace app
