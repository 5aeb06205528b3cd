#pragma once
// The UI's look: the font (DejaVu Sans, embedded into the binary at build time),
// the style, and the colour behind the panel. The window and the capture mode share it.
struct ImFont;

namespace ui {

constexpr float kBaseFontPixels = 17.0f;                  // px, at UI scale 1 on a normal screen
constexpr float kBackdropColor[3] = {0.09f, 0.10f, 0.12f};  // behind the panel

// Loads the font at kBaseFontPixels * uiScale and scales ImGui's style with it. The
// renderer must rebuild its font texture afterwards (ImGuiGlRenderer::invalidateFontTexture).
void applyStyle(float uiScale);

// Replaces ImGui's fonts with DejaVu Sans at `pixelSize` (px). The renderer must
// rebuild its font texture afterwards (ImGuiGlRenderer::invalidateFontTexture).
ImFont* loadUiFont(float pixelSize);

}  // namespace ui
