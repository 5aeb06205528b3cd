#pragma once
// Params::threads = 0 (auto) on a world large enough for threads: the solver runs
// with the cores' count of threads, and now and then a few solver steps with one
// thread, and keeps whichever took less wall time. When other processes share the
// cores (a laptop running a browser and a video call), two threads can be slower
// than one: then the solver goes back to one, and the readouts say so. The count
// never changes a result (every count gives the same state, bit for bit), only the
// time a step takes.
#include <array>

namespace physics {

class AutomaticThreads {
public:
    // Chooses the threads for the next solver step, when `many` (> 1) is the cores'
    // count; current() says them until the next call.
    void next(int many);
    // The threads chosen; 0 before the first next().
    int current() const { return trying_ != 0 ? trying_ : inUse_; }
    // The last solver step used `threads` and took `seconds` of wall time.
    void record(int threads, double seconds);
    // Threads found slower than the count in use at the last comparison, 0 none.
    int slowerCount() const { return slower_; }

    // A comparison takes this many solver steps of each count: their medians (a
    // rebuild of the candidate pairs costs several steps' time).
    static constexpr int kSamples = 5;
    // The count not in use is tried again after this many steps of the one in use,
    // so that a change of load is seen within a second or two; the first time after
    // kFirstTry steps.
    static constexpr int kStepsBetweenTries = 100;
    static constexpr int kFirstTry = 10;

private:
    int many_ = 0;    // the cores' count; 0: not started
    int inUse_ = 0;   // many_ or 1
    int trying_ = 0;  // the other count while it is tried, else 0
    int slower_ = 0;
    int stepsSinceTry_ = kStepsBetweenTries - kFirstTry;
    int inUseCount_ = 0, tryingCount_ = 0;  // samples kept in the rings below
    std::array<double, kSamples> inUseSeconds_{}, tryingSeconds_{};
};

}  // namespace physics
