#include "physics/thread_team.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sched.h>
#endif

namespace physics {
namespace {

// A solver step hands out a dozen stages, each a fraction of a millisecond long:
// waking a sleeping thread would cost as much as the stage. Workers therefore spin
// this long for the next stage before they sleep (when the threads fit the cores:
// else a spin takes the core from a thread that has work).
constexpr auto kSpinTime = std::chrono::microseconds(200);
// A task watching another's progress (WatchedWord) spins this long before it sleeps:
// most such waits are for a few pairs, a microsecond or two.
constexpr auto kWatchSpinTime = std::chrono::microseconds(20);

// Polls done() until it holds (true) or `time` has passed (false), telling the core
// that this is a spin (pause). Never sched_yield: with other processes on the cores,
// the scheduler takes a yield as "run everyone else first", a time slice each
// (milliseconds) instead of a microsecond; a waiter that must wait longer sleeps.
template <class Done>
bool spinUntil(const Done& done, std::chrono::microseconds time) {
    const auto deadline = std::chrono::steady_clock::now() + time;
    for (unsigned polls = 1;; ++polls) {
        if (done()) return true;
        if (polls % 64 == 0 && std::chrono::steady_clock::now() >= deadline) return false;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
    }
}

class Team {
public:
    ~Team() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
            ++generation_;
        }
        wake_.notify_all();
        for (std::thread& worker : workers_) worker.join();
    }

    void run(int threads, int tasks, TaskFunction function, const void* context) {
        std::lock_guard<std::mutex> oneRunAtATime(runMutex_);
        const int helpers = std::min(threads, tasks) - 1;
        while (int(workers_.size()) < helpers) {
            const int id = int(workers_.size());
            const std::uint64_t seen = generation_.load();  // it waits for the next one
            workers_.emplace_back([this, id, seen] { work(id, seen); });
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            function_ = function;
            context_ = context;
            untaken_.store(std::uint64_t(std::uint32_t(tasks)) << 32);
            helpers_ = helpers;
            spin_ = spinningPays(helpers + 1);
            open_ = true;
            ++generation_;
        }
        wake_.notify_all();
        drain(true);
        // Every task is taken. A worker that has not joined yet (the cores are busy with
        // other processes, say) is not waited for: it will skip this run.
        {
            std::lock_guard<std::mutex> lock(mutex_);
            open_ = false;
        }
        awaitJoinedWorkers();
    }

private:
    std::chrono::microseconds spinTime() const { return spin_ ? kSpinTime : std::chrono::microseconds(0); }

    // Runs untaken tasks until none is left: the caller's thread from the first on, the
    // workers from the last back. Each thread then keeps to one end of the tasks, and so,
    // where the tasks are ranges of spheres by number or by place, to the same spheres from
    // one run to the next: their cache lines stay in its core's cache (one fetched from the
    // other core cost 80-110 ns on the machine of the 2026-11-26 runs).
    void drain(bool fromFirst) {
        for (;;) {
            std::uint64_t range = untaken_.load();
            std::uint64_t taken;
            int t;
            do {
                const std::uint32_t first = std::uint32_t(range), end = std::uint32_t(range >> 32);
                if (first >= end) return;
                t = int(fromFirst ? first : end - 1);
                taken = fromFirst ? range + 1 : range - (std::uint64_t(1) << 32);
            } while (!untaken_.compare_exchange_weak(range, taken));
            function_(context_, t);
        }
    }

    void awaitJoinedWorkers() {
        if (spinUntil([this] { return active_.load() == 0; }, spinTime())) return;
        std::unique_lock<std::mutex> lock(mutex_);
        finished_.wait(lock, [this] { return active_.load() == 0; });
    }

    // Waits for a run after generation `seen` that this worker may join, and joins it
    // (under the lock that closes it); false when the team is stopping.
    bool join(int id, std::uint64_t& seen) {
        for (;;) {
            spinUntil([&] { return generation_.load() != seen; }, spinTime());
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return generation_.load() != seen; });
            seen = generation_.load();
            if (stopping_) return false;
            if (open_ && id < helpers_) {  // not over yet, and it asked for this many threads
                ++active_;
                return true;
            }
        }
    }

    void work(int id, std::uint64_t seen) {
        while (join(id, seen)) {
            drain(false);
            if (active_.fetch_sub(1) == 1) {
                std::lock_guard<std::mutex> lock(mutex_);
                finished_.notify_one();
            }
        }
    }

    std::mutex runMutex_;  // runs from several threads take turns
    std::mutex mutex_;
    std::condition_variable wake_, finished_;
    std::vector<std::thread> workers_;
    std::atomic<std::uint64_t> generation_{0};
    bool stopping_ = false;
    TaskFunction function_ = nullptr;
    const void* context_ = nullptr;
    int helpers_ = 0;
    std::atomic<std::uint64_t> untaken_{0};  // the tasks not taken yet: [low 32 bits, high 32 bits)
    std::atomic<bool> spin_{true};  // the last run's threads fit the cores: waits spin first
    bool open_ = false;           // workers may join the run (under mutex_)
    std::atomic<int> active_{0};  // workers that joined the run and have not finished
};

}  // namespace

void runTasksOnTeam(int threads, int tasks, TaskFunction function, const void* context) {
    static Team team;
    team.run(threads, tasks, function, context);
}

void WatchedWord::store(unsigned value) {
    word_.store(value);  // seq_cst, as the sleepers' count below and in awaitChange:
    if (sleepers_.load() > 0) {  // either this sees a sleeper, or the sleeper sees the word
        std::lock_guard<std::mutex> lock(mutex_);
        changed_.notify_all();
    }
}

unsigned WatchedWord::spinForChange(unsigned seen, bool spin) const {
    unsigned now = seen;
    spinUntil([&] { return (now = word_.load()) != seen; }, spin ? kWatchSpinTime : std::chrono::microseconds(0));
    return now;
}

unsigned WatchedWord::awaitChange(unsigned seen, bool spin) const {
    const unsigned now = spinForChange(seen, spin);
    if (now != seen) return now;
    std::unique_lock<std::mutex> lock(mutex_);
    sleepers_.fetch_add(1);
    unsigned changed = seen;
    changed_.wait(lock, [&] { return (changed = word_.load()) != seen; });
    sleepers_.fetch_sub(1);
    return changed;
}

bool spinningPays(int threads) {
    static const int cores = usableCores();
    return threads <= cores;
}

int usableCores() {
    if (!kCanStartThreads) return 1;
#ifdef __linux__
    cpu_set_t allowed;
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0) return std::max(1, CPU_COUNT(&allowed));
#endif
    return std::max(1, int(std::thread::hardware_concurrency()));
}

}  // namespace physics
