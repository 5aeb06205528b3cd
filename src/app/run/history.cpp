#include "app/run/history.h"

#include <fstream>

#include <glm/geometric.hpp>

namespace app {

void History::clear() {
    times_.clear();
    for (auto& series : ordered_) series.clear();
}

void History::add(double time, const physics::Diagnostics& d, std::uint64_t inContact, std::uint64_t bounces) {
    const float sample[] = {float(d.kinetic), float(d.potential), float(d.modified), float(glm::length(physics::momentumShown(d))),
                            float(inContact), float(d.maxPenetration), float(bounces)};
    static_assert(sizeof sample / sizeof sample[0] == static_cast<std::size_t>(Series::Count));
    // Kept in order (oldest first) so the plots read the vectors as they are; at
    // 600 samples the shift costs less than a frame's drawing.
    if (times_.size() == kCapacity) {
        times_.erase(times_.begin());
        for (auto& series : ordered_) series.erase(series.begin());
    }
    times_.push_back(time);
    for (int s = 0; s < static_cast<int>(Series::Count); ++s) ordered_[s].push_back(sample[s]);
}

const char* History::name(Series series) {
    switch (series) {
        case Series::Kinetic: return "kinetic energy (J)";
        case Series::Potential: return "potential energy (J)";
        case Series::Modified: return "modified energy E~ (J)";
        case Series::Momentum: return "|momentum| (kg m/s)";
        case Series::InContact: return "spheres in contact (most in a step)";
        case Series::Penetration: return "deepest penetration / r";
        case Series::Bounces: return "bounces since restart";
        case Series::Count: break;
    }
    return "";
}

bool History::writeCsv(const std::string& path) const {
    std::ofstream file(path);
    if (!file) return false;
    file << "time_s";
    for (int s = 0; s < static_cast<int>(Series::Count); ++s) file << ",\"" << name(Series(s)) << '"';
    file << '\n';
    for (std::size_t k = 0; k < times_.size(); ++k) {
        file << times_[k];
        for (const auto& series : ordered_) file << ',' << series[k];
        file << '\n';
    }
    return static_cast<bool>(file);
}

}  // namespace app
