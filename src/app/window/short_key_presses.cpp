#include "app/window/short_key_presses.h"

#include <algorithm>

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace app {
namespace {

// From 1.87 ImGui queues the key events itself (io.AddKeyEvent): this class then does nothing.
#if IMGUI_VERSION_NUM < 18700
constexpr int kKeys = int(sizeof(ImGuiIO::KeysDown) / sizeof(ImGuiIO::KeysDown[0]));
#else
constexpr int kKeys = 0;
#endif
// Shift, Ctrl, Alt, Super: states, not actions. The backend derives io.KeyCtrl from
// io.KeysDown at every key event, so a Ctrl held on after its release (Ctrl+A, then
// typing) made ImGui drop the characters typed next as shortcuts.
constexpr int kFirstModifier = GLFW_KEY_LEFT_SHIFT, kLastModifier = GLFW_KEY_RIGHT_SUPER;

bool contains(const std::vector<int>& keys, int key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

}  // namespace

void ShortKeyPresses::pressed(int key) {
    const bool modifier = key >= kFirstModifier && key <= kLastModifier;
    if (key >= 0 && key < kKeys && !modifier && !contains(pressed_, key)) pressed_.push_back(key);
}

void ShortKeyPresses::beforeNewFrame([[maybe_unused]] ImGuiIO& io) {
#if IMGUI_VERSION_NUM < 18700
    for (const int key : held_) {
        if (!contains(pressed_, key)) io.KeysDown[key] = false;  // pressed again since: the backend's state stands
    }
    held_.clear();
    for (const int key : pressed_) {
        if (io.KeysDown[key]) continue;  // still held: the release will come as an event
        io.KeysDown[key] = true;
        held_.push_back(key);
    }
    pressed_.clear();
#endif
}

}  // namespace app
