#pragma once
// Side by side: one to three more Simulations of the same scene, each with one or more
// parameters overridden ("method=velocity"), built from the same initial state and
// advanced with the same real seconds, so that the views step together and differ
// only by what the overrides say. The window and `spheres capture --compare` use it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "app/run/simulation.h"
#include "physics/diagnostics.h"
#include "scenes/overrides.h"

namespace app {

using scenes::checkCompare;
using scenes::checkOverrides;
using scenes::kMostViews;
using scenes::overrideLabel;
using scenes::overrideVariants;
using scenes::splitOverrides;
using scenes::Variants;

class Comparison {
public:
    // The other runs: `primary`'s scene with each variant's overrides applied (checked
    // first with checkOverrides; throws UsageError when one is refused), from its
    // initial state. One variant per view, at most kMostViews - 1.
    Comparison(const scenes::Scene& primary, Variants variants);
    Comparison(const scenes::Scene& primary, std::vector<std::string> overrides)
        : Comparison(primary, Variants{std::move(overrides)}) {}

    // Rebuilds from the primary's scene (after a restart, a new preset or file).
    void restartFrom(const scenes::Scene& primary);
    // Before each frame: the primary's live parameters (what the panel edits), its
    // time scale and pause, then each run's overrides again.
    void follow(const Simulation& primary);

    int count() const { return int(runs_.size()); }  // the other runs: B, C, D
    Simulation& simulation(int k = 0) { return *runs_[std::size_t(k)].simulation; }
    const Simulation& simulation(int k = 0) const { return *runs_[std::size_t(k)].simulation; }
    const std::vector<std::string>& overrides(int k = 0) const { return runs_[std::size_t(k)].overrides; }

    // {method, position} (the primary's values of every overridden name) and {method,
    // velocity} (run k's); as one line, "method = position" and "method = velocity".
    std::vector<scenes::ShownSetting> primarySettings(const scenes::Scene& primary) const;
    std::vector<scenes::ShownSetting> settings(int k = 0) const {
        return scenes::shownSettings(simulation(k).scene(), overrides(k));
    }
    std::string primaryLabel(const scenes::Scene& primary) const { return overrideLabel(primarySettings(primary)); }
    std::string label(int k = 0) const { return overrideLabel(settings(k)); }
    // Whether every run shows what the primary shows: the overrides change nothing.
    bool changesNothing(const scenes::Scene& primary) const;
    // The parameters every other run sets itself: the panel's edit of one reaches view A
    // alone (on slide 14's column, K and shock).
    std::vector<std::string> setInEveryView() const;

private:
    struct Run {
        std::vector<std::string> overrides;
        std::unique_ptr<Simulation> simulation;
    };
    static scenes::Scene withOverrides(const scenes::Scene& primary, const std::vector<std::string>& overrides);

    std::vector<Run> runs_;
};

// One view's title and numbers, for its label.
struct ViewReadout {
    char letter = 'A';
    std::vector<scenes::ShownSetting> settings;  // what differs: {method, position}
    std::string title;  // "A   method = position"
    physics::Diagnostics diagnostics;
    double time = 0.0;  // s
    std::uint64_t steps = 0;
    std::string properties;  // slide 14's five properties, marks only ("" until a contact)
    // Slide 4's apex ratio, where the restitution meter follows the view's spheres: the
    // newest floor bounce's (none yet: not measured), beside beta^2.
    bool bouncesMeasured = false;
    std::optional<double> apexRatio;
    std::uint64_t apexBounce = 0;  // which bounce apexRatio is (1 the first), with one sphere; else 0
    double betaSquared = 0.0;
    // The most work its method or solver took in one time step since the restart ("most a
    // step: lcp sweeps 14"); "" for the sequential passes.
    std::string work;
};

// The lines of a view's label: the title, then energy, momentum, penetration, hash, the
// apex ratio where bounces are measured, the solver's work, and the five properties' marks
// when there are any.
std::vector<std::string> viewReadoutLines(const ViewReadout& view);
// The presentation layout's: the title, E~, the penetration and the apex ratio, short lines,
// and the properties' marks where the views compare solvers or the shock sweep.
std::vector<std::string> presentedLines(const ViewReadout& view);
// Beside the dock (a sphere inspected or explained), where four full labels left thumbnails:
// the title, E~ with the penetration, and the properties' marks.
std::vector<std::string> compactLines(const ViewReadout& view);

// Which of those a view's label shows.
enum class LabelLines { Full, Compact, Presented };

// Override lists as one text, as the window's bar and the page's field show them:
// joined by commas.
std::string joinedOverrides(const std::vector<std::string>& lists);

// What the side-by-side field offers for `scene` until the user writes there: the scene's
// own "compare", else the other of the slides' two methods (method=velocity offered on the
// cradle, already velocity based, made two identical views).
std::string suggestedOverrides(const scenes::Scene& scene);

// Each view's label lines, A first: "A   method = position", then its readouts
// (viewReadoutLines, compactLines or presentedLines).
// The window draws them with ImGui (view_labels.h), the browser's page as text.
std::vector<std::vector<std::string>> comparisonReadouts(const Simulation& primary, const Comparison& comparison,
                                                         LabelLines lines = LabelLines::Full);
// What those lines are made from, each view measured once: A first.
std::vector<ViewReadout> viewReadouts(const Simulation& primary, const Comparison& comparison);
// Each view's tooltip, A first: what its properties' marks mean, and their numbers.
std::vector<std::string> propertiesTooltips(const Simulation& primary, const Comparison& comparison);

}  // namespace app
