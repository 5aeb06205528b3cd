#pragma once
// `spheres simulate`: runs a scene without any GL and reports what happened.
#include <cstdint>
#include <string>
#include <vector>

namespace app {

struct SimulateOptions {
    std::string scene;                  // file or preset name
    std::vector<std::string> settings;  // "name=value"
    std::int64_t steps = 600;           // time steps of h
    std::int64_t every = 0;             // write diagnostics every K steps (0: never)
    std::string out;                    // diagnostics: .csv or .jsonl
    std::string state;                  // final state of every sphere: .csv
    std::string save;                   // final scene and state: .json
};

// Returns the process exit code. Throws UsageError / scenes::SceneError on bad input.
int runSimulate(const SimulateOptions& options);

}  // namespace app
