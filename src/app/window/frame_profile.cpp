#include "app/window/frame_profile.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>

namespace app {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

void FrameProfile::lap(Part part) {
    const auto now = std::chrono::steady_clock::now();
    current_[part] += std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
}

void FrameProfile::endFrame(bool keep) {
    if (keep) frames_.push_back(current_);
    previous_ = current_;
    current_ = {};
}

double FrameProfile::lastFrameWithout(Part part) const {
    double sum = 0.0;  // ms
    for (int p = 0; p < kParts; ++p) {
        if (p != part) sum += previous_[std::size_t(p)];
    }
    return sum;
}

double FrameProfile::medianOf(Part part) const {
    std::vector<double> values;
    for (const Parts& f : frames_) values.push_back(f[part]);
    return median(values);
}

void FrameProfile::print(int frames, double seconds) const {
    std::vector<double> total;
    for (const Parts& f : frames_) {
        double sum = 0.0;
        for (double ms : f) sum += ms;
        total.push_back(sum);
    }
    const int timed = static_cast<int>(frames_.size());
    std::printf("spheres: %d frames; the last %d in %.2f s: %.1f frames per second (median frame %.1f ms; "
                "events %.1f, stepping %.1f, draw %.1f, UI layout %.1f, UI render %.1f, other %.1f, present %.1f ms)\n",
                frames, timed, seconds, seconds > 0.0 ? timed / seconds : 0.0, median(total), medianOf(Events),
                medianOf(Stepping), medianOf(Draw), medianOf(Layout), medianOf(UiRender), medianOf(Other),
                medianOf(Present));
    std::fflush(stdout);
}

}  // namespace app
