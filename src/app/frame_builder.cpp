#include "app/frame_builder.h"

#include <algorithm>

#include <glm/common.hpp>

#include "scenes/scene.h"

namespace app {

void buildSnapshot(const Simulation& simulation, const ui::PanelState& view, render::FrameSnapshot& snapshot) {
    snapshot.clear();
    render::snapshotSpheres(simulation.world(), static_cast<render::ColorBy>(view.colorBy), snapshot);
    render::snapshotPlanes(simulation.world(), snapshot);
}

ui::Readouts makeReadouts(const Simulation& simulation, double fps, double renderMs) {
    ui::Readouts r;
    r.fps = fps;
    r.renderMs = renderMs;
    r.stepMs = simulation.lastStepMilliseconds();
    r.paused = simulation.paused;
    r.behindRealTime = simulation.behindRealTime();
    r.time = simulation.world().time;
    r.steps = simulation.world().stepCount;
    r.sphereCount = simulation.world().size();
    r.stats = simulation.lastStepStats();
    r.diagnostics = simulation.diagnostics();
    const History& history = simulation.history();
    for (Series s : {Series::Kinetic, Series::Potential, Series::Modified, Series::Contacts}) {
        r.plots.emplace_back(History::name(s), &history.values(s));
    }
    return r;
}

void sceneBounds(const Simulation& simulation, glm::vec3& lo, glm::vec3& hi) {
    const scenes::Scene& scene = simulation.scene();
    if (scene.box) {
        const glm::dvec3 size = scene.box->size;
        lo = glm::vec3(-size.x / 2, -size.y / 2, 0.0);
        hi = glm::vec3(size.x / 2, size.y / 2, size.z);
        return;
    }
    lo = glm::vec3(-1.0f);
    hi = glm::vec3(1.0f);
    const physics::World& world = simulation.world();
    for (std::size_t i = 0; i < world.size(); ++i) {
        lo = glm::min(lo, glm::vec3(world.position[i]) - float(world.radius[i]));
        hi = glm::max(hi, glm::vec3(world.position[i]) + float(world.radius[i]));
    }
}

glm::ivec4 viewportRightOf(glm::ivec2 size, float panelPixels) {
    const int x = std::clamp(static_cast<int>(panelPixels + 0.5f), 0, std::max(size.x - 1, 0));
    return {x, 0, std::max(size.x - x, 1), std::max(size.y, 1)};
}

}  // namespace app
