#include "physics/thread_team.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace physics {
namespace {

// A solver step hands out a dozen stages, each a fraction of a millisecond long:
// waking a sleeping thread would cost as much as the stage. Workers therefore spin
// this long for the next stage before they sleep.
constexpr auto kSpinTime = std::chrono::microseconds(200);

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
            // Under the lock, with the generation: a worker reads them under it too, so
            // it sees the helper count of the generation it wakes for, never the next
            // run's (which would make it drain and count itself done twice).
            std::lock_guard<std::mutex> lock(mutex_);
            function_ = function;
            context_ = context;
            taskCount_ = tasks;
            nextTask_.store(0);
            helpers_ = helpers;
            pending_.store(helpers);
            ++generation_;
        }
        wake_.notify_all();
        drain();
        awaitHelpers();
    }

private:
    void drain() {
        for (int t = nextTask_.fetch_add(1); t < taskCount_; t = nextTask_.fetch_add(1)) function_(context_, t);
    }

    void awaitHelpers() {
        const auto spinUntil = std::chrono::steady_clock::now() + kSpinTime;
        while (pending_.load() > 0 && std::chrono::steady_clock::now() < spinUntil) std::this_thread::yield();
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return pending_.load() == 0; });
    }

    // Waits for a generation after `seen`; false when the team is stopping. `helpers`:
    // how many workers that generation's run asked for.
    bool awaitWork(std::uint64_t& seen, int& helpers) {
        const auto spinUntil = std::chrono::steady_clock::now() + kSpinTime;
        while (generation_.load() == seen && std::chrono::steady_clock::now() < spinUntil) {
            std::this_thread::yield();
        }
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return generation_.load() != seen; });
        seen = generation_.load();
        helpers = helpers_;
        return !stopping_;
    }

    void work(int id, std::uint64_t seen) {
        int helpers = 0;
        while (awaitWork(seen, helpers)) {
            if (id >= helpers) continue;  // this run needs fewer threads
            drain();
            if (pending_.fetch_sub(1) == 1) {
                std::lock_guard<std::mutex> lock(mutex_);
                done_.notify_one();
            }
        }
    }

    std::mutex runMutex_;  // runs from several threads take turns
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::vector<std::thread> workers_;
    std::atomic<std::uint64_t> generation_{0};
    bool stopping_ = false;
    TaskFunction function_ = nullptr;
    const void* context_ = nullptr;
    int taskCount_ = 0;
    int helpers_ = 0;
    std::atomic<int> nextTask_{0};
    std::atomic<int> pending_{0};
};

}  // namespace

void runTasksOnTeam(int threads, int tasks, TaskFunction function, const void* context) {
    static Team team;
    team.run(threads, tasks, function, context);
}

unsigned awaitAtLeast(const std::atomic<unsigned>& counter, unsigned value) {
    for (int spins = 0;; ++spins) {
        const unsigned now = counter.load(std::memory_order_acquire);
        if (now >= value) return now;
        if (spins > 64) std::this_thread::yield();
    }
}

}  // namespace physics
