#pragma once
// Progress of a long headless run on a terminal: "frames 120/600 (20 %), 35.2 frames/s,
// 14 s left", rewritten in place on standard error. Silent when standard error is not
// a terminal (a pipeline, a log file, the tests) and for runs shorter than a second.
#include <chrono>
#include <cstdint>
#include <string>

namespace app {

// The line for `done` of `total` after `seconds` of wall time ("steps", "frames").
std::string progressText(const char* unit, std::uint64_t done, std::uint64_t total, double seconds);

class ProgressLine {
public:
    ProgressLine(const char* unit, std::uint64_t total);
    ~ProgressLine();  // clears the line, so that the result printed next starts clean
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void update(std::uint64_t done);

private:
    const char* unit_;
    std::uint64_t total_;
    bool terminal_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point lastShown_ = start_;
};

}  // namespace app
