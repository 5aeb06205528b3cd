#pragma once
// Dear ImGui 1.86 (Debian 12's) reads the keys once a frame, from io.KeysDown, which the
// GLFW backend's key callback sets and clears as events come: a key pressed and released
// between two frames never reaches a widget. At a few frames a second (a heavy scene on a
// software GL) a quick Enter after a value typed into a slider, a Backspace or an arrow in
// a field was lost, and the typed value silently not applied. (Characters are queued by
// ImGui, and the mouse backend keeps a click that came and went: those were never lost.)
// A press seen since the last frame is held down through the next frame, then let go;
// not a modifier (Shift, Ctrl, Alt, Super), whose state ImGui reads at every key event.
// From ImGui 1.87 on, which queues key events itself, it does nothing.
#include <vector>

struct ImGuiIO;

namespace app {

class ShortKeyPresses {
public:
    // From the key callback, for every GLFW_PRESS (key: io.KeysDown's index, a GLFW key);
    // modifiers are ignored.
    void pressed(int key);
    // After the events were polled, before ImGui::NewFrame: the keys pressed and already
    // released since the last frame are down for this one; those held so last frame let go.
    void beforeNewFrame(ImGuiIO& io);
    // Whether a press is still to be let go (the next frame must come soon).
    bool holding() const { return !pressed_.empty() || !held_.empty(); }

private:
    std::vector<int> pressed_;  // since the last frame
    std::vector<int> held_;     // by us through the last frame
};

}  // namespace app
