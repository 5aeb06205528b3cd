#include "physics/automatic_threads.h"

#include <algorithm>

namespace physics {
namespace {

template <std::size_t N>
double median(std::array<double, N> seconds) {
    std::nth_element(seconds.begin(), seconds.begin() + N / 2, seconds.end());
    return seconds[N / 2];
}

}  // namespace

void AutomaticThreads::next(int many) {
    if (many != many_) {  // first use, or other cores: start again with `many`
        *this = AutomaticThreads();
        many_ = inUse_ = many;
    }
    if (trying_ == 0 && inUseCount_ >= kSamples && stepsSinceTry_ >= kStepsBetweenTries) {
        trying_ = inUse_ == 1 ? many_ : 1;
        tryingCount_ = 0;
    }
}

void AutomaticThreads::record(int threads, double seconds) {
    if (trying_ != 0 && threads == trying_) {
        tryingSeconds_[std::size_t(tryingCount_++)] = seconds;
        if (tryingCount_ < kSamples) return;
        // The tried count takes over only when it was faster than the last steps of
        // the count in use, measured just before it, on nearly the same state.
        const int faster = median(tryingSeconds_) < median(inUseSeconds_) ? trying_ : inUse_;
        slower_ = faster == trying_ ? inUse_ : trying_;
        if (slower_ == 1) slower_ = 0;  // one thread slower than many: nothing to say
        inUse_ = faster;
        trying_ = 0;
        inUseCount_ = 0;
        stepsSinceTry_ = 0;
        return;
    }
    if (threads != inUse_) return;
    inUseSeconds_[std::size_t(inUseCount_ % kSamples)] = seconds;
    ++inUseCount_;
    ++stepsSinceTry_;
}

}  // namespace physics
