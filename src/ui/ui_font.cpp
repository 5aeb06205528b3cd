#include "ui/ui_font.h"

#include <imgui.h>

// The .ttf file (from fonts-dejavu-core) is assembled straight into read-only data.
// SPHERES_FONT_FILE is an absolute path given by CMake.
__asm__(".section .rodata\n"
        ".balign 16\n"
        "spheres_ui_font_begin:\n"
        ".incbin \"" SPHERES_FONT_FILE "\"\n"
        "spheres_ui_font_end:\n"
        ".previous\n");
extern "C" const unsigned char spheres_ui_font_begin[];
extern "C" const unsigned char spheres_ui_font_end[];

namespace ui {

ImFont* loadUiFont(float pixelSize) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    ImFontConfig config;
    config.FontDataOwnedByAtlas = false;  // the bytes live in the binary
    config.OversampleH = 2;
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF,  // Latin-1, Greek (α β ε μ)
                                     0x2010, 0x22FF,                  // punctuation, arrows, maths
                                     0x2713, 0x2717, 0};              // check marks (✓ ✗)
    const int size = static_cast<int>(spheres_ui_font_end - spheres_ui_font_begin);
    void* data = const_cast<unsigned char*>(spheres_ui_font_begin);
    return io.Fonts->AddFontFromMemoryTTF(data, size, pixelSize, &config, ranges);
}

void applyStyle(float uiScale) {
    loadUiFont(kBaseFontPixels * uiScale);
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 0.0f;
    style.FrameRounding = 3.0f;
    // A see-through grab: the value printed under it stays readable (μ = 0.5 sits
    // mid-slider, where the grab covered its digits).
    style.Colors[ImGuiCol_SliderGrab].w = 0.45f;
    style.Colors[ImGuiCol_SliderGrabActive].w = 0.7f;
    // An open list covers the controls under it: ImGui's dark popups are 94 % opaque, and
    // the labels behind showed through its choices ("k propagation" amid "lecture").
    style.Colors[ImGuiCol_PopupBg].w = 1.0f;
    // Secondary text (subtitles, "view A only", hints): ImGui's grey of 0.5 is 4.8:1 against
    // the panel, which a projector's washed-out black brings under 3:1 (a teacher's review
    // at 1080p found it hard to read); 0.65 is 8:1 and still plainly not the white text.
    style.Colors[ImGuiCol_TextDisabled] = ImVec4(0.65f, 0.65f, 0.65f, 1.0f);
    style.ScaleAllSizes(uiScale);
    ImGui::GetStyle() = style;
}

}  // namespace ui
