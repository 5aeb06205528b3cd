#pragma once
// Side by side: a second Simulation of the same scene with one or more parameters
// overridden ("method=velocity"), built from the same initial state and advanced
// with the same real seconds, so that two views step together and differ only by
// what the overrides say. The window and `spheres capture --compare` both use it.
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "app/run/simulation.h"
#include "physics/diagnostics.h"

namespace app {

// "name=value[,name=value]" lists (each string may hold several, separated by
// commas) as single "name=value" settings, trimmed, empty ones dropped.
std::vector<std::string> splitOverrides(const std::vector<std::string>& lists);

// "" when every override applies to a copy of `scene`, else one line naming the bad one.
std::string checkOverrides(const scenes::Scene& scene, const std::vector<std::string>& overrides);

// What a view shows about its parameters: "method = velocity, order = reversed",
// the overridden names with their values in `scene`.
std::string overrideLabel(const scenes::Scene& scene, const std::vector<std::string>& overrides);

class Comparison {
public:
    // The second run: `primary`'s scene with `overrides` applied (checked first with
    // checkOverrides; throws UsageError when one is refused), from its initial state.
    Comparison(const scenes::Scene& primary, std::vector<std::string> overrides);

    // Rebuilds from the primary's scene (after a restart, a new preset or file).
    void restartFrom(const scenes::Scene& primary);
    // Before each frame: the primary's live parameters (what the panel edits), its
    // time scale and pause, then the overrides again.
    void follow(const Simulation& primary);

    Simulation& simulation() { return simulation_; }
    const Simulation& simulation() const { return simulation_; }
    const std::vector<std::string>& overrides() const { return overrides_; }

    // "method = position" (the primary's values) and "method = velocity" (this run's).
    std::string primaryLabel(const scenes::Scene& primary) const { return overrideLabel(primary, overrides_); }
    std::string label() const { return overrideLabel(simulation_.scene(), overrides_); }

private:
    scenes::Scene withOverrides(const scenes::Scene& primary) const;

    std::vector<std::string> overrides_;
    Simulation simulation_;
};

// The two halves of a viewport (x, y, width, height; GL's lower-left origin), with a
// gap of `gap` pixels between them: left is the primary run, right the comparison.
void splitViewport(glm::ivec4 view, int gap, glm::ivec4& left, glm::ivec4& right);

// One view's title and numbers, for its label.
struct ViewReadout {
    std::string title;  // "A  method = position"
    physics::Diagnostics diagnostics;
    double time = 0.0;  // s
    std::uint64_t steps = 0;
};

// The lines of a view's label: the title, then energy, momentum, penetration, hash.
std::vector<std::string> viewReadoutLines(const ViewReadout& view);

}  // namespace app
