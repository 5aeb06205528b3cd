// The lab sheet: every claim a preset's text (or its row of the README's teaching
// table) makes is data in the preset (scenes/claims.h), and this test runs them all, as
// `spheres claims` does (tested at the end).
// A text changed without its claim, or physics that no longer does what the text
// says, fails here. The texts are also checked for claims nobody backs: every number
// and every sentence of a description, and every clause of a teaching-table row, lies
// in the quote of some claim.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "scenes/claims.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace {

using scenes::Claim;
using scenes::ClaimSource;
using scenes::Scene;

std::string readFile(const std::string& path) {
    std::ifstream file(path);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// The README's teaching table: its rows, each "| lecture | presets | what to look at |".
std::vector<std::string> teachingRows() {
    const std::string readme = readFile(scenes::assetDirectory() + "/../README.md");
    const std::size_t start = readme.find("## What the demo teaches");
    const std::size_t end = readme.find("\n## ", start + 1);
    std::vector<std::string> rows;
    std::size_t at = readme.find("\n|", start);
    while (at != std::string::npos && at < end) {
        const std::size_t eol = readme.find('\n', at + 1);
        const std::string row = readme.substr(at + 1, eol - at - 1);
        if (row.rfind("|---", 0) != 0 && row.find("| lecture") != 0) rows.push_back(row);
        at = readme.find("\n|", eol);
    }
    return rows;
}

bool namesAPreset(const std::string& row) {
    for (const std::string& name : scenes::listPresets()) {
        if (row.find("`" + name + "`") != std::string::npos) return true;
    }
    return false;
}

// The rows a preset's README claims may quote: those naming it, and those naming none ("any").
std::vector<std::string> rowsOf(const std::string& name) {
    std::vector<std::string> out;
    for (const std::string& row : teachingRows()) {
        if (row.find("`" + name + "`") != std::string::npos || !namesAPreset(row)) out.push_back(row);
    }
    return out;
}

// The spans [begin, end) of `text` that the claims from `source` quote.
std::vector<std::pair<std::size_t, std::size_t>> quotedSpans(const std::string& text, const Scene& scene,
                                                             ClaimSource source) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    for (const Claim& c : scene.claims) {
        if (c.in != source) continue;
        for (std::size_t at = text.find(c.says); at != std::string::npos; at = text.find(c.says, at + 1)) {
            spans.emplace_back(at, at + c.says.size());
        }
    }
    return spans;
}

bool covered(const std::vector<std::pair<std::size_t, std::size_t>>& spans, std::size_t begin, std::size_t end) {
    for (const auto& [b, e] : spans) {
        if (b <= begin && end <= e) return true;
    }
    return false;
}

bool overlapsAQuote(const std::vector<std::pair<std::size_t, std::size_t>>& spans, std::size_t begin,
                    std::size_t end) {
    for (const auto& [b, e] : spans) {
        if (b < end && begin < e) return true;
    }
    return false;
}

class LabSheet : public testing::TestWithParam<std::string> {};

TEST_P(LabSheet, EveryClaimOfThePresetHolds) {
    const Scene scene = scenes::loadScene(scenes::presetPath(GetParam()));
    ASSERT_FALSE(scene.claims.empty()) << "a preset without claims";
    const std::vector<std::string> rows = rowsOf(GetParam());
    for (const scenes::ClaimCheck& check : scenes::checkClaims(scene)) {
        const Claim& c = *check.claim;
        std::cout << "  " << (check.holds ? "holds " : "FAILS ") << "\"" << c.says << "\": " << check.measured << "\n";
        EXPECT_TRUE(check.holds) << "\"" << c.says << "\" (" << c.measure << "): " << check.measured;
        if (c.in == ClaimSource::Description) {
            EXPECT_NE(scene.description.find(c.says), std::string::npos) << "not in the text: " << c.says;
        } else {
            const bool quoted = std::any_of(rows.begin(), rows.end(),
                                            [&](const std::string& row) { return row.find(c.says) != std::string::npos; });
            EXPECT_TRUE(quoted) << "not in the preset's README row: " << c.says;
        }
    }
}

// Every number of the description is inside a claim's quote (slide references aside).
TEST_P(LabSheet, EveryNumberOfTheTextIsInAClaim) {
    const Scene scene = scenes::loadScene(scenes::presetPath(GetParam()));
    const std::string& text = scene.description;
    const auto spans = quotedSpans(text, scene, ClaimSource::Description);
    std::vector<std::pair<std::size_t, std::size_t>> references;
    const std::regex reference("[Ss]lides? [0-9]+(–[0-9]+)?|option [0-9]+");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), reference); it != std::sregex_iterator(); ++it) {
        references.emplace_back(it->position(), it->position() + it->length());
    }
    const std::regex number("[0-9]+([.,/][0-9]+)*");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
        const std::size_t b = static_cast<std::size_t>(it->position()), e = b + static_cast<std::size_t>(it->length());
        if (covered(references, b, e)) continue;
        EXPECT_TRUE(covered(spans, b, e)) << "no claim quotes \"" << it->str() << "\" in: ..."
                                          << text.substr(b > 40 ? b - 40 : 0, 80) << "...";
    }
}

// Every sentence of the description quotes at least one claim.
TEST_P(LabSheet, EverySentenceOfTheTextHasAClaim) {
    const Scene scene = scenes::loadScene(scenes::presetPath(GetParam()));
    const std::string& text = scene.description;
    const auto spans = quotedSpans(text, scene, ClaimSource::Description);
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find(". ", begin);
        end = end == std::string::npos ? text.size() : end + 1;
        EXPECT_TRUE(overlapsAQuote(spans, begin, end)) << "no claim in: " << text.substr(begin, end - begin);
        begin = end + 1;
    }
}

INSTANTIATE_TEST_SUITE_P(Presets, LabSheet, testing::ValuesIn(scenes::listPresets()),
                         [](const testing::TestParamInfo<std::string>& param) { return param.param; });

// Every clause ("; ") of the README teaching table's third column quotes a claim of a
// preset of its row (the claim with "in": "README").
TEST(LabSheetReadme, EveryClauseOfTheTeachingTableIsAClaim) {
    std::vector<Scene> presets;
    for (const std::string& name : scenes::listPresets()) presets.push_back(scenes::loadScene(scenes::presetPath(name)));
    const std::vector<std::string> rows = teachingRows();
    ASSERT_GE(rows.size(), 8u);
    for (const std::string& row : rows) {
        const std::size_t cell = row.rfind("| ", row.size() - 3);
        const std::string what = row.substr(cell + 2, row.size() - cell - 4);
        std::vector<std::pair<std::size_t, std::size_t>> spans;
        for (const Scene& scene : presets) {
            for (const auto& span : quotedSpans(row, scene, ClaimSource::Readme)) spans.push_back(span);
        }
        std::size_t begin = cell + 2;
        for (std::size_t end; begin < cell + 2 + what.size(); begin = end + 2) {
            end = row.find("; ", begin);
            if (end == std::string::npos || end > cell + 2 + what.size()) end = cell + 2 + what.size();
            EXPECT_TRUE(overlapsAQuote(spans, begin, end)) << "no claim in: " << row.substr(begin, end - begin);
        }
    }
}

}  // namespace

namespace {

// What `spheres ARGUMENTS` prints (stdout and stderr) and its exit code.
std::pair<std::string, int> runSpheres(const std::string& arguments) {
    const std::string command = std::string("'") + SPHERES_EXECUTABLE + "' " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    char buffer[512];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    const int status = pipe ? pclose(pipe) : -1;
    return {output, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

int countOf(const std::string& text, const std::string& part) {
    int count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

}  // namespace

// `spheres claims --scene NAME` measures the preset's claims as the lab sheet does: one
// line each (✓, the quote, what was measured), then the count; exit 0.
TEST(ClaimsCommandLine, MeasuresEachClaimOfAPresetAsTheLabSheetDoes) {
    const std::size_t claims = scenes::checkClaims(scenes::loadScene(scenes::presetPath("03_head_on"))).size();
    const auto [output, code] = runSpheres("claims --scene head_on");
    EXPECT_EQ(code, 0) << output;
    EXPECT_EQ(countOf(output, "  \u2713 \""), int(claims)) << output;
    EXPECT_EQ(countOf(output, "\u2717 \""), 0) << output;
    EXPECT_NE(output.find("  \u2713 \"the other leaves at 1 m/s\": vx of sphere #1 over t = 0.9\u20131.2 s = 1"), std::string::npos) << output;
    EXPECT_NE(output.find("\"Lower \u03b2 to see the lecture's attenuation v1 \u2190 \u03b1 v1\u2225 + \u03b2 v2\u22a5\" (with beta=0.5)"),
              std::string::npos) << output;
    const std::string total = std::to_string(claims);
    EXPECT_NE(output.find("The text, measured: " + total + " \u2713 0 \u2717 of " + total + " claims in 1 scene\n"),
              std::string::npos) << output;
}

// A teacher's scene file whose text claims what the run does not do: its claim is marked ✗
// with what was measured instead, and the command exits 1. A scene that cannot be found:
// one line, exit 2.
TEST(ClaimsCommandLine, AClaimThatFailsIsMarkedAndTheExitCodeSaysSo) {
    std::ifstream preset(scenes::presetPath("03_head_on"));
    std::string text((std::istreambuf_iterator<char>(preset)), std::istreambuf_iterator<char>());
    const std::string claim = R"({"says": "the other leaves at 1 m/s", "measure": "vx", "sphere": 1, "from": 0.9, "to": 1.2, "near": 1,)";
    const std::size_t at = text.find(claim);
    ASSERT_NE(at, std::string::npos) << "the preset's claim changed: update this test";
    text.replace(at, claim.size(), R"({"says": "the other leaves at 1 m/s", "measure": "vx", "sphere": 1, "from": 0.9, "to": 1.2, "near": 2,)");
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "spheres_claims_false.json";
    std::ofstream(file) << text;
    const auto [output, code] = runSpheres("claims --scene '" + file.string() + "'");
    EXPECT_EQ(code, 1) << output;
    EXPECT_NE(output.find("  \u2717 \"the other leaves at 1 m/s\": vx of sphere #1 over t = 0.9\u20131.2 s = 1 m/s (19 samples), expected 2"), std::string::npos) << output;
    EXPECT_NE(output.find(" 1 \u2717 of "), std::string::npos) << output;
    // Repeated after the count with its scene: in a long log the ✗ line is far above.
    EXPECT_NE(output.find("Failed:\n  \u2717 " + file.string() + ": \"the other leaves at 1 m/s\"\n"), std::string::npos) << output;
    // The same as a JUnit report, for a course's CI: a test case per claim, the failed one
    // with what was measured; written whole, and a path it cannot write refused before the runs.
    const std::filesystem::path report = std::filesystem::temp_directory_path() / "spheres_claims_report.xml";
    std::filesystem::remove(report);
    const auto [reported, reportCode] = runSpheres("claims --scene '" + file.string() + "' --junit '" + report.string() + "'");
    EXPECT_EQ(reportCode, 1) << reported;
    std::ifstream xml(report);
    const std::string junit((std::istreambuf_iterator<char>(xml)), std::istreambuf_iterator<char>());
    const std::size_t cases = scenes::checkClaims(scenes::loadScene(file.string())).size();
    EXPECT_EQ(countOf(junit, "<testcase "), int(cases)) << junit;
    EXPECT_EQ(countOf(junit, "<failure "), 1) << junit;
    EXPECT_NE(junit.find("<testsuites name=\"spheres claims\" tests=\"" + std::to_string(cases) + "\" failures=\"1\">"),
              std::string::npos) << junit;
    EXPECT_NE(junit.find("name=\"the other leaves at 1 m/s\"><failure message=\"vx of sphere #1 over t = 0.9\u20131.2 s = 1 m/s"),
              std::string::npos) << junit;
    EXPECT_NE(junit.find("name=\"Lower \u03b2 to see the lecture&apos;s attenuation"), std::string::npos) << "escaped: " << junit;
    const auto [unwritable, unwritableCode] = runSpheres("claims --scene head_on --junit /no/such/folder/report.xml");
    EXPECT_EQ(unwritableCode, 2) << unwritable;
    EXPECT_EQ(countOf(unwritable, "\n"), 1) << unwritable;
    EXPECT_EQ(countOf(unwritable, "\u2713"), 0) << "refused before the runs: " << unwritable;
    std::filesystem::remove(report);
    std::filesystem::remove(file);
    // What a claim may measure, for a teacher writing one.
    const auto [measures, listed] = runSpheres("claims --measures");
    EXPECT_EQ(listed, 0) << measures;
    EXPECT_NE(measures.find("\npenetration (r): the penetration readout: deepest overlap / smaller radius\n"), std::string::npos)
        << measures;
    const auto [missing, refused] = runSpheres("claims --scene no_such_scene");
    EXPECT_EQ(refused, 2) << missing;
    EXPECT_EQ(missing.rfind("spheres: ", 0), 0u) << missing;
    EXPECT_EQ(countOf(missing, "\n"), 1) << missing;
}

// A claim about a setting reads as the panel names the setting ("method = position", not
// "setting = 0"); one that fails says the value the text expected, by its name too.
TEST(ClaimsCommandLine, ASettingIsNamedByItsValue) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("21_shock_column"));
    std::vector<std::string> measured;
    for (const scenes::ClaimCheck& check : scenes::checkClaims(scene)) {
        if (check.claim->measure == "setting") measured.push_back(check.measured);
    }
    EXPECT_EQ(measured, (std::vector<std::string>{"method = position", "passes = 1", "shock = off", "shock = on", "mu = 0.5"}));
    scene.claims = {scene.claims[1]};  // "position based": method near 0
    scene.claims[0].near = 1.0;        // velocity
    const std::vector<scenes::ClaimCheck> wrong = scenes::checkClaims(scene);
    ASSERT_EQ(wrong.size(), 1u);
    EXPECT_FALSE(wrong[0].holds);
    EXPECT_EQ(wrong[0].measured, "method = position, expected velocity");
    const auto [output, code] = runSpheres("claims --scene 21_shock_column");
    EXPECT_NE(output.find("  \u2713 \"A, shock propagation off\": shock = off\n"), std::string::npos) << output;
}

// A bare number means nothing beside a quote: the panel's line names what was measured, how
// it was taken from the samples and of which sphere, as the inspector names it.
TEST(ClaimsCommandLine, AMeasuredValueNamesItsQuantity) {
    const auto [output, code] =
        runSpheres("claims --scene 03_head_on --scene 21_shock_column --scene 13_tunnelling --scene 05_billiard --scene 14_three_answers");
    EXPECT_EQ(code, 0) << output;
    for (const char* line : {"\"its momentum spreads to all 15\": spheres moving faster than 1 cm/s among #1\u2013#15 at t = 0.35 s = 15",
                             "momentum change at t = 0.25 s = 0.1 of |P| at t = 0",
                             "\"A and B never rest either\": max speed over t = 50\u201360 s = 0.2616 m/s (\u2265 0.1)",
                             "\"B at every landing\" (with method=reflection): max contact state over t = 50\u201360 s = 1 (0 free, 1 bounced, 2 static)",
                             "\"its top sinks 4.9 cm, about one radius\": last top drop at t = 10 s = 0.04872 m",
                             "\"so its centre jumps past the middle of the wall\": distance to plane 0 at t = 0.15 s = -0.05 m",
                             "\"a 2 cm wall\": thickness of plane 0 = 0.02 m",
                             "\"the moving one stops dead\": vx of sphere #0 over t = 0.9\u20131.2 s = 0 m/s (19 samples)",
                             "\"Two equal spheres meet head-on\": mass of spheres #0, #1 = 1 kg (2 samples)",
                             "\"so it squashes (overlaps up to 19 % of r)\": max penetration over t = 0\u201310 s = 19.27 % of r",
                             "\"the contact graph's 20 levels\" (with shock=on): shock levels over t = 1\u201310 s = 20 (",
                             "\"Twenty stacked spheres, position based\": method = position",
                             // At t = 0, said (a claim without "to" measures the start only)
                             "\"Two equal spheres meet head-on\": y of spheres #0, #1 at t = 0 s = 0 m (2 samples)"}) {
        EXPECT_NE(output.find(line), std::string::npos) << line << "\n" << output;
    }
}
