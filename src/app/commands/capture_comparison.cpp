#include "app/commands/capture_comparison.h"

#include "app/views/frame_builder.h"
#include "app/run/scene_source.h"

namespace app {
namespace {

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
                                     glm::ivec2 size, float uiScale, bool present)
    : comparison_(primary.scene(), variantsOf(primary.scene(), lists)), labels_(size, uiScale), presented_(present) {
    for (int k = 0; k < comparison_.count(); ++k) comparison_.simulation(k).setOverlayFlags(primary.overlayFlags());
}

void CaptureComparison::sizeLabels(const Simulation& primary, LayoutRequest& request) {
    sized_ = comparisonLabels(primary, comparison_, presented_ ? LabelLines::Presented : LabelLines::Full);
    request.labelWidth = labels_.width(sized_);
    request.labelHeight = [this](float width) { return labels_.height(sized_, width); };
}

void CaptureComparison::place(const WindowLayout& layout) { layout_ = layout; }

void CaptureComparison::advance(const Simulation& primary, double seconds) {
    comparison_.follow(primary);
    for (int k = 0; k < comparison_.count(); ++k) comparison_.simulation(k).advance(seconds);
}

void CaptureComparison::draw(render::Renderer& renderer, const render::Camera& camera, const ui::PanelState& view,
                             const Simulation& primary) {
    for (int k = 0; k < comparison_.count(); ++k) {
        const glm::ivec4& v = layout_.views.views[k + 1];
        buildSnapshot(comparison_.simulation(k), view, snapshot_);
        renderer.draw(snapshot_, camera, v.x, v.y, v.z, v.w);
    }
    std::vector<ViewLabel> labels = comparisonLabels(primary, comparison_, presented_ ? LabelLines::Presented : LabelLines::Full);
    for (std::size_t k = 0; k < labels.size() && k < std::size_t(kMostViews); ++k) {
        labels[k].topLeft = layout_.labels[k].min;
        labels[k].room = layout_.labels[k].size;
    }
    labelsDrawn_ = labels_.draw(labels);
}

}  // namespace app
