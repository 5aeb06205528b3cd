#pragma once
// Shared by the benchmark programs of this folder: the shipped scenes scaled to N
// spheres, medians, log-log slopes and the machine's load. Header only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace bench {

// The first shipped preset whose name contains `part` ("pile", "gas"): presets are
// renumbered from time to time, their names stay. Exits when there is none.
inline std::string presetContaining(std::string_view part) {
    for (const std::string& name : scenes::listPresets()) {
        if (name.find(part) != std::string::npos) return name;
    }
    std::fprintf(stderr, "bench: no preset in %s/scenes has '%.*s' in its name\n",
                 scenes::assetDirectory().c_str(), int(part.size()), part.data());
    std::exit(2);
}

inline scenes::Scene loadPreset(const std::string& name) {
    try {
        return scenes::loadScene(scenes::presetPath(name));
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench: %s\n", error.what());
        std::exit(2);
    }
}

// "name=value" through the parameter table; exits on a refused setting.
inline void set(scenes::Scene& scene, const std::string& setting) {
    const std::string error = scenes::applySetting(scene, setting);
    if (!error.empty()) {
        std::fprintf(stderr, "bench: %s: %s\n", setting.c_str(), error.c_str());
        std::exit(2);
    }
}

// m: the radius that keeps the volume of `reference` spheres of `radius` with
// `count` spheres (r ~ N^(-1/3)), never below the parameter table's 5 mm.
inline double scaledRadius(double radius, int reference, int count) {
    return std::max(0.005, radius * std::cbrt(double(reference) / count));
}

// The pile preset with `count` spheres of one radius, 5 cm at N = 1000.
inline scenes::Scene pileOf(int count) {
    scenes::Scene scene = loadPreset(presetContaining("pile"));
    set(scene, "count=" + std::to_string(count));
    set(scene, "radius=" + scenes::formatNumber(scaledRadius(0.05, 1000, count)));
    return scene;
}

inline double median(std::vector<double> values) {
    if (values.empty()) return std::nan("");
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + long(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1) return upper;
    return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + long(middle)));
}

// The least-squares slope of log(y) against log(x): the exponent b of y ~ x^b.
inline double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2) return std::nan("");
    double mx = 0.0, my = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        mx += std::log(x[k]);
        my += std::log(y[k]);
    }
    mx /= double(n);
    my /= double(n);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double dx = std::log(x[k]) - mx;
        sxy += dx * (std::log(y[k]) - my);
        sxx += dx * dx;
    }
    return sxy / sxx;
}

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "1.08 1.56 1.66": the 1, 5 and 15 minute load averages (Linux), or "?".
inline std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "?";
    return one + " " + five + " " + fifteen;
}

// The CPU's model name (Linux), or "?".
inline std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
    return "?";
}

// Thousands with a thin separator as the README writes them: 256000 -> "256 000".
inline std::string grouped(long long value) {
    std::string digits = std::to_string(value < 0 ? -value : value);
    for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(std::size_t(at), " ");
    return value < 0 ? "-" + digits : digits;
}

// Simulated seconds from 0 to 600 (the steps they take are counted in an int): false
// when `text` is not such a number.
inline bool parseSimulatedSeconds(const std::string& text, double& seconds) {
    char* end = nullptr;
    seconds = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0' && seconds >= 0.0 && seconds <= 600.0;
}

// A list of whole numbers "1000,4k,16k,1M"; false when a part is not one.
inline bool parseCounts(const std::string& text, std::vector<int>& out) {
    out.clear();
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        std::string part = text.substr(start, comma - start);
        double scale = 1.0;
        if (!part.empty() && (part.back() == 'k' || part.back() == 'K')) scale = 1e3;
        if (!part.empty() && part.back() == 'M') scale = 1e6;
        if (scale != 1.0) part.pop_back();
        char* end = nullptr;
        const double value = std::strtod(part.c_str(), &end);
        if (part.empty() || *end != '\0' || !(value * scale >= 1.0) || value * scale > 1e8)
            return false;
        out.push_back(int(std::lround(value * scale)));
        start = comma + 1;
    }
    return !out.empty();
}

// A program's name and usage text, for the two below.
struct Usage {
    const char* program;
    const char* text;
};

// Prints "program: why" and the usage on stderr; exits with code 2.
[[noreturn]] inline void usageError(const Usage& usage, const std::string& why) {
    std::fprintf(stderr, "%s: %s\n%s", usage.program, why.c_str(), usage.text);
    std::exit(2);
}

// With --help or -h, prints the usage and exits with code 0.
inline void helpIfAsked(const Usage& usage, const std::string& option) {
    if (option != "--help" && option != "-h") return;
    std::fputs(usage.text, stdout);
    std::exit(0);
}

}  // namespace bench
