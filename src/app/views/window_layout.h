#pragma once
// Where everything lies in the window, so that nothing covers the spheres: the panel
// on the left, the timeline bar along the bottom, the folded readouts as one line
// along the top, and a dock (a column on the right, or a strip above the bar,
// whichever leaves the views the larger box) for the readouts' numbers and plots,
// the inspector and "explain this contact". The views take what is left: one, or a
// grid of up to kMostViews side by side, each with its label beside or above it.
// Pure arithmetic over sizes, so it is tested alone; the window and `spheres capture`
// lay out their frames with it.
#include <functional>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "app/run/comparison.h"
#include "render/camera.h"

namespace app {

// A rectangle in window units (ImGui's, top-left origin).
struct Rect {
    glm::vec2 min{0.0f};
    glm::vec2 size{0.0f};
    glm::vec2 max() const { return min + size; }
    bool empty() const { return size.x <= 0.0f || size.y <= 0.0f; }
};

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
    Rect rect(int view) const;  // view k in window units
};

// What there is to lay out. Sizes in window units; 0 means "not shown".
struct LayoutRequest {
    glm::vec2 window{1.0f};
    glm::vec2 pixelsPerUnit{1.0f};
    float font = 17.0f;          // ImGui's font size: the dock's widths are counted in it
    float panelWidth = 0.0f;     // the control panel, full height on the left
    float barHeight = 0.0f;      // the timeline bar
    float readoutsLine = 0.0f;   // the readouts folded to their title line
    bool readouts = false;       // the readouts unfolded: numbers and plots, in the dock
    float inspectorHeight = 0.0f;  // the selected sphere's inspector, as tall as last drawn
    bool explainer = false;      // "explain this contact"
    int views = 1;
    // Side by side: each view's label, as wide as its longest line, and its height
    // when laid `width` wide (its lines wrap); the tallest of the views'. Empty: none.
    float labelWidth = 0.0f;
    std::function<float(float width)> labelHeight;
    float boxAspect = 1.0f;      // the box's width / height on screen: the views fit it
    int gap = 4;                 // px between views
};

struct WindowLayout {
    Rect panel, readoutsLine, timeline;
    Rect dock;  // holds the three below; empty when none is shown
    bool dockAtBottom = false;
    Rect inspector, explainer, readouts;
    Rect scene;  // the views and their labels
    Rect labels[kMostViews];  // side by side: each view's label
    ViewLayout views;
};

// The dock's windows' widths, in font sizes.
constexpr float kInspectorFonts = 20.0f, kExplainerFonts = 32.0f, kReadoutsFonts = 18.0f;

WindowLayout layoutWindow(const LayoutRequest& request);

// `count` views in `area` (px, GL's lower-left origin), with `gap` px between them,
// each with its label (`labelWidth` px wide unwrapped, `labelHeight(width)` px high
// when `width` px wide; 0 or empty: no labels) above it or left of it: the grid and
// the label places that give each view the largest box of aspect `boxAspect` (width /
// height). Returns that box's height, px. `labels` in px, GL's origin.
using LabelHeight = std::function<int(int width)>;
float arrangeViews(glm::ivec4 area, int count, int gap, int labelWidth, const LabelHeight& labelHeight,
                   float boxAspect, glm::ivec4 views[kMostViews], glm::ivec4 labels[kMostViews]);

// The box's width / height on screen for the camera's angles (1: a cube seen level).
float boxAspectOnScreen(const render::Camera& camera, glm::vec3 lo, glm::vec3 hi);

}  // namespace app
