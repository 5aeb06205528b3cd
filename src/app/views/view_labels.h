#pragma once
// The labels of the two views side by side (what differs, and the readouts of
// each), placed at the top left of each view; and a small ImGui context of its own
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

// Labels "A  method = position", "B  method = velocity", ... with each run's readouts,
// at the top left of `views` (GL viewports in framebuffer pixels, lower-left origin)
// moved by `offset` (ImGui units), or at their bottom left moved by `offset` when
// `atBottom`, for a framebuffer of `framebufferSize` pixels that holds
// `pixelsPerUnit` pixels per ImGui unit.
std::vector<ViewLabel> comparisonLabels(const Simulation& primary, const Comparison& comparison,
                                        const glm::ivec4 views[kMostViews], glm::ivec2 framebufferSize,
                                        glm::vec2 pixelsPerUnit, glm::vec2 offset, bool atBottom = false);

// Draws labels with an ImGui context of its own, at UI scale 1 (capture mode).
class HeadlessViewLabels {
public:
    explicit HeadlessViewLabels(glm::ivec2 size);  // px; needs a current GL context
    ~HeadlessViewLabels();
    HeadlessViewLabels(const HeadlessViewLabels&) = delete;
    HeadlessViewLabels& operator=(const HeadlessViewLabels&) = delete;

    // Into the bound framebuffer. Lays the labels out twice (auto-sized windows
    // measure the previous frame), so that a frame does not depend on the ones before.
    void draw(const std::vector<ViewLabel>& labels);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace app
