#pragma once
// What changed in a Dear ImGui draw list from one frame to the next: the renderer keeps
// the control panel drawn in a texture and draws it again only where it changed (on a
// software GL, filling the panel costs 2 ms a frame, and most frames change a line).
#include <imgui.h>

#include <optional>
#include <vector>

namespace ui {

// One triangle as drawn: its corners, its command's clip rectangle and texture.
struct DrawnTriangle {
    ImDrawVert corner[3];
    ImVec4 clip;  // ImGui units: x0, y0, x1, y1
    ImTextureID texture;
};

// A draw list's triangles in drawing order.
struct DrawListCopy {
    std::vector<DrawnTriangle> triangles;

    void assign(const ImDrawList& list);
    void clear() { triangles.clear(); }
    bool empty() const { return triangles.empty(); }
};

// Where `now` draws differently from `before`, in ImGui units (x0, y0, x1, y1): the
// triangles between the two lists' common start and common end, those of both, each cut
// by its clip rectangle. Outside it a pixel is covered by the same triangles in the same
// order in both. An empty box (x1 <= x0) when nothing changed; nullopt when `before` is
// empty (nothing to compare with: all of it).
std::optional<ImVec4> changedArea(const DrawListCopy& before, const DrawListCopy& now);

}  // namespace ui
