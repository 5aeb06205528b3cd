#include "ui/tooltip_timing.h"

namespace ui {

bool tooltipDue(ImVec2 corner) {
    // One pointer: the thing it rests on, since when (s, ImGui's clock), the frame it was
    // last over it, and whether a button went down since it came to rest.
    static ImVec2 restingOn{-1.0f, -1.0f};
    static double since = 0.0;
    static int seenIn = -2;
    static bool clicked = false;
    const ImGuiIO& io = ImGui::GetIO();
    const bool moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
    if (corner.x != restingOn.x || corner.y != restingOn.y || seenIn < ImGui::GetFrameCount() - 1 || moved) {
        restingOn = corner;
        since = ImGui::GetTime();
        clicked = false;
    }
    seenIn = ImGui::GetFrameCount();
    clicked = clicked || ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right);
    const double rested = ImGui::GetTime() - since;
    return !clicked && rested >= kTooltipAfter && rested <= kTooltipFor;
}

}  // namespace ui
