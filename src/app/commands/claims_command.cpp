#include "app/commands/claims_command.h"

#include <cstdio>

#include "app/run/scene_source.h"
#include "platform/whole_file.h"
#include "scenes/claims.h"
#include "scenes/presets.h"

namespace app {
namespace {

// " (with beta=0.5, mu=1)" for a claim about the scene with other settings; "" for its own.
std::string withSettings(const std::vector<std::string>& settings) {
    std::string text;
    for (const std::string& setting : settings) text += (text.empty() ? " (with " : ", ") + setting;
    return text.empty() ? text : text + ")";
}

// Text for XML: & < > " ' as entities.
std::string xmlEscaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

// One scene's claims as the report keeps them: its name, then per claim the case's name
// (the quote and its settings), whether it held and what was measured.
struct SceneReport {
    std::string name;
    struct Case {
        std::string name, measured;
        bool holds = false;
    };
    std::vector<Case> cases;
};

// JUnit XML, as CI systems read test reports: a test suite per scene, a test case per
// claim, a failure where it did not hold (its message what was measured).
std::string junitReport(const std::vector<SceneReport>& reports) {
    int tests = 0, failures = 0;
    std::string suites;
    for (const SceneReport& scene : reports) {
        int failed = 0;
        std::string cases;
        for (const SceneReport::Case& c : scene.cases) {
            cases += "    <testcase classname=\"" + xmlEscaped(scene.name) + "\" name=\"" + xmlEscaped(c.name) + "\"";
            if (c.holds) {
                cases += "><system-out>" + xmlEscaped(c.measured) + "</system-out></testcase>\n";
            } else {
                cases += "><failure message=\"" + xmlEscaped(c.measured) + "\"/></testcase>\n";
                ++failed;
            }
        }
        suites += "  <testsuite name=\"" + xmlEscaped(scene.name) + "\" tests=\"" + std::to_string(scene.cases.size()) +
                  "\" failures=\"" + std::to_string(failed) + "\">\n" + cases + "  </testsuite>\n";
        tests += int(scene.cases.size());
        failures += failed;
    }
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"spheres claims\" tests=\"" +
           std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\">\n" + suites + "</testsuites>\n";
}

}  // namespace

namespace {

// What a claim may measure, for a teacher writing one: name, unit, meaning.
int listMeasures() {
    for (const scenes::ClaimMeter& m : scenes::claimMeters()) {
        const std::string unit = m.unit.empty() ? "" : m.unit.front() == '(' ? " " + std::string(m.unit) : " (" + std::string(m.unit) + ")";
        std::printf("%s%s: %s\n", std::string(m.name).c_str(), unit.c_str(), std::string(m.what).c_str());
    }
    return 0;
}

}  // namespace

int runClaims(const ClaimsOptions& options) {
    if (options.measures) return listMeasures();
    const std::vector<std::string> names = options.scenes.empty() ? scenes::listPresets() : options.scenes;
    checkWritable("--junit", options.junit, ".xml");  // before the runs: a bad path is said at once
    std::vector<scenes::Scene> loaded;  // all loaded first: a bad name ends the command before any run
    for (const std::string& name : names) loaded.push_back(loadSceneWithSettings(name, {}));
    int held = 0, failed = 0;
    std::vector<std::string> failures;  // repeated at the end: a long log's ✗ lines are far above it
    std::vector<SceneReport> reports;
    for (std::size_t k = 0; k < names.size(); ++k) {
        const scenes::Scene& scene = loaded[k];
        reports.push_back({names[k], {}});
        std::printf("%s  %s\n", names[k].c_str(), scene.title.c_str());
        if (scene.claims.empty()) std::printf("  (its text claims nothing a run can measure)\n");
        for (const scenes::ClaimCheck& check : scenes::checkClaims(scene)) {
            std::printf("  %s \"%s\"%s: %s\n", check.holds ? "\u2713" : "\u2717",
                        scenes::withCount(check.claim->says, scene).c_str(),
                        withSettings(check.claim->settings).c_str(), check.measured.c_str());
            (check.holds ? held : failed) += 1;
            reports.back().cases.push_back({scenes::withCount(check.claim->says, scene) + withSettings(check.claim->settings),
                                            check.measured, check.holds});
            if (!check.holds) failures.push_back(names[k] + ": \"" + scenes::withCount(check.claim->says, scene) + "\"");
        }
        std::fflush(stdout);
    }
    if (!failures.empty()) std::printf("Failed:\n");
    for (const std::string& failure : failures) std::printf("  \u2717 %s\n", failure.c_str());
    std::printf("The text, measured: %d \u2713 %d \u2717 of %d claims in %zu scene%s\n", held, failed, held + failed,
                names.size(), names.size() == 1 ? "" : "s");
    if (!options.junit.empty() && !platform::writeWholeFile(options.junit, junitReport(reports))) {
        throw UsageError("--junit " + options.junit + ": cannot be written whole (is the disk full?)");
    }
    return failed == 0 ? 0 : 1;
}

}  // namespace app
