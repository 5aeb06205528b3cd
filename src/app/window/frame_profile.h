#pragma once
// `spheres --frames N`: where each frame's wall time went (events, stepping, drawing,
// the UI's layout and drawing, presenting), printed as one line at the end with the
// frame rate. The first frame (start-up: shaders, the font atlas) is left out.
#include <array>
#include <chrono>
#include <vector>

namespace app {

class FrameProfile {
public:
    enum Part { Events, Stepping, Draw, Layout, UiRender, Other, Present, kParts };

    void begin() { last_ = std::chrono::steady_clock::now(); }
    // The time since the last lap() or begin() goes to `part`.
    void lap(Part part);
    // The frame's parts are kept when `keep`, and the next frame starts.
    void endFrame(bool keep);
    // ms: what the last frame spent on everything but `part`.
    double lastFrameWithout(Part part) const;
    // "spheres: 300 frames; the last 299 in 3.60 s: 83.0 frames per second (median ...)".
    void print(int frames, double seconds) const;

private:
    using Parts = std::array<double, kParts>;  // ms
    double medianOf(Part part) const;

    std::chrono::steady_clock::time_point last_;
    Parts current_{};
    Parts previous_{};  // the last frame's
    std::vector<Parts> frames_;
};

}  // namespace app
