#include "app/commands/capture_comparison.h"

#include "app/views/frame_builder.h"
#include "app/run/scene_source.h"

namespace app {
namespace {

constexpr int kViewGap = 4;           // px between the views
constexpr float kLabelMargin = 8.0f;  // px from a view's corner

// The views --compare asks for; throws UsageError naming a refused override.
Variants variantsOf(const scenes::Scene& scene, const std::vector<std::string>& lists) {
    Variants variants;
    if (const std::string error = overrideVariants(scene, lists, variants); !error.empty()) {
        throw UsageError("--compare " + error);
    }
    return variants;
}

}  // namespace

CaptureComparison::CaptureComparison(const Simulation& primary, const std::vector<std::string>& lists,
                                     const glm::ivec4& view, glm::ivec2 size, bool labelsAtBottom)
    : comparison_(primary.scene(), variantsOf(primary.scene(), lists)),
      size_(size),
      labelsAtBottom_(labelsAtBottom),
      labels_(size) {
    splitViewport(view, kViewGap, 1 + comparison_.count(), views_);
    for (int k = 0; k < comparison_.count(); ++k) comparison_.simulation(k).setOverlayFlags(primary.overlayFlags());
}

void CaptureComparison::advance(const Simulation& primary, double seconds) {
    comparison_.follow(primary);
    for (int k = 0; k < comparison_.count(); ++k) comparison_.simulation(k).advance(seconds);
}

void CaptureComparison::draw(render::Renderer& renderer, const render::Camera& camera, const ui::PanelState& view,
                             const Simulation& primary) {
    for (int k = 0; k < comparison_.count(); ++k) {
        const glm::ivec4& v = views_[k + 1];
        buildSnapshot(comparison_.simulation(k), view, snapshot_);
        renderer.draw(snapshot_, camera, v.x, v.y, v.z, v.w);
    }
    const glm::vec2 offset(kLabelMargin, labelsAtBottom_ ? -kLabelMargin : kLabelMargin);
    labels_.draw(comparisonLabels(primary, comparison_, views_, size_, glm::vec2(1.0f), offset, labelsAtBottom_));
}

}  // namespace app
