#include "ui/tooltip_timing.h"

#include <algorithm>

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

namespace {

// The largest type, as a share of the panel's (to half at the least), in which `text`
// wrapped `lineWidth` wide stands no taller than `room` (units). Measured in the panel's
// type: in type s a line holds lineWidth / s of it, each s as tall.
float tooltipType(std::string_view text, float lineWidth, float room) {
    constexpr float kSmallest = 0.5f;
    const auto height = [&](float s) {
        return s * ImGui::CalcTextSize(text.data(), text.data() + text.size(), false, lineWidth / s).y;
    };
    float type = 1.0f;
    while (type > kSmallest && height(type) > room) type = std::max(kSmallest, 0.95f * type);
    return type;
}

}  // namespace

float showTooltip(std::string_view text) {
    ImGui::BeginTooltip();
    ImGui::SetWindowFontScale(1.0f);  // measured in the panel's type
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 padding = ImGui::GetStyle().WindowPadding;
    const float wrap = std::min(ImGui::GetFontSize() * 28.0f, 0.45f * display.x);  // from the window's left edge
    const float type = tooltipType(text, wrap - padding.x, 0.85f * display.y - 2.0f * padding.y);
    ImGui::SetWindowFontScale(type);
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::SetWindowFontScale(1.0f);  // the window is ImGui::SetTooltip's too
    ImGui::EndTooltip();
    return type;
}

}  // namespace ui
