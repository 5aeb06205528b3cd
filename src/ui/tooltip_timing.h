#pragma once
// When a tooltip shows: once the pointer has rested on its thing for kTooltipAfter, and
// until it has rested there kTooltipFor or clicked it, until it moves again. A pointer left on
// a header after a click, or on a view's label, had kept a tooltip over the views for a whole
// run. The panel's tooltips and the views' labels share it (one pointer, one tooltip).
#include <imgui.h>

namespace ui {

constexpr double kTooltipAfter = 0.5, kTooltipFor = 10.0;  // s

// Call each frame the pointer is over the thing whose top left corner is `corner` (ImGui
// units); whether its tooltip shows this frame.
bool tooltipDue(ImVec2 corner);

}  // namespace ui
