#include "app/run/comparison.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <utility>

#include "app/run/scene_source.h"
#include "app/teaching/impact_report.h"
#include "scenes/parameters.h"

namespace app {

Comparison::Comparison(const scenes::Scene& primary, Variants variants) {
    if (variants.empty() || int(variants.size()) > kMostViews - 1) {
        throw UsageError("--compare: 1 to " + std::to_string(kMostViews - 1) + " views besides A");
    }
    for (std::vector<std::string>& overrides : variants) {
        scenes::Scene scene = withOverrides(primary, overrides);
        runs_.push_back({std::move(overrides), std::make_unique<Simulation>(std::move(scene))});
    }
}

scenes::Scene Comparison::withOverrides(const scenes::Scene& primary, const std::vector<std::string>& overrides) {
    if (const std::string error = checkOverrides(primary, overrides); !error.empty()) {
        throw UsageError("--compare " + error);
    }
    scenes::Scene scene = primary;
    for (const std::string& setting : overrides) scenes::applySetting(scene, setting);
    return scene;
}

void Comparison::restartFrom(const scenes::Scene& primary) {
    for (Run& run : runs_) {
        const double timeScale = run.simulation->timeScale;
        const bool paused = run.simulation->paused;
        run.simulation->setScene(withOverrides(primary, run.overrides));
        run.simulation->timeScale = timeScale;
        run.simulation->paused = paused;
    }
}

void Comparison::follow(const Simulation& primary) {
    for (Run& run : runs_) {
        scenes::Scene& scene = run.simulation->editableScene();
        scene.params = primary.scene().params;
        for (const std::string& setting : run.overrides) {
            const scenes::Parameter* parameter = scenes::findParameter(scenes::settingName(setting));
            if (parameter && parameter->applies == scenes::Applies::Live) scenes::applySetting(scene, setting);
        }
        run.simulation->timeScale = primary.timeScale;
        run.simulation->paused = primary.paused;
    }
}

std::vector<scenes::ShownSetting> Comparison::primarySettings(const scenes::Scene& primary) const {
    std::vector<std::string> every;
    for (const Run& run : runs_) every.insert(every.end(), run.overrides.begin(), run.overrides.end());
    return scenes::shownSettings(primary, every);
}

bool Comparison::changesNothing(const scenes::Scene& primary) const {
    for (const Run& run : runs_) {
        if (overrideLabel(primary, run.overrides, true) != overrideLabel(run.simulation->scene(), run.overrides, true)) {
            return false;
        }
    }
    return true;
}

std::vector<std::string> Comparison::setInEveryView() const {
    std::vector<std::string> names;
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        const auto sets = [&](const Run& run) {
            return std::any_of(run.overrides.begin(), run.overrides.end(),
                               [&](const std::string& setting) { return scenes::settingName(setting) == p.name; });
        };
        if (!runs_.empty() && std::all_of(runs_.begin(), runs_.end(), sets)) names.emplace_back(p.name);
    }
    return names;
}

namespace {

// "apex ratio 0.590 (β² 0.640)", a dash until the first bounce, "apex ratio 0.467 at bounce 5
// (β² 0.640)" where the bounces are one ball's; `space` joins a number to its name (a
// no-break space where the line may wrap).
std::string apexRatioLine(const ViewReadout& view, const char* space) {
    char ratio[64] = "\u2013";
    if (view.apexRatio) std::snprintf(ratio, sizeof ratio, "%.3f", *view.apexRatio);
    if (view.apexRatio && view.apexBounce > 0) {
        std::snprintf(ratio + std::strlen(ratio), sizeof ratio - std::strlen(ratio), " at bounce%s%llu", space,
                      static_cast<unsigned long long>(view.apexBounce));
    }
    char line[128];
    std::snprintf(line, sizeof line, "apex ratio%s%s (\u03b2\u00b2%s%.3f)", space, ratio, space, view.betaSquared);
    return line;
}

// The properties' marks, a line each as judged ("✓ momentum  ✓ energy  ✗ symmetry").
void appendProperties(const ViewReadout& view, std::vector<std::string>& lines) {
    for (std::size_t at = 0; at < view.properties.size();) {
        const std::size_t end = std::min(view.properties.find('\n', at), view.properties.size());
        lines.push_back(view.properties.substr(at, end - at));
        at = end + 1;
    }
}

// Whether every view differs in one and the same parameter: presented, each is then titled
// by its value alone, "B   simultaneous" (the panel's slider names it): "solver =
// generalized-reflections" took four lines of large type in a quarter of a projector.
bool differInOne(const std::vector<ViewReadout>& views) {
    for (const ViewReadout& view : views) {
        if (view.settings.size() != 1 || view.settings[0].name != views[0].settings[0].name) return false;
    }
    return !views.empty();
}

bool differsIn(const ViewReadout& view, const char* name) {
    return std::any_of(view.settings.begin(), view.settings.end(), [&](const scenes::ShownSetting& s) { return s.name == name; });
}

// The names after each `mark` in the marks' line.
std::vector<std::string> namesMarked(const std::string& marks, const std::string& mark) {
    std::vector<std::string> names;
    for (std::size_t at = marks.find(mark); at != std::string::npos; at = marks.find(mark, at + 1)) {
        const std::size_t name = at + mark.size();
        const std::size_t end = std::min(marks.find_first_of(" \n", name), marks.size());
        names.push_back(marks.substr(name, end - name));
    }
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// The marks as a projector shows them: what the solver breaks, a line each ("✗ momentum",
// "✗ positivity"), "✓ nothing broken", or "– none tested yet" (five marks in large type
// broke inside their words, and so did "✗ momentum, positivity" in a quarter of the width).
std::vector<std::string> brokenProperties(const std::string& marks) {
    // A mark stays with its word (a no-break space, U+00A0): four narrow labels on a
    // projector had "✗" alone above "break-away".
    const std::vector<std::string> broken = namesMarked(marks, "\u2717\u00a0");
    if (marks.find("not measured") == std::string::npos) {
        std::vector<std::string> lines;
        for (const std::string& name : broken) lines.push_back("\u2717\u00a0" + name);
        if (lines.empty()) {
            lines.push_back(marks.find("\u2713") != std::string::npos ? "\u2713\u00a0nothing broken"
                                                                      : "\u2013\u00a0none tested yet");
        }
        return lines;
    }
    // The continuous method measures the symmetry alone: what it found, and that the others
    // are not measured ("nothing broken" would claim five properties from the symmetry).
    if (!broken.empty()) return {"\u2717\u00a0" + joined(broken) + ", " + kOthersNotMeasured};
    const std::vector<std::string> kept = namesMarked(marks, "\u2713\u00a0");
    return {kept.empty() ? "\u2013\u00a0not measured (continuous)" : "\u2713\u00a0" + joined(kept) + ", " + kOthersNotMeasured};
}

}  // namespace

std::vector<std::string> viewReadoutLines(const ViewReadout& view) {
    const physics::Diagnostics& d = view.diagnostics;
    char line[160];
    std::vector<std::string> lines{view.title};
    // A number joined to its name and unit by no-break spaces (U+00A0): a narrow label wraps
    // between the readouts, not inside one ("t" / "4.367 s").
    std::snprintf(line, sizeof line, "E\u00a0%.6g\u00a0J   E~\u00a0%.6g\u00a0J", d.total, d.modified);
    lines.emplace_back(line);
    const glm::dvec3 p = physics::momentumShown(d);  // kg m/s
    std::snprintf(line, sizeof line, "p (%.3g, %.3g, %.3g) kg m/s", p.x, p.y, p.z);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "penetration %.2f\u00a0%%\u00a0r   t\u00a0%.3f\u00a0s",
                  100.0 * d.maxPenetration, view.time);
    lines.emplace_back(line);
    std::snprintf(line, sizeof line, "hash %016llx", static_cast<unsigned long long>(d.hash));
    lines.emplace_back(line);
    if (view.bouncesMeasured) lines.push_back(apexRatioLine(view, " "));
    if (!view.work.empty()) lines.push_back(view.work);
    appendProperties(view, lines);
    return lines;
}

std::vector<std::string> compactLines(const ViewReadout& view) {
    char line[160];
    std::snprintf(line, sizeof line, "E~\u00a0%.6g\u00a0J   penetration %.2f\u00a0%%\u00a0r", view.diagnostics.modified,
                  100.0 * view.diagnostics.maxPenetration);
    std::vector<std::string> lines{view.title, line};
    appendProperties(view, lines);
    return lines;
}

// Presented, a label is short lines in large type: what the slides compare, the energy
// (slide 14's simultaneous solver makes it grow) and the deepest penetration (slide 7's
// answers, slide 14's sweep); where the views compare solvers or the shock sweep, the five
// properties too (slide 14's lesson: sequential breaks the symmetry, simultaneous creates
// energy; one pass leaves contacts approaching that the sweep answers).
std::vector<std::string> presentedLines(const ViewReadout& view) {
    char energy[64], penetration[64];  // a number and its unit joined by no-break spaces (U+00A0)
    std::snprintf(energy, sizeof energy, "E~ %.4g\u00a0J", view.diagnostics.modified);
    std::snprintf(penetration, sizeof penetration, "penetration %.2f\u00a0%%\u00a0r", 100.0 * view.diagnostics.maxPenetration);
    std::vector<std::string> lines{view.title, energy, penetration};
    if (view.bouncesMeasured) lines.push_back(apexRatioLine(view, "\u00a0"));
    if ((differsIn(view, "solver") || differsIn(view, "shock")) && !view.properties.empty()) {
        for (std::string& line : brokenProperties(view.properties)) lines.push_back(std::move(line));
    }
    return lines;
}

std::string suggestedOverrides(const scenes::Scene& scene) {
    if (!scene.compare.empty()) return joinedOverrides(scene.compare);
    return scene.params.method == physics::Method::VelocityBased ? "method=position" : "method=velocity";
}

std::string joinedOverrides(const std::vector<std::string>& lists) {
    std::string text;
    for (const std::string& list : lists) text += (text.empty() ? "" : ",") + list;
    return text;
}

std::vector<std::vector<std::string>> comparisonReadouts(const Simulation& primary, const Comparison& comparison,
                                                         LabelLines lines) {
    std::vector<ViewReadout> readouts = viewReadouts(primary, comparison);
    if (lines == LabelLines::Presented && differInOne(readouts)) {
        for (ViewReadout& readout : readouts) readout.title = std::string(1, readout.letter) + "   " + readout.settings[0].value;
    }
    std::vector<std::vector<std::string>> views;
    for (const ViewReadout& readout : readouts) {
        views.push_back(lines == LabelLines::Presented ? presentedLines(readout)
                        : lines == LabelLines::Compact ? compactLines(readout)
                                                       : viewReadoutLines(readout));
    }
    return views;
}

namespace {

// The most work the run's method or solver took in one time step since the restart: what
// the views compare (a label of the last step's read 0 but in the frame of an impact).
std::string workOf(const Simulation& run) {
    const physics::Params& params = run.params();
    const physics::StepStats& s = run.mostWorkAStep();
    // "1 reflection round", "26 lcp sweeps": the number joined to its noun by a no-break space.
    const auto counted = [](std::uint64_t n, const char* one, const char* many) {
        return std::to_string(n) + "\u00a0" + (n == 1 ? one : many);
    };
    std::string work;
    if (params.method == physics::Method::Continuous) {
        work = counted(s.events, "impact", "impacts");
    } else if (params.solver == physics::Solver::GeneralizedReflections) {
        work = counted(s.reflectionRounds, "reflection round", "reflection rounds");
    } else if (physics::solvesGlobally(params.solver)) {
        work = counted(s.lcpSweeps, "lcp sweep", "lcp sweeps");
    } else if (params.solver == physics::Solver::UntilConverged) {
        work = counted(s.passesUsed, "pass", "passes");
    }
    if (params.shock == physics::ShockPropagation::On && physics::sweepsLevels(params.method)) {
        work += (work.empty() ? "" : ", ") + counted(s.shockLevels, "shock level", "shock levels") + ", " +
                counted(s.shockRounds, "round", "rounds");
    }
    return work.empty() ? work : "most in one step: " + work;
}

std::vector<PropertyVerdict> judgedProperties(const Simulation& run) {
    std::vector<physics::MirrorAsymmetry> mirrors;
    for (const physics::Plane& m : run.scene().mirrors) mirrors.push_back(physics::mirrorAsymmetry(run.world(), m));
    return judgeProperties(run.impacts(), mirrors, run.params());
}

}  // namespace

std::vector<std::string> propertiesTooltips(const Simulation& primary, const Comparison& comparison) {
    std::vector<std::string> tips;
    for (int k = 0; k <= comparison.count(); ++k) {
        tips.push_back(propertiesTooltip(judgedProperties(k == 0 ? primary : comparison.simulation(k - 1))));
    }
    return tips;
}

std::vector<ViewReadout> viewReadouts(const Simulation& primary, const Comparison& comparison) {
    std::vector<ViewReadout> views;
    for (int k = 0; k <= comparison.count(); ++k) {
        const Simulation& run = k == 0 ? primary : comparison.simulation(k - 1);
        const physics::World& world = run.world();
        ViewReadout readout;
        readout.letter = char('A' + k);
        readout.settings = k == 0 ? comparison.primarySettings(primary.scene()) : comparison.settings(k - 1);
        readout.title = std::string(1, readout.letter) + "   " + scenes::overrideLabel(readout.settings);
        readout.diagnostics = physics::measure(world, run.params());
        readout.time = world.time;
        readout.steps = world.stepCount;
        // From the first frame on (dashes until measured): the label keeps its size.
        readout.properties = propertiesMarks(judgedProperties(run));
        // Scenes the meter follows whole (not the selected sphere alone: a column's would read
        // "–" for ever, and the label would change size with the selection).
        readout.bouncesMeasured = followsBounces(world, run.params(), -1);
        // The last bounce at the β set now: one of an earlier β read "0.640 (β² 0.250)".
        const auto& latest = run.restitution().latest();
        if (latest && latest->beta == run.params().beta) readout.apexRatio = latest->ratio();
        // Its number where the bounces are one ball's: the texts count them ("0.47 at the fifth").
        if (world.size() == 1) readout.apexBounce = run.restitution().latestNumber();
        readout.betaSquared = run.params().beta * run.params().beta;
        readout.work = workOf(run);
        views.push_back(std::move(readout));
    }
    return views;
}

}  // namespace app
