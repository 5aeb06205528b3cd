#include "app/window/short_key_presses.h"

#include <algorithm>

#include <imgui.h>

namespace app {
namespace {

constexpr int kKeys = int(sizeof(ImGuiIO::KeysDown) / sizeof(ImGuiIO::KeysDown[0]));
// GLFW_KEY_LEFT_SHIFT .. GLFW_KEY_RIGHT_SUPER: states, not actions. The backend derives
// io.KeyCtrl from io.KeysDown at every key event, so a Ctrl held on after its release
// (Ctrl+A, then typing) made ImGui drop the characters typed next as shortcuts.
constexpr int kFirstModifier = 340, kLastModifier = 347;

bool contains(const std::vector<int>& keys, int key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

}  // namespace

void ShortKeyPresses::pressed(int key) {
    const bool modifier = key >= kFirstModifier && key <= kLastModifier;
    if (key >= 0 && key < kKeys && !modifier && !contains(pressed_, key)) pressed_.push_back(key);
}

void ShortKeyPresses::beforeNewFrame(ImGuiIO& io) {
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
}

}  // namespace app
