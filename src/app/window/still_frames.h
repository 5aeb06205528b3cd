#pragma once
// A paused window that draws the same picture frame after frame waits for input instead,
// for at most kWaitSeconds (a message still goes on time, a blinking cursor still blinks).
// Paused, the demo had drawn the same frame as fast as the GL let it: 1.64 cores under
// Xvfb (llvmpipe draws on both cores): a laptop's battery and fan in class. Now 0.10.
#include <cstdint>

struct ImDrawData;
namespace render {
class Camera;
}

namespace app {

class StillFrames {
  public:
    static constexpr double kWaitSeconds = 0.25;  // s: the longest wait for input
    static constexpr int kAlikeBeforeWaiting = 3;  // frames drawn alike (ImGui settles a hover in one or two)

    // After each frame: `quiet` when nothing but input can change the next one (paused, no
    // step taken, no key or button held, no scripted run); what it drew: the UI, the camera
    // and `scene` (whatever else the views show: the step, the selected sphere).
    void after(bool quiet, const ImDrawData& ui, const render::Camera& camera, std::uint64_t scene);
    // Whether the next frame should wait for input first.
    bool waits() const { return alike_ >= kAlikeBeforeWaiting; }
    // Input ended a wait: the frames it changes are drawn, and kAlikeBeforeWaiting more.
    void woken() { alike_ = 0; }

  private:
    std::uint64_t last_ = 0;  // the last quiet frame's look (a hash)
    int alike_ = 0;           // quiet frames in a row that looked the same
};

}  // namespace app
