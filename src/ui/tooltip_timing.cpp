#include "ui/tooltip_timing.h"

#include <algorithm>
#include <cmath>

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

float tooltipTypeFor(float height, float room) {
    return height <= room ? 1.0f : std::max(0.5f, std::sqrt(room / height));
}

void showTooltip(std::string_view text) {
    ImGui::BeginTooltip();
    ImGui::SetWindowFontScale(1.0f);  // measured in the panel's type (the window keeps its scale)
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float wrap = std::min(ImGui::GetFontSize() * 28.0f, 0.45f * display.x);  // units
    const float height = ImGui::CalcTextSize(text.data(), text.data() + text.size(), false, wrap).y;
    // Smaller type by s makes each line hold 1/s more and stand s as high: the height by s².
    ImGui::SetWindowFontScale(tooltipTypeFor(height, 0.85f * display.y));
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

}  // namespace ui
