// The solver's speed on the pile preset (the shipped preset with "pile" in its name)
// from N = 1k to 1M, on one thread and on more, and the log-log slope of time
// against N. The radius shrinks as N^(-1/3) so that the pile keeps its volume.
//
// For each N the pile falls and lands first (--warm-up simulated seconds, on the
// most threads asked for); then every thread count runs the same number of steps
// from that same state, interleaved (1, 2, 1, 2, ...), and a row gives the median.
// "broad phase" and "passes" are StepStats' profile (per solver step, median): what
// is left of a step is the integration and the rest.
// The "hash" column is the state hash after the timed steps of the first
// repetition: equal for every thread count, or the row says DIFFERENT (and the
// program exits with 1), since threads must never change the result.
//
// With --busy B it compares instead one thread, two and automatic threads on the pile
// at 16k and 64k spheres, alone and beside B busy processes that it starts and stops
// itself: what a student's laptop running a browser and a video call does to threads.
//   usage: spheres_bench_solver --help
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#ifdef __linux__
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include "bench/bench_common.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "physics/thread_team.h"

namespace {

struct Options {
    std::vector<int> counts{1000, 4000, 16000, 64000, 100000, 256000, 1000000};
    std::vector<int> threads{1, 2};
    int passes = 4;
    std::vector<std::string> orders{"index", "colored"};  // pair orders, timed side by side
    std::string solver = "sequential";  // slide 14's solvers; the warm-up is always sequential
    std::string shock = "off";          // slide 14's shock propagation, warm-up included
    double warmUp = 1.5;  // s simulated before timing: the pile has landed
    double block = 0.5;   // s of wall time per timed repetition (at least one step)
    int repetitions = 3;
    bool mixNumbers = false;  // shuffle the spheres' numbers after the warm-up
    bool chains = false;      // print how much of a pass could run side by side
    int busy = 0;             // --busy: busy processes beside the loaded runs
    bool countsGiven = false, threadsGiven = false;  // --n, --threads (--busy has its own defaults)
};

// The most seconds a busy process of --busy lives, whatever happens to this one.
constexpr unsigned kBusyLifetime = 900;

const bench::Usage kUsage{"spheres_bench_solver",
    "usage: spheres_bench_solver [options]\n"
    "Times our solver on the pile, N = 1k to 1M, on 1 and 2 threads; prints a markdown table.\n"
    "  --quick        N = 1k,4k,16k,64k,100k, 2 repetitions\n"
    "  --n LIST       sphere counts (default 1k,4k,16k,64k,100k,256k,1M)\n"
    "  --threads LIST thread counts (default 1,2)\n"
    "  --k K          passes (default 4)\n"
    "  --order LIST   pair orders: index, reversed, shuffled, colored (default index,colored;\n"
    "                 colored is not the lecture's); the warm-up runs in the first\n"
    "  --solver NAME  multiple collisions: sequential, until-converged, simultaneous, lcp or\n"
    "                 generalized-reflections (default sequential; the warm-up is sequential)\n"
    "  --shock on|off slide 14's shock propagation, in the warm-up too (default off)\n"
    "  --warm-up S    simulated seconds before timing (default 1.5)\n"
    "  --reps R       timed repetitions (default 3)\n"
    "  --mix-numbers  after the warm-up, shuffle the spheres' numbers (the same places and\n"
    "                 speeds): memory visited out of order, as in a gas that has run long\n"
    "  --chains       also print, per N, how much of a pass could run side by side with\n"
    "                 the same result (chains of pairs that share a sphere)\n"
    "  --busy B       instead: threads 1, 2 and auto on N = 16k,64k, alone and beside B busy\n"
    "                 processes (started and stopped here), 2 s per run; prints the ratios\n"
    "                 (--n, --threads with 'auto' for automatic, --reps apply)\n"};

[[noreturn]] void usageError(const std::string& why) { bench::usageError(kUsage, why); }

std::vector<int> countsFrom(const std::string& option, const char* text) {
    std::vector<int> counts;
    if (!bench::parseCounts(text, counts)) usageError(option + " " + text + ": expected numbers such as 1k,64k,1M");
    return counts;
}

// Thread counts such as "1,2,auto" (auto: 0).
std::vector<int> threadsFrom(const std::string& option, const std::string& text) {
    std::vector<int> threads;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string part = text.substr(start, comma - start);
        threads.push_back(part == "auto" ? 0 : countsFrom(option, part.c_str()).front());
        start = comma + 1;
    }
    return threads;
}

// "index,colored" -> {"index", "colored"}.
std::vector<std::string> namesFrom(const std::string& list) {
    std::vector<std::string> names;
    std::size_t start = 0;
    for (std::size_t comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1) {
        names.push_back(list.substr(start, comma - start));
    }
    names.push_back(list.substr(start));
    return names;
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string option = argv[k];
        bench::helpIfAsked(kUsage, option);
        if (option == "--quick") {
            o.counts = {1000, 4000, 16000, 64000, 100000};
            o.repetitions = 2;
            continue;
        }
        if (option == "--mix-numbers") {
            o.mixNumbers = true;
            continue;
        }
        if (option == "--chains") {
            o.chains = true;
            continue;
        }
        if (k + 1 >= argc) usageError(option + ": expected a value after it");
        const char* value = argv[++k];
        if (option == "--n") {
            o.counts = countsFrom(option, value);
            o.countsGiven = true;
        } else if (option == "--threads") {
            o.threads = threadsFrom(option, value);
            o.threadsGiven = true;
        }
        else if (option == "--busy") {
            o.busy = countsFrom(option, value).front();
            if (o.busy > 64) usageError(option + " " + value + ": at most 64 busy processes");
        }
        else if (option == "--k") o.passes = countsFrom(option, value).front();
        else if (option == "--order") o.orders = namesFrom(value);
        else if (option == "--solver") o.solver = value;
        else if (option == "--shock") o.shock = value;
        else if (option == "--warm-up") {
            if (!bench::parseSimulatedSeconds(value, o.warmUp))
                usageError(option + " " + value + ": expected simulated seconds from 0 to 600");
        }
        else if (option == "--reps") o.repetitions = countsFrom(option, value).front();
        else usageError("unknown option " + option);
    }
    return o;
}

// The timed scene in order number `order` of --order; with `warmUp` the lecture's
// sequential solver whatever --solver says.
scenes::Scene pileOf(int count, const Options& options, int threads, bool warmUp = false, std::size_t order = 0) {
    scenes::Scene scene = bench::pileOf(count);
    bench::set(scene, "passes=" + std::to_string(options.passes));
    bench::set(scene, "order=" + options.orders[order]);
    bench::set(scene, "threads=" + std::to_string(threads));
    bench::set(scene, "solver=" + (warmUp ? std::string("sequential") : options.solver));
    bench::set(scene, "shock=" + options.shock);
    return scene;
}

// The same spheres under shuffled numbers: sphere k takes the place, speed, radius and
// mass of sphere order[k]. Neighbours in space are then far apart in memory.
physics::World withNumbersShuffled(const physics::World& world) {
    std::vector<std::size_t> order(world.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::shuffle(order.begin(), order.end(), std::mt19937_64(world.seed));
    physics::World mixed = world;
    for (std::size_t k = 0; k < world.size(); ++k) {
        mixed.position[k] = world.position[order[k]];
        mixed.velocity[k] = world.velocity[order[k]];
        mixed.radius[k] = world.radius[order[k]];
        mixed.mass[k] = world.mass[order[k]];
        mixed.contactState[k] = world.contactState[order[k]];
    }
    mixed.workspace = physics::Workspace{};  // its pairs and caches name the old numbers
    return mixed;
}

// How many levels the pairs [first, end) take: a pair must come after every earlier
// pair of the range that shares a sphere with it, so its level is one more than theirs.
// Pairs of one level share no sphere. `level` is scratch, one per sphere.
std::uint32_t levelsOf(const std::vector<physics::SpherePair>& pairs, std::size_t first, std::size_t end,
                       std::vector<std::uint32_t>& level) {
    for (std::size_t k = first; k < end; ++k) level[pairs[k].i] = level[pairs[k].j] = 0;
    std::uint32_t top = 0;
    for (std::size_t k = first; k < end; ++k) {
        const std::uint32_t l = 1 + std::max(level[pairs[k].i], level[pairs[k].j]);
        level[pairs[k].i] = level[pairs[k].j] = l;
        top = std::max(top, l);
    }
    return top;
}

// How much of a pass could run side by side without changing its result: pairs per
// level over the whole pass, and inside windows of consecutive pairs (whose spheres
// stay in the caches).
std::string chainsRow(const physics::World& world, int count) {
    const std::vector<physics::SpherePair>& pairs = world.workspace.visitOrder;
    std::vector<std::uint32_t> level(world.size(), 0);
    const std::uint32_t longest = levelsOf(pairs, 0, pairs.size(), level);
    char cell[96];
    std::snprintf(cell, sizeof cell, "| %s | %zu | %u | %.0f |", bench::grouped(count).c_str(), pairs.size(),
                  longest, double(pairs.size()) / std::max(1u, longest));
    std::string row = cell;
    for (std::size_t size : {64, 256, 1024}) {
        std::size_t levels = 0;
        for (std::size_t first = 0; first < pairs.size(); first += size) {
            levels += levelsOf(pairs, first, std::min(pairs.size(), first + size), level);
        }
        std::snprintf(cell, sizeof cell, " %.1f |", double(pairs.size()) / double(std::max<std::size_t>(1, levels)));
        row += cell;
    }
    return row;
}

struct Run {
    std::vector<double> seconds;  // per repetition
    std::vector<double> broadPhase, passes;  // s per repetition: StepStats' profile
    std::uint64_t builds = 0;
    std::uint64_t hash = 0;       // after the first repetition
};

struct Row {
    int count = 0;
    double solverSteps = 0.0;
    std::map<std::pair<std::size_t, int>, Run> byRun;  // by order (its number in --order), threads
    std::string chains;  // --chains: a row of that table
};

Row measure(int count, const Options& options) {
    const int mostThreads = *std::max_element(options.threads.begin(), options.threads.end());
    const scenes::Scene warmUp = pileOf(count, options, mostThreads, true);
    const scenes::Scene scene = pileOf(count, options, mostThreads);
    physics::World start = scenes::buildWorld(warmUp);
    auto warmUpStart = std::chrono::steady_clock::now();
    const int warmUpSteps = int(std::lround(options.warmUp / scene.params.timeStep));
    for (int k = 0; k < warmUpSteps; ++k) physics::step(start, warmUp.params);
    double perStep = bench::secondsSince(warmUpStart) / std::max(1, warmUpSteps);
    if (options.solver != "sequential") {  // one step of the solver sets how many are timed
        physics::World probe = start;
        warmUpStart = std::chrono::steady_clock::now();
        physics::step(probe, scene.params);
        perStep = bench::secondsSince(warmUpStart);
    }
    if (options.mixNumbers) start = withNumbersShuffled(start);
    const int steps = std::max(1, int(options.block / std::max(perStep, 1e-9)));

    Row row;
    row.count = count;
    if (options.chains) {
        physics::World stepped = start;
        physics::step(stepped, scene.params);  // its last substep's candidate pairs, in pass order
        row.chains = chainsRow(stepped, count);
    }
    row.solverSteps = double(steps) * scene.params.substeps;
    for (int rep = 0; rep < options.repetitions; ++rep) {
        for (std::size_t order = 0; order < options.orders.size(); ++order) {
          for (int threads : options.threads) {
            const scenes::Scene timed = pileOf(count, options, threads, false, order);
            physics::World world = start;
            physics::StepStats stats;
            const auto begin = std::chrono::steady_clock::now();
            for (int k = 0; k < steps; ++k) stats += physics::step(world, timed.params);
            Run& run = row.byRun[{order, threads}];
            run.seconds.push_back(bench::secondsSince(begin));
            run.broadPhase.push_back(stats.broadPhaseSeconds);
            run.passes.push_back(stats.passesSeconds);
            run.builds = stats.broadPhaseBuilds;
            if (rep == 0) run.hash = physics::stateHash(world);
          }
        }
    }
    return row;
}

// --busy: processes that spin on a core each until this object ends (or for
// kBusyLifetime seconds, should this process die first).
class BusyProcesses {
public:
    explicit BusyProcesses(int count) {
#ifdef __linux__
        for (int k = 0; k < count; ++k) {
            const pid_t pid = fork();
            if (pid == 0) {
                prctl(PR_SET_PDEATHSIG, SIGKILL);
                alarm(kBusyLifetime);
                for (volatile unsigned long spin = 0;; spin = spin + 1) {
                }
            }
            if (pid > 0) pids_.push_back(pid);
        }
#endif
        if (int(pids_.size()) != count) {
            std::fprintf(stderr, "spheres_bench_solver: --busy: could not start %d busy processes\n", count);
            std::exit(2);
        }
    }
    ~BusyProcesses() {
#ifdef __linux__
        for (pid_t pid : pids_) kill(pid, SIGKILL);
        for (pid_t pid : pids_) waitpid(pid, nullptr, 0);
#endif
    }
    BusyProcesses(const BusyProcesses&) = delete;
    BusyProcesses& operator=(const BusyProcesses&) = delete;

private:
    std::vector<int> pids_;
};

// s of wall time a run of --busy may take at most: a collapsing thread count ends
// early, with its time per step from the steps it made.
constexpr double kLongestLoadedRun = 20.0;

struct LoadedRun {
    std::vector<double> secondsPerStep;  // per repetition
    physics::StepStats last;             // the last step's: threads, slowerThreads
};

// The pile of `count` spheres from `start`, `steps` steps with `threads` (0: auto).
void timeLoadedRun(const physics::World& start, int count, int threads, int steps, const Options& options,
                   LoadedRun& run) {
    const scenes::Scene scene = pileOf(count, options, threads);
    physics::World world = start;
    const auto begin = std::chrono::steady_clock::now();
    int done = 0;
    while (done < steps && bench::secondsSince(begin) < kLongestLoadedRun) {
        run.last = physics::step(world, scene.params);
        ++done;
    }
    run.secondsPerStep.push_back(bench::secondsSince(begin) / (done * scene.params.substeps));
}

std::string threadsName(int threads) { return threads == 0 ? "auto" : std::to_string(threads); }

// --busy: each thread count alone and beside `options.busy` busy processes, interleaved.
int compareUnderLoad(Options options) {
    if (!options.countsGiven) options.counts = {16000, 64000};
    if (!options.threadsGiven) options.threads = {1, 2, 0};
    std::printf("Pile (%s), K = %d, alone and beside %d busy processes, %s, %d usable cores; load average %s\n\n",
                bench::presetContaining("pile").c_str(), options.passes, options.busy, bench::cpuModel().c_str(),
                physics::usableCores(), bench::loadAverage().c_str());
    std::printf("| N | beside | threads | ms per solver step | time / one thread's | threads at the end |\n");
    std::printf("|---:|---|---:|---:|---:|---|\n");
    for (int count : options.counts) {
        scenes::Scene scene = pileOf(count, options, 1);
        physics::World start = scenes::buildWorld(scene);
        const auto warmUpStart = std::chrono::steady_clock::now();
        const int warmUpSteps = int(std::lround(options.warmUp / scene.params.timeStep));
        for (int k = 0; k < warmUpSteps; ++k) physics::step(start, scene.params);
        const double perStep = bench::secondsSince(warmUpStart) / std::max(1, warmUpSteps);
        const int steps = std::max(1, int(2.0 / std::max(perStep, 1e-9)));
        std::map<int, LoadedRun> alone, loaded;
        for (int rep = 0; rep < options.repetitions; ++rep) {
            for (int threads : options.threads) timeLoadedRun(start, count, threads, steps, options, alone[threads]);
            const BusyProcesses busy(options.busy);
            for (int threads : options.threads) timeLoadedRun(start, count, threads, steps, options, loaded[threads]);
        }
        for (const auto* runs : {&alone, &loaded}) {
            const double one = runs->count(1) ? bench::median(runs->at(1).secondsPerStep) : std::nan("");
            for (int threads : options.threads) {
                const LoadedRun& run = runs->at(threads);
                const double seconds = bench::median(run.secondsPerStep);
                std::string end = std::to_string(run.last.threads);
                if (run.last.slowerThreads > 0) end += " (" + std::to_string(run.last.slowerThreads) + " were slower)";
                std::printf("| %s | %s | %s | %.3f | %.2f | %s |\n", bench::grouped(count).c_str(),
                            runs == &alone ? "nothing" : (std::to_string(options.busy) + " busy").c_str(),
                            threadsName(threads).c_str(), 1e3 * seconds, seconds / one, end.c_str());
            }
        }
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv);
    for (std::size_t order = 0; order < options.orders.size(); ++order) {
        pileOf(1000, options, 1, false, order);  // a refused --solver or --order says so before anything is printed
    }
    if (options.busy > 0) return compareUnderLoad(options);
    std::string orders;
    for (const std::string& order : options.orders) orders += (orders.empty() ? "" : ", ") + order;
    std::printf("Pile (%s), K = %d, orders %s, solver %s, shock %s%s, %s; load average %s at the start\n\n",
                bench::presetContaining("pile").c_str(), options.passes, orders.c_str(), options.solver.c_str(),
                options.shock.c_str(),
                options.mixNumbers ? ", numbers shuffled after the warm-up" : "",
                bench::cpuModel().c_str(), bench::loadAverage().c_str());
    std::printf("| N | order | threads | ms per solver step | ns per sphere-step | × one thread | × %s | broad phase ms "
                "| passes ms | rebuilds | hash |\n",
                options.orders.front().c_str());
    std::printf("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    std::map<std::pair<std::size_t, int>, std::vector<double>> counts, times;  // by order, threads
    std::vector<std::string> chains;
    bool same = true;
    for (int count : options.counts) {
        const Row row = measure(count, options);
        chains.push_back(row.chains);
        for (const auto& [key, run] : row.byRun) {
            const auto& [order, threads] = key;
            const Run& oneThread = row.byRun.at({order, options.threads.front()});
            const Run& firstOrder = row.byRun.at({0, threads});
            const double seconds = bench::median(run.seconds);
            const bool equal = run.hash == oneThread.hash;
            same = same && equal;
            std::printf("| %s | %s | %d | %.3f | %.0f | %.2f | %.2f | %.3f | %.3f | %.0f %% | %016llx%s |\n",
                        bench::grouped(count).c_str(), options.orders[order].c_str(), threads,
                        1e3 * seconds / row.solverSteps, 1e9 * seconds / (row.solverSteps * count),
                        bench::median(oneThread.seconds) / seconds, bench::median(firstOrder.seconds) / seconds,
                        1e3 * bench::median(run.broadPhase) / row.solverSteps,
                        1e3 * bench::median(run.passes) / row.solverSteps, 100.0 * double(run.builds) / row.solverSteps,
                        static_cast<unsigned long long>(run.hash), equal ? "" : " DIFFERENT");
            counts[key].push_back(count);
            times[key].push_back(seconds / row.solverSteps);
        }
        std::fflush(stdout);
    }
    if (options.counts.size() > 1) {
        std::printf("\nlog-log slope of time per step against N:");
        for (const auto& [key, t] : times) {
            std::printf(" %.3f (%s, %d thread%s)", bench::logLogSlope(counts[key], t), options.orders[key.first].c_str(),
                        key.second, key.second > 1 ? "s" : "");
        }
        std::printf("\n");
    }
    if (options.chains) {
        std::printf("\nPairs that could be visited side by side with the same result, in the pass order of\n"
                    "the last substep of one step after the warm-up (a pair comes after every earlier pair\n"
                    "that shares a sphere with it):\n\n"
                    "| N | candidate pairs | longest chain | pairs per level | per level, windows of 64 | 256 | 1024 |\n"
                    "|---:|---:|---:|---:|---:|---:|---:|\n");
        for (const std::string& row : chains) std::printf("%s\n", row.c_str());
    }
    std::printf("\n%s\n", same ? "every thread count reached the same state" : "THREADS CHANGED THE RESULT");
    return same ? 0 : 1;
}
