#pragma once
// The solver's worker threads: one process-wide team, started on first use, that
// runs the tasks of a parallel stage. Which thread runs which task never changes a
// result: the stages give threads only work that touches disjoint spheres, and
// sum what they count afterwards.

namespace physics {

using TaskFunction = void (*)(const void* context, int task);

// Runs function(context, 0) ... function(context, tasks - 1), each exactly once, on
// up to `threads` threads (the caller is one of them); returns when all have finished.
void runTasksOnTeam(int threads, int tasks, TaskFunction function, const void* context);

// task(0) ... task(tasks - 1): in order on the caller with one thread or one task,
// else on the team. (A template, so that no std::function allocates per stage.)
template <class Task>
void runTasks(int threads, int tasks, const Task& task) {
    if (threads <= 1 || tasks <= 1) {
        for (int t = 0; t < tasks; ++t) task(t);
        return;
    }
    runTasksOnTeam(threads, tasks, [](const void* context, int t) { (*static_cast<const Task*>(context))(t); },
                   &task);
}

}  // namespace physics
