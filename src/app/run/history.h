#pragma once
// The last few hundred samples of the readouts, for the UI's scrolling plots and
// for export as CSV.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "physics/diagnostics.h"

namespace app {

enum class Series { Kinetic, Potential, Modified, Momentum, InContact, Penetration, Bounces, Count };

class History {
public:
    static constexpr int kCapacity = 600;  // samples kept

    void clear();
    // The energies, momentum and penetration from `d` (Simulation gives the deepest of the
    // frame's steps in small scenes); `inContact`: the most spheres whose
    // contact one solver step of the frame answered (StepStats::mostSpheresInContact);
    // `bounces`: contacts answered as a bounce since restart (Simulation::bouncesSinceRestart).
    void add(double time, const physics::Diagnostics& d, std::uint64_t inContact, std::uint64_t bounces);
    // Oldest first, for ImGui::PlotLines.
    const std::vector<float>& values(Series series) const { return ordered_[static_cast<int>(series)]; }
    std::size_t size() const { return times_.size(); }
    const std::vector<double>& times() const { return times_; }  // s, of the samples, oldest first
    static const char* name(Series series);  // with its unit
    // Writes time and every series as CSV; false when the file cannot be written.
    bool writeCsv(const std::string& path) const;

private:
    std::vector<double> times_;
    std::array<std::vector<float>, static_cast<int>(Series::Count)> ordered_;
};

}  // namespace app
