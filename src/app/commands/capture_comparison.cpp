#include "app/commands/capture_comparison.h"

#include "app/views/frame_builder.h"
#include "app/run/scene_source.h"

namespace app {
namespace {

constexpr int kViewGap = 4;           // px between the two views
constexpr float kLabelMargin = 8.0f;  // px from a view's corner

}  // namespace

CaptureComparison::CaptureComparison(const Simulation& primary, const std::vector<std::string>& lists,
                                     const glm::ivec4& view, glm::ivec2 size, bool labelsAtBottom)
    : comparison_(primary.scene(), splitOverrides(lists)), size_(size), labelsAtBottom_(labelsAtBottom), labels_(size) {
    splitViewport(view, kViewGap, views_[0], views_[1]);
    comparison_.simulation().setOverlayFlags(primary.overlayFlags());
}

void CaptureComparison::advance(const Simulation& primary, double seconds) {
    comparison_.follow(primary);
    comparison_.simulation().advance(seconds);
}

void CaptureComparison::draw(render::Renderer& renderer, const render::Camera& camera, const ui::PanelState& view,
                             const Simulation& primary) {
    buildSnapshot(comparison_.simulation(), view, snapshot_);
    renderer.draw(snapshot_, camera, views_[1].x, views_[1].y, views_[1].z, views_[1].w);
    const glm::vec2 offset(kLabelMargin, labelsAtBottom_ ? -kLabelMargin : kLabelMargin);
    labels_.draw(comparisonLabels(primary, comparison_, views_, size_, glm::vec2(1.0f), offset, labelsAtBottom_));
}

}  // namespace app
