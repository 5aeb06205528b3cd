#pragma once
// The UI font, DejaVu Sans, embedded into the binary at build time.
struct ImFont;

namespace ui {

// Replaces ImGui's fonts with DejaVu Sans at `pixelSize` (px). The renderer must
// rebuild its font texture afterwards (ImGuiGlRenderer::invalidateFontTexture).
ImFont* loadUiFont(float pixelSize);

}  // namespace ui
