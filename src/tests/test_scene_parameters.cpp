// The parameter table: one name, range, default and tooltip per lecture parameter,
// read by the UI, the command line's --set and the JSON loader.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/overrides.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace {

using scenes::applySetting;
using scenes::Parameter;
using scenes::ParameterKind;
using scenes::Scene;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

Scene sceneWithGenerators() {
    Scene scene;
    scenes::Generator g;
    g.count = 50;
    scene.generators = {g, g};
    scene.emitters = {scenes::Emitter{}, scenes::Emitter{}};
    return scene;
}

TEST(ParameterTable, HasTheLectureParametersOnceEach) {
    std::set<std::string> names;
    for (const Parameter& p : scenes::parameterTable()) names.insert(std::string(p.name));
    EXPECT_EQ(names.size(), scenes::parameterTable().size());
    const std::set<std::string> expected = {
        "alpha",  "beta",     "epsilon", "mu",    "h",          "substeps", "passes", "gravity",
        "method", "response", "split",   "order", "broadphase", "emit_period", "count", "radius",
        "seed",   "threads",  "toi",     "max_events", "solver", "shock"};
    EXPECT_EQ(names, expected);
}

TEST(ParameterTable, EveryDefaultLiesInItsRange) {
    for (const Parameter& p : scenes::parameterTable()) {
        SCOPED_TRACE(std::string(p.name));
        EXPECT_LE(p.min, p.defaultValue);
        EXPECT_LE(p.defaultValue, p.max);
        EXPECT_LT(p.min, p.max);
        EXPECT_EQ(scenes::checkValue(p, p.defaultValue), "");
        EXPECT_FALSE(p.label.empty());
        EXPECT_FALSE(p.tooltip.empty());
        ASSERT_NE(p.get, nullptr);
        ASSERT_NE(p.set, nullptr);
        if (p.kind == ParameterKind::Choice) {
            EXPECT_EQ(p.max, static_cast<double>(p.choices.size()) - 1.0);
        }
    }
}

TEST(ParameterTable, LiveDefaultsAreThoseOfADefaultScene) {
    const Scene scene;
    for (const Parameter& p : scenes::parameterTable()) {
        if (p.applies != scenes::Applies::Live) continue;
        SCOPED_TRACE(std::string(p.name));
        EXPECT_EQ(p.get(scene), p.defaultValue);
    }
    EXPECT_EQ(scenes::findParameter("gravity")->defaultValue, 9.81);
    EXPECT_EQ(scenes::findParameter("h")->defaultValue, 1.0 / 60.0);
}

TEST(ParameterTable, RangesAreTheLecturesAndApplyAsDocumented) {
    const Parameter* h = scenes::findParameter("h");
    ASSERT_NE(h, nullptr);
    EXPECT_EQ(h->min, 1e-4);
    EXPECT_EQ(h->max, 0.1);
    EXPECT_EQ(h->unit, "s");
    EXPECT_EQ(scenes::findParameter("epsilon")->unit, "m/s");
    EXPECT_EQ(scenes::findParameter("epsilon")->max, 10.0);
    EXPECT_EQ(scenes::findParameter("substeps")->max, 64.0);
    EXPECT_EQ(scenes::findParameter("passes")->max, 100.0);
    EXPECT_EQ(scenes::findParameter("gravity")->max, 50.0);
    EXPECT_EQ(scenes::findParameter("count")->applies, scenes::Applies::Restart);
    EXPECT_EQ(scenes::findParameter("radius")->applies, scenes::Applies::Restart);
    EXPECT_EQ(scenes::findParameter("seed")->applies, scenes::Applies::Restart);
    EXPECT_EQ(scenes::findParameter("mu")->applies, scenes::Applies::Live);
    EXPECT_TRUE(contains(std::string(scenes::findParameter("mu")->tooltip), "not Coulomb"));
    EXPECT_TRUE(
        contains(std::string(scenes::findParameter("epsilon")->tooltip), "|g| h / substeps"));
    EXPECT_EQ(scenes::findParameter("nope"), nullptr);
}

// threads = 0 is "one per core", not "no threads": the slider says so.
TEST(ParameterTable, ZeroIsNamedWhereItMeansAutomatic) {
    EXPECT_EQ(scenes::findParameter("threads")->zeroMeans, "auto");
    EXPECT_EQ(scenes::findParameter("count")->zeroMeans, "");  // 0 spheres is none
    for (const Parameter& p : scenes::parameterTable()) {
        if (!p.zeroMeans.empty()) {
            EXPECT_EQ(p.kind, ParameterKind::Integer) << p.name;
            EXPECT_EQ(p.min, 0.0) << p.name;
            EXPECT_EQ(p.zeroMeans.find('%'), std::string_view::npos) << p.name << ": a printf format";
        }
    }
}

TEST(ApplySetting, AcceptsGoodValuesAndChangesTheScene) {
    Scene scene = sceneWithGenerators();
    EXPECT_EQ(applySetting(scene, "alpha=0.25"), "");
    EXPECT_EQ(scene.params.alpha, 0.25);
    EXPECT_EQ(applySetting(scene, " beta = 0.5 "), "");
    EXPECT_EQ(scene.params.beta, 0.5);
    EXPECT_EQ(applySetting(scene, "h=0.001"), "");
    EXPECT_EQ(scene.params.timeStep, 0.001);
    EXPECT_EQ(applySetting(scene, "substeps=8"), "");
    EXPECT_EQ(scene.params.substeps, 8);
    EXPECT_EQ(applySetting(scene, "gravity=3.5"), "");
    EXPECT_EQ(scene.params.gravity, glm::dvec3(0.0, 0.0, -3.5));
    EXPECT_EQ(applySetting(scene, "method=velocity"), "");
    EXPECT_EQ(scene.params.method, physics::Method::VelocityBased);
    EXPECT_EQ(applySetting(scene, "response=momentum"), "");
    EXPECT_EQ(scene.params.response, physics::ResponseModel::MomentumConserving);
    EXPECT_EQ(applySetting(scene, "split=mass"), "");
    EXPECT_EQ(scene.params.split, physics::PositionSplit::MassWeighted);
    EXPECT_EQ(applySetting(scene, "order=shuffled"), "");
    EXPECT_EQ(scene.params.order, physics::PairOrder::Shuffled);
    EXPECT_EQ(applySetting(scene, "broadphase=allpairs"), "");
    EXPECT_EQ(scene.params.broadPhase, physics::BroadPhase::AllPairs);
    EXPECT_EQ(applySetting(scene, "count=500"), "");
    EXPECT_EQ(scene.generators[0].count, 500);
    EXPECT_EQ(scene.generators[1].count, 50);
    EXPECT_EQ(applySetting(scene, "radius=0.03"), "");
    EXPECT_EQ(scene.generators[1].radiusMin, 0.03);
    EXPECT_EQ(scene.generators[1].radiusMax, 0.03);
    EXPECT_EQ(applySetting(scene, "seed=42"), "");
    EXPECT_EQ(scene.seed, 42u);
    EXPECT_EQ(applySetting(scene, "emit_period=0.25"), "");  // the first emitter only
    EXPECT_EQ(scene.emitters[0].period, 0.25);
    EXPECT_EQ(scene.emitters[1].period, scenes::Emitter{}.period);
}

TEST(ApplySetting, RefusesOutOfRangeWithTheRange) {
    Scene scene;
    EXPECT_EQ(applySetting(scene, "beta=1.5"), "beta = 1.5 is out of range [0, 1]");
    EXPECT_EQ(applySetting(scene, "h=0"), "h = 0 is out of range [0.0001, 0.1] s");
    EXPECT_EQ(applySetting(scene, "epsilon=-1"), "epsilon = -1 is out of range [0, 10] m/s");
    EXPECT_EQ(applySetting(scene, "passes=0"), "passes = 0 is out of range [1, 100]");
    EXPECT_EQ(applySetting(scene, "substeps=2.5"), "substeps = 2.5 must be a whole number");
    EXPECT_EQ(scene.params.beta, physics::Params{}.beta);  // unchanged on error
    EXPECT_EQ(scene.params.timeStep, physics::Params{}.timeStep);
}

TEST(ApplySetting, RefusesUnknownNamesWithCloseAndValidNames) {
    Scene scene;
    const std::string typo = applySetting(scene, "alpah=0.5");
    EXPECT_TRUE(contains(typo, "unknown parameter 'alpah'")) << typo;
    EXPECT_TRUE(contains(typo, "did you mean 'alpha'?")) << typo;
    EXPECT_TRUE(contains(typo, "alpha, beta, epsilon, mu, h")) << typo;
    const std::string far = applySetting(scene, "friction=0.5");
    EXPECT_TRUE(contains(far, "unknown parameter 'friction'")) << far;
    EXPECT_FALSE(contains(far, "did you mean")) << far;
    EXPECT_EQ(applySetting(scene, "alpha"), "expected name=value, got 'alpha'");
}

TEST(ApplySetting, RefusesValuesThatAreNotNumbersOrChoices) {
    Scene scene;
    EXPECT_EQ(applySetting(scene, "alpha=abc"), "value 'abc' for alpha is not a number");
    EXPECT_EQ(applySetting(scene, "alpha=0.5x"), "value '0.5x' for alpha is not a number");
    EXPECT_EQ(applySetting(scene, "alpha="), "value '' for alpha is not a number");
    EXPECT_EQ(applySetting(scene, "alpha=0,5"), "value '0,5' for alpha is not a number: write decimals with a point (0.5, not 0,5)");
    EXPECT_EQ(applySetting(scene, "alpha=nan"), "value 'nan' for alpha is not a number");
    EXPECT_EQ(applySetting(scene, "h=1e400"), "value '1e400' for h is beyond what a number can hold (about 1e-308 to 1e308)");
    // The seed's largest is 2^53; one more read as the nearest double was 2^53 again.
    EXPECT_EQ(applySetting(scene, "seed=9007199254740992"), "");
    EXPECT_EQ(applySetting(scene, "seed=9007199254740993"), "seed = 9007199254740993 is out of range [0, 9007199254740992]");
    EXPECT_EQ(applySetting(scene, "seed=18446744073709551615"),  // past a long long: as written, not ...616
              "seed = 18446744073709551615 is out of range [0, 9007199254740992]");
    EXPECT_EQ(applySetting(scene, "gravity=inf"), "value 'inf' for gravity is not a number");
    EXPECT_EQ(applySetting(scene, "method=fast"),
              "method = 'fast' is not a choice; choices: position, velocity, response-only, reflection, continuous");
    EXPECT_EQ(applySetting(scene, "order=2"),
              "order = '2' is not a choice; choices: index, reversed, shuffled, colored");
    EXPECT_EQ(scene.params.alpha, physics::Params{}.alpha);
}

// The texts write h as a fraction ("lower h to 1/240 s"); --set, links and a slider's
// Ctrl+click take it so, and refuse what only starts like a number (ImGui's own reading of
// a typed "1/2" for beta kept the 1).
TEST(ApplySetting, TakesAFractionAsTheTextsWriteIt) {
    Scene scene;
    EXPECT_EQ(applySetting(scene, "h=1/240"), "");
    EXPECT_EQ(scene.params.timeStep, 1.0 / 240.0);
    EXPECT_EQ(applySetting(scene, "beta = 1 / 2 "), "");
    EXPECT_EQ(scene.params.beta, 0.5);
    EXPECT_EQ(applySetting(scene, "beta=3/2"), "beta = 1.5 is out of range [0, 1]");
    EXPECT_EQ(applySetting(scene, "substeps=9/2"), "substeps = 4.5 must be a whole number");
    EXPECT_EQ(applySetting(scene, "h=1/0"), "value '1/0' for h divides by zero or overflows");
    EXPECT_EQ(applySetting(scene, "h=1e300/1e-300"), "value '1e300/1e-300' for h divides by zero or overflows");
    EXPECT_EQ(applySetting(scene, "h=1e309/1e300"),
              "value '1e309/1e300' for h is beyond what a number can hold (about 1e-308 to 1e308)");
    EXPECT_EQ(applySetting(scene, "seed=9007199254740993/1"), "seed = 9007199254740993 is out of range [0, 9007199254740992]");
    EXPECT_EQ(applySetting(scene, "h=nan/1"), "value 'nan/1' for h is not a number (a decimal, or a fraction such as 1/240)");
    EXPECT_EQ(applySetting(scene, "beta=0,5/2"),
              "value '0,5/2' for beta is not a number: write decimals with a point (0.5, not 0,5)");
    const std::string notANumber = " is not a number (a decimal, or a fraction such as 1/240)";
    EXPECT_EQ(applySetting(scene, "beta=1/2x"), "value '1/2x' for beta" + notANumber);
    EXPECT_EQ(applySetting(scene, "beta=1/2/3"), "value '1/2/3' for beta" + notANumber);
    EXPECT_EQ(applySetting(scene, "beta=/2"), "value '/2' for beta" + notANumber);
    EXPECT_EQ(applySetting(scene, "beta=1/"), "value '1/' for beta" + notANumber);
    EXPECT_EQ(scene.params.beta, 0.5);  // unchanged by the refusals
    scenes::Parameter const* beta = scenes::findParameter("beta");
    double value = 0.0;
    EXPECT_EQ(scenes::parseValue(*beta, "11/20", value), "");  // a slider's typed text, read alike
    EXPECT_EQ(value, 0.55);
    EXPECT_EQ(applySetting(scene, "threads=2"), "");
    EXPECT_EQ(applySetting(scene, "threads=auto"), "");  // what its slider shows for 0
    EXPECT_EQ(scene.params.threads, 0);
}

// h is shown as the texts write it where it is 1/N (the slider read 0.01667 for 1/60); the
// other numbers, and an h that is no such fraction, as decimals.
TEST(ParameterTable, TheTimeStepIsShownAsTheFractionItIs) {
    const scenes::Parameter& h = *scenes::findParameter("h");
    EXPECT_EQ(scenes::fractionShown(h, 1.0 / 60.0), "1/60");
    EXPECT_EQ(scenes::fractionShown(h, 1.0 / 240.0), "1/240");
    EXPECT_EQ(scenes::fractionShown(h, 0.001), "1/1000");
    EXPECT_EQ(scenes::fractionShown(h, 0.01667), "");
    EXPECT_EQ(scenes::fractionShown(h, 0.0015), "");
    EXPECT_EQ(scenes::fractionShown(*scenes::findParameter("beta"), 0.5), "") << "only h";
    double typed = 0.0;
    ASSERT_EQ(scenes::parseValue(h, scenes::fractionShown(h, 1.0 / 240.0), typed), "");
    EXPECT_EQ(typed, 1.0 / 240.0) << "what is shown reads back as the same h";
}

TEST(ApplySetting, RestartParametersNeedGeneratedSpheres) {
    Scene scene;
    EXPECT_EQ(applySetting(scene, "count=10"), "scene has no generated spheres");
    EXPECT_EQ(applySetting(scene, "radius=0.1"), "scene has no generated spheres");
    EXPECT_EQ(applySetting(scene, "emit_period=1"), "scene has no emitter");
    EXPECT_EQ(applySetting(scene, "emit_period=0"), "emit_period = 0 is out of range [0.01, 60] s");
    EXPECT_EQ(applySetting(scene, "count=-1"), "count = -1 is out of range [0, 1000000]");
    EXPECT_EQ(applySetting(scene, "seed=-3"), "seed = -3 is out of range [0, 9007199254740992]");
}

TEST(FormatValue, ReadsBackThroughApplySetting) {
    Scene scene = sceneWithGenerators();
    scene.params.timeStep = 1.0 / 240.0;
    scene.params.alpha = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
    scene.params.method = physics::Method::VelocityBased;
    scene.seed = 123456789;
    EXPECT_EQ(scenes::formatValue(*scenes::findParameter("method"), scene), "velocity");
    EXPECT_EQ(scenes::formatValue(*scenes::findParameter("alpha"), scene), "0.30000000000000004");
    EXPECT_EQ(scenes::formatValue(*scenes::findParameter("substeps"), scene), "4");
    EXPECT_EQ(scenes::formatValue(*scenes::findParameter("seed"), scene), "123456789");
    for (const Parameter& p : scenes::parameterTable()) {
        SCOPED_TRACE(std::string(p.name));
        Scene copy = scene;
        const std::string text = scenes::formatValue(p, scene);
        EXPECT_EQ(applySetting(copy, std::string(p.name) + "=" + text), "");
        EXPECT_EQ(p.get(copy), p.get(scene));
    }
}

}  // namespace

namespace {

// Found by the fuzzer (src/tests/fuzz): a setting with a newline in it was quoted back
// over two lines. The answer is one line, the control character shown as \x0a.
TEST(ParameterSettings, ARefusalIsOneLineWhateverTheInputHolds) {
    scenes::Scene scene;
    const std::string error = scenes::applySetting(scene, "sp\nspl");
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_NE(error.find("sp\\x0aspl"), std::string::npos) << error;
}

}  // namespace

// The README's parameter table is the one table's: a row per parameter, its range and when
// it applies, and a meaning that quotes the start of the panel's tooltip (ten of its rows
// had drifted from the tooltips, the threads one by a whole design).
TEST(ParameterTable, TheReadmesRowsQuoteTheTable) {
    std::ifstream file(scenes::assetDirectory() + "/../README.md");
    const std::string readme{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    const std::size_t start = readme.find("\n| name | symbol / label |");
    ASSERT_NE(start, std::string::npos);
    std::set<std::string> rows;
    std::istringstream lines(readme.substr(start + 1, readme.find("\n\n", start + 1) - start - 1));
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("| `", 0) != 0) continue;
        std::vector<std::string> cells;  // split at " | " (a "\|" inside a cell is its text)
        for (std::size_t at = 2; at < line.size();) {
            const std::size_t end = line.find(" | ", at);
            cells.push_back(line.substr(at, (end == std::string::npos ? line.size() - 2 : end) - at));
            at = end == std::string::npos ? line.size() : end + 3;
        }
        ASSERT_EQ(cells.size(), 7u) << line;
        const std::string name = cells[0].substr(1, cells[0].size() - 2);
        const scenes::Parameter* p = scenes::findParameter(name);
        ASSERT_NE(p, nullptr) << name;
        rows.insert(name);
        std::string range;
        if (p->kind == scenes::ParameterKind::Choice) {
            for (const std::string_view choice : p->choices) range += (range.empty() ? "`" : " / `") + std::string(choice) + "`";
        } else {
            range = scenes::formatNumber(p->min) + " \u2013 " + scenes::formatNumber(p->max);
        }
        EXPECT_EQ(cells[3], range) << name;
        EXPECT_EQ(cells[5], p->applies == scenes::Applies::Live ? "live" : "restart") << name;
        // The default: the value a scene file that leaves it out runs with (for a Live one, a
        // default Scene's), as the table holds it; "1/60 (0.01667)" says it as a fraction too.
        if (cells[4] == "the file's (required)") {
            EXPECT_NE(p->available, nullptr) << name << ": only a thing of some scenes (an emitter) is the file's";
        } else if (p->kind == scenes::ParameterKind::Choice) {
            EXPECT_EQ(cells[4], std::string(p->choices.at(std::size_t(p->defaultValue)))) << name;
        } else {
            const std::size_t open = cells[4].find('(');
            const double written = std::stod(open == std::string::npos ? cells[4] : cells[4].substr(open + 1));
            EXPECT_NEAR(written, p->defaultValue, 1e-3 * std::abs(p->defaultValue)) << name << ": " << cells[4];
        }
        if (p->applies == scenes::Applies::Live && p->availableIn(scenes::Scene{})) {
            EXPECT_EQ(p->get(scenes::Scene{}), p->defaultValue) << name << ": a default scene's";
        }
        std::string meaning = cells[6];
        for (std::size_t bar = meaning.find("\\|"); bar != std::string::npos; bar = meaning.find("\\|", bar)) {
            meaning.erase(bar, 1);
        }
        EXPECT_FALSE(meaning.empty()) << name;
        EXPECT_EQ(std::string(p->tooltip).substr(0, meaning.size()), meaning) << name;
        EXPECT_EQ(meaning.back(), '.') << name << ": whole sentences";
    }
    EXPECT_EQ(rows.size(), scenes::parameterTable().size());
}

// A setting of a parameter the run's method has no use for (toi under the velocity method)
// was accepted and did nothing; it is refused once every setting is in, whatever their order.
TEST(ParameterTable, ASettingThatActsOnNothingIsRefusedWhateverTheOrder) {
    const scenes::Scene cradle = scenes::loadScene(scenes::presetPath("08_newtons_cradle"));  // velocity based
    const auto refusal = [&](const std::vector<std::string>& settings) {
        scenes::Scene scene = cradle;
        for (const std::string& setting : settings) EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
        return scenes::settingsThatActOnNothing(scene, settings);
    };
    EXPECT_EQ(refusal({"toi=bisection"}),
              "toi=bisection: toi acts only with the continuous method, and this run's is velocity");
    EXPECT_EQ(refusal({"toi=bisection", "method=continuous"}), "");
    EXPECT_EQ(refusal({"method=continuous", "max_events=7"}), "");
    EXPECT_EQ(refusal({"method=continuous", "shock=on"}),
              "shock=on: shock acts only with the position, velocity or reflection method, and this run's is continuous");
    EXPECT_EQ(refusal({"shock=on", "beta=0.5"}), "");
}

// The presentation layout keeps the sliders a scene's text tells the class to move, the
// settings its views differ in first: at 1024x768 only the first fit, and 21 had kept μ (a
// claim sets it, and μ comes first in the table), scrolling away its lesson's K and shock.
TEST(PresentedSliders, WhatTheViewsDifferInComesFirst) {
    const auto sliders = [](const char* preset) { return scenes::slidersToMove(scenes::loadScene(scenes::presetPath(preset))); };
    const std::vector<std::string> column = sliders("21_shock_column");
    ASSERT_GE(column.size(), 3u);
    EXPECT_EQ(std::vector<std::string>(column.begin(), column.begin() + 2), (std::vector<std::string>{"passes", "shock"}));
    EXPECT_NE(std::find(column.begin(), column.end(), "mu"), column.end()) << "a claim's μ stays, after them";
    const std::vector<std::string> bounce = sliders("02_bounce_projection");  // no views side by side: the table's order
    ASSERT_FALSE(bounce.empty());
    EXPECT_EQ(bounce.front(), "beta");
}
