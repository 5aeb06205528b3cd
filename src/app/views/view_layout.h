#pragma once
// Where the views lie in the window: the scene right of the panel and above the
// timeline bar, as one view or two side by side, and which view and which camera
// ray a mouse position falls on. Pure arithmetic over sizes, so it is tested alone.
#include <glm/vec2.hpp>

#include "app/run/comparison.h"
#include <glm/vec4.hpp>

#include "render/camera.h"

namespace app {

struct ViewLayout {
    glm::ivec2 framebuffer{1};      // px
    glm::vec2 pixelsPerUnit{1.0f};  // framebuffer px per window unit (mouse, ImGui): 2 on HiDPI
    int count = 1;                  // views: 1, or 2 to kMostViews side by side
    glm::ivec4 views[kMostViews]{};  // x, y, width, height in px, GL's lower-left origin

    // The view under a window point (top-left origin, window units), or -1.
    int viewAt(glm::vec2 mouse) const;
    // The point in view k's own pixels (top-left origin), as render::Camera takes them;
    // it may lie outside the view.
    glm::vec2 pixelIn(int view, glm::vec2 mouse) const;
    render::Ray ray(const render::Camera& camera, int view, glm::vec2 mouse) const;
    float aspect() const;  // width / height of a view
};

// The views of a `framebuffer` whose left `panelUnits` hold the panel and whose
// bottom `barUnits` hold the timeline bar (window units); several views are split
// with a gap of `gap` px (splitViewport).
ViewLayout layoutViews(glm::ivec2 framebuffer, glm::vec2 pixelsPerUnit, float panelUnits, float barUnits, int count,
                       int gap);

}  // namespace app
