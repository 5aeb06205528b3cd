#pragma once
// The solver's worker threads: one process-wide team, started on first use, that
// runs the tasks of a parallel stage. Which thread runs which task never changes a
// result: the stages give threads work on disjoint spheres, or make a task wait
// until the one that met a sphere before it is done, and sum what they count after.
#include <atomic>
#include <condition_variable>
#include <mutex>

namespace physics {

using TaskFunction = void (*)(const void* context, int task);

// Runs function(context, 0) ... function(context, tasks - 1), each exactly once, on
// up to `threads` threads (the caller is one of them); returns when all have finished.
// Calls from several threads take turns (the solver, the renderer's hidden spheres);
// a task must not call it (it would wait for itself) nor throw.
void runTasksOnTeam(int threads, int tasks, TaskFunction function, const void* context);

// task(0) ... task(tasks - 1): in order on the caller with one thread or one task,
// else on the team. (A template, so that no std::function allocates per stage.)
// A task may wait for another (WatchedWord) only if it can do that task's work
// itself when no thread has taken it: the caller's thread may be the only one that
// runs (the workers may not get a core before the tasks are done; then they skip
// the call).
template <class Task>
void runTasks(int threads, int tasks, const Task& task) {
    if (threads <= 1 || tasks <= 1) {
        for (int t = 0; t < tasks; ++t) task(t);
        return;
    }
    runTasksOnTeam(threads, tasks, [](const void* context, int t) { (*static_cast<const Task*>(context))(t); },
                   &task);
}

// A word that the tasks of one runTasks call publish to and watch (how far a
// task has got). A watcher spins for a few microseconds (most waits are for a few
// pairs), then sleeps until the word changes: when other processes share the
// cores, a sleeping watcher leaves its core to the thread it waits for instead of
// competing with it for time slices.
class WatchedWord {
public:
    unsigned load() const { return word_.load(); }
    // Sets the word and wakes its sleeping watchers.
    void store(unsigned value);
    // Sets the word to `desired` if it is `expected` (no watcher needs waking: take
    // only what a store will give back).
    bool compareExchange(unsigned expected, unsigned desired) { return word_.compare_exchange_strong(expected, desired); }
    // The word once it differs from `seen`: spins (if `spin`), then sleeps.
    unsigned awaitChange(unsigned seen, bool spin) const;
    // The word once it differs from `seen`, or after the spin (then it may be `seen`).
    unsigned spinForChange(unsigned seen, bool spin) const;

private:
    std::atomic<unsigned> word_{0};
    mutable std::atomic<int> sleepers_{0};
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
};

// Whether a thread waiting for one of `threads` threads should spin before it sleeps:
// only while they fit the usable cores (more, and the spin takes the core from a
// thread that has work).
bool spinningPays(int threads);

// The cores this process may run on: its CPU affinity mask where the system has
// one (a container or `taskset` may allow fewer than the machine has), else the
// hardware's count; at least 1.
int usableCores();

// A browser build without WebAssembly threads cannot start one: every stage then runs
// on the calling thread (the result is the same on any thread count).
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr bool kCanStartThreads = false;
#else
constexpr bool kCanStartThreads = true;
#endif

}  // namespace physics
