#pragma once
// The solver's worker threads: one process-wide team, started on first use, that
// runs the tasks of a parallel stage. Which thread runs which task never changes a
// result: the stages give threads work on disjoint spheres, or make a task wait
// until the one that met a sphere before it is done, and sum what they count after.
#include <atomic>

namespace physics {

using TaskFunction = void (*)(const void* context, int task);

// Runs function(context, 0) ... function(context, tasks - 1), each exactly once, on
// up to `threads` threads (the caller is one of them); returns when all have finished.
// Calls from several threads take turns (the solver, the renderer's hidden spheres);
// a task must not call it (it would wait for itself) nor throw.
void runTasksOnTeam(int threads, int tasks, TaskFunction function, const void* context);

// task(0) ... task(tasks - 1): in order on the caller with one thread or one task,
// else on the team. (A template, so that no std::function allocates per stage.)
// Tasks may wait for each other (awaitAtLeast) when tasks <= threads: the team has
// threads - 1 workers besides the caller, so a task that no thread has taken yet
// always has an idle thread on its way to take it.
template <class Task>
void runTasks(int threads, int tasks, const Task& task) {
    if (threads <= 1 || tasks <= 1) {
        for (int t = 0; t < tasks; ++t) task(t);
        return;
    }
    runTasksOnTeam(threads, tasks, [](const void* context, int t) { (*static_cast<const Task*>(context))(t); },
                   &task);
}

// Returns the value of `counter` (written by another task of the same runTasks call)
// once it has reached `value`. Waiting spins (the wait is for a few pairs), then
// yields, so that more threads than cores still make progress.
unsigned awaitAtLeast(const std::atomic<unsigned>& counter, unsigned value);

}  // namespace physics
