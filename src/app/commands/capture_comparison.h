#pragma once
// `spheres capture --compare name=value[,value][,name=value]`: the other runs side by
// side. A is the scene as given, B, C, D the same with each view's overrides, all
// advanced by the same frames and drawn with the same camera in the views the
// layout gives (layoutWindow), each labelled with what differs and its readouts.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "app/run/comparison.h"
#include "app/views/view_labels.h"
#include "app/views/window_layout.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/renderer.h"
#include "ui/control_panel.h"

namespace app {

class CaptureComparison {
public:
    // `lists` as given to --compare, for an image of `size` px whose labels are drawn
    // at `uiScale` (titles only when `present`). Throws UsageError for a refused override.
    CaptureComparison(const Simulation& primary, const std::vector<std::string>& lists, glm::ivec2 size,
                      float uiScale, bool present);

    int views() const { return 1 + comparison_.count(); }
    // The room each view's label needs, into the layout's request.
    void sizeLabels(const Simulation& primary, LayoutRequest& request);
    // The views and the labels' places, from the capture's layout.
    void place(const WindowLayout& layout);
    const glm::ivec4& view(int k) const { return layout_.views.views[k]; }  // run k's (0: the primary's)

    // One frame of real time, after the primary's.
    void advance(const Simulation& primary, double seconds);
    // Draws the other runs into their views and every label into the bound framebuffer.
    void draw(render::Renderer& renderer, const render::Camera& camera, const ui::PanelState& view,
              const Simulation& primary);
    const std::vector<glm::vec4>& labelsDrawn() const { return labelsDrawn_; }  // px, top-left origin
    int labelsCut() const { return labels_.cut(); }  // the last draw's labels taller than their room
    int labelWordsBroken() const { return labels_.wordsBroken(); }  // ...and with a word broken inside

    const Comparison& comparison() const { return comparison_; }

private:
    Comparison comparison_;
    WindowLayout layout_;
    render::FrameSnapshot snapshot_;
    HeadlessViewLabels labels_;
    std::vector<glm::vec4> labelsDrawn_;
    bool presented_ = false;
    std::vector<ViewLabel> sized_;  // the labels sizeLabels measured
};

}  // namespace app
