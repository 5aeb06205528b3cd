#include "app/window/short_key_presses.h"

#include <algorithm>

#include <imgui.h>

namespace app {
namespace {

constexpr int kKeys = int(sizeof(ImGuiIO::KeysDown) / sizeof(ImGuiIO::KeysDown[0]));

bool contains(const std::vector<int>& keys, int key) { return std::find(keys.begin(), keys.end(), key) != keys.end(); }

}  // namespace

void ShortKeyPresses::pressed(int key) {
    if (key >= 0 && key < kKeys && !contains(pressed_, key)) pressed_.push_back(key);
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
