#pragma once
// `spheres capture --compare name=value[,value][,name=value]`: the other runs side by
// side. The capture's viewport is split (splitViewport): A the scene as given, B, C, D
// the same with each view's overrides, all advanced by the same frames and drawn with
// the same camera, each labelled with what differs and its readouts.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "app/run/comparison.h"
#include "app/views/view_labels.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/renderer.h"
#include "ui/control_panel.h"

namespace app {

class CaptureComparison {
public:
    // `lists` as given to --compare; `view` the capture's scene viewport (px, GL's
    // origin) in an image of `size` px. Throws UsageError for a refused override.
    CaptureComparison(const Simulation& primary, const std::vector<std::string>& lists, const glm::ivec4& view,
                      glm::ivec2 size, bool labelsAtBottom);

    const glm::ivec4& left() const { return views_[0]; }   // the primary's viewport
    const glm::ivec4& view(int k) const { return views_[k]; }  // run k's (0: the primary's)

    // One frame of real time, after the primary's.
    void advance(const Simulation& primary, double seconds);
    // Draws the other runs into their views and every label into the bound framebuffer.
    void draw(render::Renderer& renderer, const render::Camera& camera, const ui::PanelState& view,
              const Simulation& primary);

    const Comparison& comparison() const { return comparison_; }

private:
    Comparison comparison_;
    glm::ivec4 views_[kMostViews];
    glm::ivec2 size_;
    bool labelsAtBottom_;
    render::FrameSnapshot snapshot_;
    HeadlessViewLabels labels_;
};

}  // namespace app
