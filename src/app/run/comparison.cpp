#include "app/run/comparison.h"

#include <algorithm>
#include <cstdio>
#include <string_view>
#include <utility>

#include "app/run/scene_source.h"
#include "scenes/parameters.h"

namespace app {

Comparison::Comparison(const scenes::Scene& primary, Variants variants) {
    if (variants.empty() || int(variants.size()) > kMostViews - 1) {
        throw UsageError("--compare: 1 to " + std::to_string(kMostViews - 1) + " views besides A");
    }
    for (std::vector<std::string>& overrides : variants) {
        scenes::Scene scene = withOverrides(primary, overrides);
        runs_.push_back({std::move(overrides), std::make_unique<Simulation>(std::move(scene))});
    }
}

scenes::Scene Comparison::withOverrides(const scenes::Scene& primary, const std::vector<std::string>& overrides) {
    if (const std::string error = checkOverrides(primary, overrides); !error.empty()) {
        throw UsageError("--compare " + error);
    }
    scenes::Scene scene = primary;
    for (const std::string& setting : overrides) scenes::applySetting(scene, setting);
    return scene;
}

void Comparison::restartFrom(const scenes::Scene& primary) {
    for (Run& run : runs_) {
        const double timeScale = run.simulation->timeScale;
        const bool paused = run.simulation->paused;
        run.simulation->setScene(withOverrides(primary, run.overrides));
        run.simulation->timeScale = timeScale;
        run.simulation->paused = paused;
    }
}

void Comparison::follow(const Simulation& primary) {
    for (Run& run : runs_) {
        scenes::Scene& scene = run.simulation->editableScene();
        scene.params = primary.scene().params;
        for (const std::string& setting : run.overrides) {
            const scenes::Parameter* parameter = scenes::findParameter(scenes::settingName(setting));
            if (parameter && parameter->applies == scenes::Applies::Live) scenes::applySetting(scene, setting);
        }
        run.simulation->timeScale = primary.timeScale;
        run.simulation->paused = primary.paused;
    }
}

std::string Comparison::primaryLabel(const scenes::Scene& primary) const {
    std::vector<std::string> every;
    for (const Run& run : runs_) every.insert(every.end(), run.overrides.begin(), run.overrides.end());
    return overrideLabel(primary, every);
}

bool Comparison::changesNothing(const scenes::Scene& primary) const {
    for (const Run& run : runs_) {
        if (overrideLabel(primary, run.overrides) != overrideLabel(run.simulation->scene(), run.overrides)) return false;
    }
    return true;
}

void splitViewport(glm::ivec4 view, int gap, glm::ivec4& left, glm::ivec4& right) {
    const int leftWidth = std::max((view.z - gap) / 2, 1);
    const int rightWidth = std::max(view.z - gap - leftWidth, 1);
    left = {view.x, view.y, leftWidth, view.w};
    right = {view.x + view.z - rightWidth, view.y, rightWidth, view.w};
}

void splitViewport(glm::ivec4 view, int gap, int count, glm::ivec4 out[kMostViews]) {
    count = std::clamp(count, 1, kMostViews);
    int bestColumns = 1;
    double bestSide = -1.0;  // px: the smaller side of a view
    for (int columns = 1; columns <= count; ++columns) {
        const int rows = (count + columns - 1) / columns;
        const double side = std::min(double(view.z - (columns - 1) * gap) / columns, double(view.w - (rows - 1) * gap) / rows);
        if (side > bestSide) bestSide = side, bestColumns = columns;
    }
    const int rows = (count + bestColumns - 1) / bestColumns;
    const int width = std::max((view.z - (bestColumns - 1) * gap) / bestColumns, 1);
    const int height = std::max((view.w - (rows - 1) * gap) / rows, 1);
    for (int k = 0; k < count; ++k) {
        const int column = k % bestColumns, row = k / bestColumns;  // row 0 at the top
        out[k] = {view.x + column * (width + gap), view.y + view.w - (row + 1) * height - row * gap, width, height};
    }
    // Two side by side keep the halves splitViewport(left, right) gives (the right one to the edge).
    if (count == 2 && bestColumns == 2) splitViewport(view, gap, out[0], out[1]);
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
    for (std::size_t at = 0; at < view.properties.size();) {  // one line each
        const std::size_t end = std::min(view.properties.find('\n', at), view.properties.size());
        lines.push_back(view.properties.substr(at, end - at));
        at = end + 1;
    }
    return lines;
}

}  // namespace app
