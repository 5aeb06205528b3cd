#pragma once
// The labels of the views side by side (what differs, and the readouts of each); and a small ImGui context of its own
// that draws them in `spheres capture`, where no other UI may be drawn.
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "app/run/comparison.h"
#include "app/views/interaction_windows.h"

struct ImGuiContext;

namespace app {

// The titles' colours of views A, B, C, D.
constexpr glm::u8vec4 kViewColors[kMostViews] = {
    {120, 200, 255, 255}, {255, 190, 90, 255}, {150, 235, 140, 255}, {235, 150, 235, 255}};

// Labels "A  method = position", "B  method = velocity", ... with each run's readouts;
// their places are the layout's (ViewLabel::topLeft left at 0); `lines` as comparisonReadouts.
std::vector<ViewLabel> comparisonLabels(const Simulation& primary, const Comparison& comparison,
                                        LabelLines lines = LabelLines::Full);

// Draws labels with an ImGui context of its own (capture mode).
class HeadlessViewLabels {
public:
    HeadlessViewLabels(glm::ivec2 size, float uiScale);  // px; needs a current GL context
    ~HeadlessViewLabels();
    HeadlessViewLabels(const HeadlessViewLabels&) = delete;
    HeadlessViewLabels& operator=(const HeadlessViewLabels&) = delete;

    // The labels' room in the layout (px): labelsWidth, and labelsHeight at a width.
    float width(const std::vector<ViewLabel>& labels);
    float height(const std::vector<ViewLabel>& labels, float width);
    // Into the bound framebuffer. Lays the labels out twice (auto-sized windows
    // measure the previous frame), so that a frame does not depend on the ones before.
    // Returns what it drew (ui::drawnRectangles).
    std::vector<glm::vec4> draw(const std::vector<ViewLabel>& labels);
    int cut() const { return drawn_.cut; }  // how many labels the last draw cut (lines taller than their room)
    int wordsBroken() const { return drawn_.wordsBroken; }  // ...and broke a word of (even in the smallest type)

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    LabelsDrawn drawn_;
};

}  // namespace app
