#include "app/run/comparison.h"

#include <algorithm>
#include <cstdio>
#include <string_view>
#include <utility>

#include "app/run/scene_source.h"
#include "scenes/parameters.h"

namespace app {
namespace {

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
    return text;
}

std::string nameOf(std::string_view setting) { return std::string(trim(setting.substr(0, setting.find('=')))); }

}  // namespace

std::vector<std::string> splitOverrides(const std::vector<std::string>& lists) {
    std::vector<std::string> settings;
    for (const std::string& list : lists) {
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t comma = std::min(list.find(',', start), list.size());
            const std::string_view part = trim(std::string_view(list).substr(start, comma - start));
            if (!part.empty()) settings.emplace_back(part);
            start = comma + 1;
        }
    }
    return settings;
}

std::string checkOverrides(const scenes::Scene& scene, const std::vector<std::string>& overrides) {
    if (overrides.empty()) return "give at least one name=value to compare, e.g. method=velocity";
    scenes::Scene copy = scene;
    for (const std::string& setting : overrides) {
        if (const std::string error = scenes::applySetting(copy, setting); !error.empty()) {
            return setting + ": " + error;
        }
    }
    return "";
}

std::string overrideLabel(const scenes::Scene& scene, const std::vector<std::string>& overrides) {
    std::string label;
    std::vector<std::string> seen;
    for (const std::string& setting : overrides) {
        const std::string name = nameOf(setting);
        const scenes::Parameter* parameter = scenes::findParameter(name);
        if (!parameter || std::find(seen.begin(), seen.end(), name) != seen.end()) continue;
        seen.push_back(name);
        if (!label.empty()) label += ", ";
        label += name + " = " + scenes::formatValue(*parameter, scene);
    }
    return label;
}

Comparison::Comparison(const scenes::Scene& primary, std::vector<std::string> overrides)
    : overrides_(std::move(overrides)), simulation_(withOverrides(primary)) {}

scenes::Scene Comparison::withOverrides(const scenes::Scene& primary) const {
    if (const std::string error = checkOverrides(primary, overrides_); !error.empty()) {
        throw UsageError("--compare " + error);
    }
    scenes::Scene scene = primary;
    for (const std::string& setting : overrides_) scenes::applySetting(scene, setting);
    return scene;
}

void Comparison::restartFrom(const scenes::Scene& primary) {
    const double timeScale = simulation_.timeScale;
    const bool paused = simulation_.paused;
    simulation_.setScene(withOverrides(primary));
    simulation_.timeScale = timeScale;
    simulation_.paused = paused;
}

void Comparison::follow(const Simulation& primary) {
    scenes::Scene& scene = simulation_.editableScene();
    scene.params = primary.scene().params;
    for (const std::string& setting : overrides_) {
        const scenes::Parameter* parameter = scenes::findParameter(nameOf(setting));
        if (parameter && parameter->applies == scenes::Applies::Live) scenes::applySetting(scene, setting);
    }
    simulation_.timeScale = primary.timeScale;
    simulation_.paused = primary.paused;
}

void splitViewport(glm::ivec4 view, int gap, glm::ivec4& left, glm::ivec4& right) {
    const int leftWidth = std::max((view.z - gap) / 2, 1);
    const int rightWidth = std::max(view.z - gap - leftWidth, 1);
    left = {view.x, view.y, leftWidth, view.w};
    right = {view.x + view.z - rightWidth, view.y, rightWidth, view.w};
}

std::vector<std::string> viewReadoutLines(const ViewReadout& view) {
    const physics::Diagnostics& d = view.diagnostics;
    char line[160];
    std::vector<std::string> lines{view.title};
    std::snprintf(line, sizeof line, "E %.6g J   E~ %.6g J", d.total, d.modified);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "p (%.3g, %.3g, %.3g) kg m/s", d.momentum.x, d.momentum.y, d.momentum.z);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "penetration %.2f %% r   t %.3f s", 100.0 * d.maxPenetration, view.time);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "hash %016llx", static_cast<unsigned long long>(d.hash));
    lines.emplace_back(line);
    return lines;
}

}  // namespace app
