#include "app/commands/progress_line.h"

#include <cstdio>

#include <unistd.h>

namespace app {
namespace {

constexpr double kQuietSeconds = 1.0;     // s before the first line
constexpr double kRefreshSeconds = 0.25;  // s between lines

double secondsBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

}  // namespace

std::string progressText(const char* unit, std::uint64_t done, std::uint64_t total, double seconds) {
    const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;  // per s
    char text[160];
    int length = std::snprintf(text, sizeof text, "%s %llu/%llu (%.0f %%), %.1f %s/s", unit,
                               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                               total > 0 ? 100.0 * double(done) / double(total) : 100.0, rate, unit);
    if (rate > 0.0 && done < total && length > 0 && length < int(sizeof text)) {
        std::snprintf(text + length, sizeof text - std::size_t(length), ", %.0f s left", double(total - done) / rate);
    }
    return text;
}

ProgressLine::ProgressLine(const char* unit, std::uint64_t total)
    : unit_(unit), total_(total), terminal_(isatty(fileno(stderr)) == 1) {}

ProgressLine::~ProgressLine() {
    if (shown_) std::fprintf(stderr, "\r\033[K");  // carriage return, erase the line
}

void ProgressLine::update(std::uint64_t done) {
    if (!terminal_) return;
    const auto now = std::chrono::steady_clock::now();
    if (secondsBetween(start_, now) < kQuietSeconds || (shown_ && secondsBetween(lastShown_, now) < kRefreshSeconds)) {
        return;
    }
    std::fprintf(stderr, "\r\033[K%s", progressText(unit_, done, total_, secondsBetween(start_, now)).c_str());
    std::fflush(stderr);
    shown_ = true;
    lastShown_ = now;
}

}  // namespace app
