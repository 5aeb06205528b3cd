// Side by side (app/comparison.h): two runs of the same initial state stepping
// together keep identical hashes when the override changes nothing and differ when
// it does; `spheres capture --compare` writes frames with the two views.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "app/commands/capture_command.h"
#include "app/run/comparison.h"
#include "app/run/scene_source.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "app/views/frame_builder.h"
#include "ui/control_panel.h"
#include "physics/diagnostics.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "test_capture_support.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;  // s

scenes::Scene preset(const std::string& name, const std::vector<std::string>& settings = {}) {
    return app::loadSceneWithSettings(name, settings);
}

// Hashes of both runs after each of `frames` frames of 1/60 s.
std::vector<std::pair<std::uint64_t, std::uint64_t>> runSideBySide(const scenes::Scene& scene,
                                                                    const std::vector<std::string>& overrides,
                                                                    int frames) {
    app::Simulation simulation(scene);
    app::Session session(simulation);
    EXPECT_EQ(session.startComparison(overrides), "");
    std::vector<std::pair<std::uint64_t, std::uint64_t>> hashes;
    for (int frame = 0; frame < frames; ++frame) {
        session.advance(kFrame);
        hashes.emplace_back(physics::stateHash(session.run(0).world()), physics::stateHash(session.run(1).world()));
        EXPECT_EQ(session.run(0).world().stepCount, session.run(1).world().stepCount) << frame;
    }
    return hashes;
}

TEST(SideBySide, ANoOpOverrideKeepsIdenticalHashes) {
    // The pile's method is position already; beta is its own value.
    for (const auto& overrides : {std::vector<std::string>{"method=position"}, std::vector<std::string>{"beta=0.8"}}) {
        const auto hashes = runSideBySide(preset("pile", {"count=300"}), overrides, 40);
        for (std::size_t frame = 0; frame < hashes.size(); ++frame) {
            ASSERT_EQ(hashes[frame].first, hashes[frame].second) << overrides[0] << " frame " << frame;
        }
    }
}

TEST(SideBySide, ARealOverrideMakesThemDifferAndTheyStepTogether) {
    const auto hashes = runSideBySide(preset("cradle"), {"order=reversed"}, 30);
    EXPECT_NE(hashes.back().first, hashes.back().second);
    const auto velocity = runSideBySide(preset("pile", {"count=300"}), {"method=velocity"}, 30);
    EXPECT_NE(velocity.back().first, velocity.back().second);
}

// The views show the same instant, whatever their steps cost: in the window (a wall budget
// a frame) the continuous gas of 15 fell 5 s behind the first view in 20 s (19th audit).
// A view of another h steps to the first view's time, to half of its own step; so does O.
TEST(SideBySide, ACostlierViewAndAViewOfAnotherStepKeepTheFirstViewsTime) {
    for (const char* other : {"method=continuous", "h=0.004"}) {
        const double h = std::string(other) == "h=0.004" ? 0.004 : kFrame;  // s, the second view's step
        app::Simulation simulation(preset("15_fast_gas"));
        simulation.wallBudget = 0.004;  // s a frame: the first view runs in slow motion
        app::Session session(simulation);
        ASSERT_EQ(session.startComparison({other}), "");
        ASSERT_EQ(session.runCount(), 2);
        for (int frame = 0; frame < 20; ++frame) {
            session.advance(kFrame);
            EXPECT_NEAR(session.run(1).world().time, session.run(0).world().time, 0.5 * h + 1e-12) << other << frame;
        }
        EXPECT_GT(session.run(0).world().time, 0.0);
        session.run(0).paused = true;
        const double before = session.run(0).world().time;
        session.singleStep();
        EXPECT_NEAR(session.run(0).world().time, before + kFrame, 1e-12);
        EXPECT_NEAR(session.run(1).world().time, session.run(0).world().time, 0.5 * h + 1e-12) << other;
    }
}

TEST(SideBySide, TheSecondRunIsTheSimulateCommandsRunWithTheOverride) {
    app::Simulation simulation(preset("pile", {"count=300"}));
    app::Session session(simulation);
    ASSERT_EQ(session.startComparison({"method=velocity,passes=2"}), "");
    app::Simulation alone(preset("pile", {"count=300", "method=velocity", "passes=2"}));
    for (int frame = 0; frame < 30; ++frame) {
        session.advance(kFrame);
        alone.advance(kFrame);
    }
    EXPECT_EQ(physics::stateHash(session.run(1).world()), physics::stateHash(alone.world()));
}

TEST(SideBySide, TheSecondRunFollowsThePanelButNotWhereItIsOverridden) {
    const scenes::Scene scene = preset("03_head_on");
    app::Simulation simulation(scene);
    app::Comparison comparison(scene, {"beta=0.5"});
    simulation.editableScene().params.alpha = 0.3;
    simulation.editableScene().params.beta = 0.9;
    simulation.timeScale = 0.25;
    simulation.paused = true;
    comparison.follow(simulation);
    EXPECT_EQ(comparison.simulation().params().alpha, 0.3);
    EXPECT_EQ(comparison.simulation().params().beta, 0.5);
    EXPECT_EQ(comparison.simulation().timeScale, 0.25);
    EXPECT_TRUE(comparison.simulation().paused);
    EXPECT_EQ(comparison.primaryLabel(simulation.scene()), "beta = 0.9");
    EXPECT_EQ(comparison.label(), "beta = 0.5");
}

TEST(SideBySide, OverridesAreSplitCheckedAndLabelled) {
    EXPECT_EQ(app::splitOverrides({" method=velocity, order=reversed ", "passes=1", ","}),
              (std::vector<std::string>{"method=velocity", "order=reversed", "passes=1"}));
    const scenes::Scene scene = preset("pile");
    EXPECT_EQ(app::checkOverrides(scene, {"method=velocity", "passes=1"}), "");
    EXPECT_NE(app::checkOverrides(scene, {"bogus=1"}).find("bogus"), std::string::npos);
    EXPECT_NE(app::checkOverrides(scene, {"beta=2"}).find("beta=2"), std::string::npos);
    EXPECT_NE(app::checkOverrides(scene, {}), "");
    EXPECT_EQ(app::overrideLabel(scene, {"method=velocity", "order=reversed"}), "method = position, order = index");
    // Six significant digits in a view's label (it read h = 0.016666666666666666), every
    // digit where two scenes are compared.
    EXPECT_EQ(app::overrideLabel(scene, {"h=0.01"}), "h = 0.0166667");
    EXPECT_EQ(app::overrideLabel(scene, {"h=0.01"}, true), "h = 0.016666666666666666");
    app::Simulation simulation(scene);
    app::Session session(simulation);
    EXPECT_NE(session.startComparison({"beta=7"}), "");
    EXPECT_EQ(session.runCount(), 1);
}

// Slide 7's three answers from one state: a name with several values makes a view per
// value; the one A already shows is left out.
TEST(SideBySide, ANameWithSeveralValuesMakesAViewEach) {
    const scenes::Scene scene = preset("02_bounce_projection");
    app::Variants variants;
    ASSERT_EQ(app::overrideVariants(scene, {"method=position,reflection,continuous"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"method=reflection"}, {"method=continuous"}}));
    ASSERT_EQ(app::overrideVariants(scene, {"method=velocity,reflection, passes=1"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"method=velocity", "passes=1"}, {"method=reflection", "passes=1"}}));
    ASSERT_EQ(app::overrideVariants(scene, {"passes=1, method=velocity,reflection"}, variants), "");  // several first
    EXPECT_EQ(variants, (app::Variants{{"method=velocity", "passes=1"}, {"method=reflection", "passes=1"}}));
    EXPECT_EQ(app::overrideVariants(scene, {"method=velocity"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"method=velocity"}}));
    EXPECT_EQ(app::overrideVariants(scene, {"method=position"}, variants), "");  // nothing differs: kept
    EXPECT_EQ(variants, (app::Variants{{"method=position"}}));
    EXPECT_TRUE(scenes::changesNothing(scene, variants));
    // A name written again is one more of its values, not the last one kept.
    ASSERT_EQ(app::overrideVariants(scene, {"method=velocity,passes=1,method=reflection"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"method=velocity", "passes=1"}, {"method=reflection", "passes=1"}}));
    EXPECT_FALSE(scenes::changesNothing(scene, variants));
    ASSERT_EQ(app::overrideVariants(scene, {"beta=0.5", "beta=0.2,0.3"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"beta=0.5"}, {"beta=0.2"}, {"beta=0.3"}}));
    EXPECT_EQ(app::overrideVariants(scene, {"reflection"}, variants), "'reflection' has no name: write name=value,value");
    EXPECT_EQ(app::overrideVariants(scene, {"order"}, variants), "'order' has no value: write order=value");
    EXPECT_EQ(app::overrideVariants(scene, {"method=velocity,reflection,beta=0.5,0.6"}, variants),
              "at most 4 views: A and 3 others");  // four combinations, none of them A's
    // Two names with two values each: a view per combination, the one A shows left out.
    ASSERT_EQ(app::overrideVariants(scene, {"method=position,velocity,passes=4,1"}, variants), "");
    EXPECT_EQ(variants, (app::Variants{{"method=position", "passes=1"}, {"method=velocity", "passes=4"},
                                       {"method=velocity", "passes=1"}}));
    EXPECT_NE(app::overrideVariants(scene, {"beta=0.1,0.2,0.3,0.4,0.5"}, variants).find("at most 4"), std::string::npos);
    // Many names with many values are refused before any combination is built.
    EXPECT_EQ(app::overrideVariants(scene, {"alpha=0,0.5,beta=0,0.5,mu=0,0.5,epsilon=0,0.1"}, variants),
              "at most 4 views: A and 3 others");
    EXPECT_NE(app::overrideVariants(scene, {"method=velocity,fast"}, variants).find("method=fast"), std::string::npos);

    app::Simulation simulation(scene);
    app::Session session(simulation);
    ASSERT_EQ(session.startComparison({"method=position,reflection,continuous"}), "");
    ASSERT_EQ(session.runCount(), 3);
    EXPECT_EQ(session.run(1).params().method, physics::Method::Reflection);
    EXPECT_EQ(session.run(2).params().method, physics::Method::Continuous);
    EXPECT_EQ(session.comparison()->primaryLabel(simulation.scene()), "method = position");
    EXPECT_EQ(session.comparison()->label(1), "method = continuous");
    for (int frame = 0; frame < 60; ++frame) session.advance(kFrame);
    for (int k = 1; k < 3; ++k) {
        EXPECT_EQ(session.run(k).world().stepCount, session.run(0).world().stepCount);
        EXPECT_NE(physics::stateHash(session.run(k).world()), physics::stateHash(session.run(0).world()));
    }
    session.stopComparison();
    EXPECT_EQ(session.runCount(), 1);
}

// A scene's "compare" opens side by side; the next scene without one closes it, but
// not a side by side the user started.
TEST(SideBySide, ASceneThatAsksForViewsOpensThemAndTheNextSceneClosesThem) {
    app::Simulation simulation(preset("14_three_answers"));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 3);
    EXPECT_EQ(session.comparison()->label(1), "method = continuous");
    simulation.setScene(preset("02_bounce_projection"));
    session.sceneChanged();
    EXPECT_EQ(session.runCount(), 1);
    ASSERT_EQ(session.startComparison({"method=velocity"}), "");
    simulation.setScene(preset("03_head_on"));
    session.sceneChanged();
    EXPECT_EQ(session.runCount(), 2);
}

// Side by side, a sphere clicked in a view is that view's: the inspector and the
// explanation read its run. On slide 14's column (A: shock off, 1 pass; C: shock on, 1
// pass) sphere 6 sits in a squashed column in A and in one standing as built in C: the
// contacts explained differ by that much.
TEST(SideBySide, ASphereSelectedInAViewIsThatViewsSphere) {
    const auto deepestExplained = [](int view) {
        app::Simulation simulation(preset("21_shock_column"));
        app::Session session(simulation);
        session.sceneChanged();
        EXPECT_EQ(session.runCount(), 4);
        session.select(6, view);
        EXPECT_EQ(session.selectedView(), view);
        for (int k = 0; k < session.runCount(); ++k) session.run(k).setSelectedSphere(6);  // as the views do
        for (int frame = 0; frame < 120; ++frame) session.advance(kFrame);
        double deepest = 0.0;  // m
        for (const physics::ContactEvent& event : session.latestContacts().events) deepest = std::max(deepest, event.depth);
        return deepest;
    };
    const double inA = deepestExplained(0), inC = deepestExplained(2);
    std::printf("deepest explained: A %.3g m, C %.3g m\n", inA, inC);
    EXPECT_GT(inA, 0.10 * 0.05);  // m: squashed, 13.6 % of r = 5 cm measured
    EXPECT_LT(inC, 0.01 * 0.05);  // the sag of one solver step, 0.34 % measured
    app::Simulation simulation(preset("21_shock_column"));
    app::Session session(simulation);
    session.sceneChanged();
    session.select(6, 3);
    session.stopComparison();
    EXPECT_EQ(session.selectedView(), 0);  // the view is gone: run 0's sphere
}

// The parameters every other view sets itself: the panel's sliders of those reach view A
// alone, and say so. On slide 14's column (shock=off,on,passes=1,4) K and shock; with
// "method=velocity" alone, method; none when a view leaves it to the panel.
TEST(SideBySide, TheParametersEveryOtherViewSetsAreNamed) {
    app::Simulation simulation(preset("21_shock_column"));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_NE(session.comparison(), nullptr);
    EXPECT_EQ(session.comparison()->setInEveryView(), (std::vector<std::string>{"passes", "shock"}));
    ASSERT_EQ(session.startComparison({"method=velocity"}), "");
    EXPECT_EQ(session.comparison()->setInEveryView(), (std::vector<std::string>{"method"}));
    ASSERT_EQ(session.startComparison({"method=velocity,reflection,passes=4"}), "");
    EXPECT_EQ(session.comparison()->setInEveryView(), (std::vector<std::string>{"passes", "method"}));
}

// ---------------------------------------------------------------- capture --compare

class CaptureCompare : public ::testing::Test {
  protected:
    void SetUp() override {
        if (const std::string why = capture_test::unavailableReason(platform::HeadlessBackend::Auto); !why.empty()) {
            GTEST_SKIP() << "no headless GL here: " << why;
        }
    }
};

bool saturated(glm::u8vec4 p) {
    return std::max({int(p.x), int(p.y), int(p.z)}) - std::min({int(p.x), int(p.y), int(p.z)}) > 60;
}

int countSaturated(const render::Image& image, int x0, int x1) {
    int count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = x0; x < x1; ++x) count += saturated(image.pixel(x, y));
    }
    return count;
}

TEST_F(CaptureCompare, WritesFramesWithTwoLabelledViews) {
    const std::string out = capture_test::freshFolder("compare_cradle");
    app::CaptureOptions options =
        capture_test::smallCapture("cradle", out, platform::HeadlessBackend::Auto);
    options.size = "640x360";
    options.at = "0,30";
    options.compare = {"order=reversed"};
    ASSERT_EQ(app::runCapture(options), 0);

    const nlohmann::json manifest = capture_test::readManifest(out);
    ASSERT_TRUE(manifest.contains("compare"));
    EXPECT_EQ(manifest["compare"]["label_a"], "order = index");
    EXPECT_EQ(manifest["compare"]["label_b"], "order = reversed");
    const auto& frames = manifest["frames"];
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0]["hash"], frames[0]["compare_hash"]);  // the same initial state
    EXPECT_NE(frames[1]["hash"], frames[1]["compare_hash"]);
    EXPECT_EQ(frames[1]["steps"], frames[1]["compare_steps"]);  // stepping together
    // The second view's hash is the override's own run, stepped as the window steps.
    const physics::World reversed = capture_test::worldAtFrame(preset("cradle", {"order=reversed"}), 30);
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(physics::stateHash(reversed)));
    EXPECT_EQ(frames[1]["compare_hash"], hash);

    // Two views: the halves both hold spheres, the middle columns are the dark gap.
    const render::Image image = capture_test::readFrame(out, 30);
    ASSERT_EQ(image.width, 640);
    const std::vector<int> viewport = manifest["viewport"].get<std::vector<int>>();
    const std::vector<int> second = manifest["compare"]["viewport_b"].get<std::vector<int>>();
    EXPECT_EQ(viewport[0], 0);
    EXPECT_EQ(viewport[2], 318);
    EXPECT_EQ(second[0], 322);
    EXPECT_GT(countSaturated(image, 0, viewport[2]), 200);
    EXPECT_GT(countSaturated(image, second[0], 640), 200);
    for (int y = 0; y < image.height; y += 7) {
        const glm::u8vec4 gap = image.pixel(320, y);
        EXPECT_LT(gap.x + gap.y + gap.z, 3 * 40) << "the gap between the views, row " << y;
    }
    // The labels: light text on a dark box at the top left of each view.
    int light = 0;
    for (int y = 8; y < 120; ++y) {
        for (int x = 330; x < 480; ++x) light += capture_test::luminance(image.pixel(x, y)) > 200.0f;
    }
    EXPECT_GT(light, 50);
}

TEST_F(CaptureCompare, WritesThreeViewsForSlideSevensAnswers) {
    const std::string out = capture_test::freshFolder("compare_three");
    app::CaptureOptions options = capture_test::smallCapture("02_bounce_projection", out, platform::HeadlessBackend::Auto);
    options.size = "960x300";
    options.at = "0,40";
    options.compare = {"method=position,reflection,continuous"};
    ASSERT_EQ(app::runCapture(options), 0);
    const nlohmann::json manifest = capture_test::readManifest(out);
    EXPECT_EQ(manifest["compare"]["labels"],
              nlohmann::json::array({"method = position", "method = reflection", "method = continuous"}));
    ASSERT_EQ(manifest["compare"]["viewports"].size(), 3u);
    // In a 960 x 300 image two rows with each label left of its view left each box 148 px,
    // but cut the labels' last lines (the properties' marks): three views in a row, each
    // under its whole label.
    const auto& views = manifest["compare"]["viewports"];
    EXPECT_EQ(views[2][1], views[0][1]);
    EXPECT_GT(views[2][0], views[1][0]);
    EXPECT_LT(int(views[0][1]) + int(views[0][3]), 300 - 7 * 17) << "under seven lines of label";
    const auto& last = manifest["frames"][1];
    ASSERT_EQ(last["compare_hashes"].size(), 2u);
    EXPECT_NE(last["compare_hashes"][0], last["compare_hashes"][1]);
    const render::Image image = capture_test::readFrame(out, 40);
    for (int k = 0; k < 3; ++k) {
        const int x = views[k][0], width = views[k][2];
        EXPECT_GT(countSaturated(image, x, x + width), 20) << "view " << k;  // its ball
    }
}

// Presented on a 1024x768 projector, four narrow labels broke their words ("sequenti" /
// "al", "penetrati" / "on", "✗ momentu" / "m"): their type is made smaller (every label
// alike) until the widest word fits, and the views take the room the smaller labels leave.
TEST_F(CaptureCompare, PresentedLabelsOnASmallProjectorKeepTheirWordsWhole) {
    for (const char* preset : {"20_stacked_drop", "21_shock_column", "16_bernoulli"}) {
        const std::string out = capture_test::freshFolder(std::string("compare_words_") + preset);
        app::CaptureOptions options = capture_test::smallCapture(preset, out, platform::HeadlessBackend::Auto);
        options.size = "1024x768";
        options.withUi = true;
        options.present = true;
        options.at = "90";
        ASSERT_EQ(app::runCapture(options), 0) << preset;
        const nlohmann::json manifest = capture_test::readManifest(out);
        ASSERT_EQ(manifest["frames"].size(), 1u);
        EXPECT_EQ(manifest["frames"][0]["label_words_broken"], 0) << preset;
        EXPECT_EQ(manifest["frames"][0]["labels_cut"], 0) << preset;
    }
}

// The label drawn above view k of a capture's manifest (the nearest rectangle of the UI
// drawn above the view, starting where it does): x, y (from the top), width, height in px;
// empty when there is none.
std::vector<float> labelAbove(const nlohmann::json& manifest, int k) {
    const auto& view = manifest["layout"]["views"][k];
    const float top = float(manifest["size"][1]) - float(view[1]) - float(view[3]);  // px from the window's top
    std::vector<float> found;
    for (const auto& drawn : manifest["layout"]["ui_drawn"]) {
        const float bottom = float(drawn[1]) + float(drawn[3]);
        if (std::abs(float(drawn[0]) - float(view[0])) <= 2.0f && bottom <= top + 1.0f &&
            (found.empty() || bottom > found[1] + found[3])) {
            found = {float(drawn[0]), float(drawn[1]), float(drawn[2]), float(drawn[3])};
        }
    }
    return found;
}

// The manifest of a capture of `scene` with its panel (presented or not) at `size`, frames `at`.
nlohmann::json capturedWithPanel(const std::string& name, const char* scene, const char* size, const char* at, bool present) {
    const std::string out = capture_test::freshFolder(name);
    app::CaptureOptions options = capture_test::smallCapture(scene, out, platform::HeadlessBackend::Auto);
    options.size = size;
    options.withUi = true;
    options.present = present;
    options.at = at;
    EXPECT_EQ(app::runCapture(options), 0) << scene << " at " << size;
    return capture_test::readManifest(out);
}

// Presented with four views, each view starts right under its label: the labels' room had a
// whole line to spare (for digits that might wrap one more), a blank band of 48 px under
// every label at 1920 x 1080, and the four views of 22 at 1280 x 800 went into one column of
// small boxes. The room is now what the lines take wrapped a font narrower.
TEST_F(CaptureCompare, PresentedViewsStartRightUnderTheirLabels) {
    for (const char* size : {"1920x1080", "1280x800"}) {
        const nlohmann::json manifest =
            capturedWithPanel(std::string("compare_under_labels_") + size, "22_shock_pyramid", size, "60", true);
        const auto& views = manifest["layout"]["views"];
        ASSERT_EQ(views.size(), 4u) << size;
        EXPECT_EQ(views[0][1], views[1][1]) << size << ": A and B in one row (a 2 x 2 grid)";
        EXPECT_EQ(manifest["frames"][0]["labels_cut"], 0) << size;
        for (int k = 0; k < 4; ++k) {
            const std::vector<float> label = labelAbove(manifest, k);
            ASSERT_FALSE(label.empty()) << size << ": no label above view " << k;
            const float top = float(manifest["size"][1]) - float(views[k][1]) - float(views[k][3]);
            EXPECT_LE(top - (label[1] + label[3]), 6.0f) << size << ": view " << k << " starts that far under its label";
        }
    }
}

// Presented with three or four views, the panel takes less of the width: at 1024x768 its
// 45 % had left 16's four views three in a row and one under them, boxes of 185 px.
TEST_F(CaptureCompare, PresentedWithFourViewsThePanelIsNarrower) {
    const nlohmann::json manifest = capturedWithPanel("compare_narrow_panel", "16_bernoulli", "1024x768", "30", true);
    const auto& views = manifest["layout"]["views"];
    ASSERT_EQ(views.size(), 4u);
    EXPECT_LE(int(views[0][0]), int(1024 * ui::kPresentedPanelShareManyViews) + 2) << "the views start where the panel ends";
    EXPECT_EQ(views[0][1], views[1][1]) << "A and B in a row";
    EXPECT_EQ(views[2][1], views[3][1]) << "C and D in a row";
    EXPECT_NE(views[0][1], views[2][1]) << "two rows";
    EXPECT_EQ(manifest["frames"][0]["labels_cut"], 0);
}

// Side by side, the labels are equally tall: in 21, C's label gains a line ("most in one
// step: 20 shock levels, 80 rounds" wraps) and had stood lower than the others.
TEST_F(CaptureCompare, TheLabelsSideBySideAreEquallyTall) {
    const nlohmann::json manifest = capturedWithPanel("compare_equal_labels", "21_shock_column", "1280x720", "120", false);
    ASSERT_EQ(manifest["layout"]["views"].size(), 4u);
    const std::vector<float> a = labelAbove(manifest, 0);
    ASSERT_FALSE(a.empty());
    for (int k = 1; k < 4; ++k) {
        const std::vector<float> label = labelAbove(manifest, k);
        ASSERT_FALSE(label.empty()) << "view " << k;
        EXPECT_NEAR(label[3], a[3], 1.0f) << "view " << k << "'s label against A's";
    }
    EXPECT_EQ(manifest["frames"][0]["labels_cut"], 0);
}

// 21's view C gains a label line at its first steps ("most in one step: 20 shock levels,
// 80 rounds" wraps where "0 shock levels, 0 rounds" did not): the views make room for it at
// the frame it appears, as the window's do, and no frame cuts a label (the README's
// screenshot, laid out once at frame 0, had lost C's last line).
TEST_F(CaptureCompare, NoFrameCutsALabelThatGrewSinceTheFirst) {
    const std::string out = capture_test::freshFolder("compare_labels_grow");
    app::CaptureOptions options = capture_test::smallCapture("21_shock_column", out, platform::HeadlessBackend::Auto);
    options.size = "1280x720";
    options.withUi = true;
    options.at = "0,120";
    ASSERT_EQ(app::runCapture(options), 0);
    const nlohmann::json manifest = capture_test::readManifest(out);
    ASSERT_EQ(manifest["frames"].size(), 2u);
    for (const auto& frame : manifest["frames"]) EXPECT_EQ(frame["labels_cut"], 0) << "frame " << frame["index"];
    // Laid out for frame 0's labels, frame 120's views would reach a line higher.
    options.at = "0";
    const std::string first = capture_test::freshFolder("compare_labels_first");
    options.out = first;
    ASSERT_EQ(app::runCapture(options), 0);
    const auto top = [](const nlohmann::json& viewport) { return int(viewport[1]) + int(viewport[3]); };  // px, from the bottom
    EXPECT_LT(top(manifest["viewport"]), top(capture_test::readManifest(first)["viewport"])) << "the views moved down";
}

TEST_F(CaptureCompare, RefusesAnUnknownOverrideBeforeWritingAnything) {
    const std::string out = capture_test::freshFolder("compare_refused");
    app::CaptureOptions options = capture_test::smallCapture("cradle", out, platform::HeadlessBackend::Auto);
    options.frames = 2;
    options.compare = {"ordr=reversed"};
    try {
        app::runCapture(options);
        ADD_FAILURE() << "not refused";
    } catch (const app::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--compare"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(capture_test::fs::exists(out));
}

}  // namespace

// Side by side, "The text, measured" lists what each view measured of the text at its own
// settings, with its letter: slide 14's column says what B (four passes), C (shock on) and
// D (both) show, and those views measure it (before, only view A's claims were listed).
TEST(SideBySide, EachViewMeasuresWhatTheTextSaysOfIt) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("21_shock_column")));
    app::Session session(simulation);
    session.sceneChanged();  // its "compare": four views
    ASSERT_EQ(session.runCount(), 4);
    for (int frame = 0; frame < 700 && simulation.world().time < 10.0 + 1e-9; ++frame) session.advance(1.0 / 60.0);
    ASSERT_GE(simulation.world().time, 10.0);
    const ui::Readouts readouts = app::makeReadouts(simulation, ui::FrameTimes{}, session.comparison());
    std::size_t watched = 0;
    for (int k = 0; k < session.runCount(); ++k) watched += session.run(k).claimsWatched();
    EXPECT_EQ(readouts.claimsWatched, watched);
    EXPECT_EQ(readouts.claims.size(), watched) << "every claim's moment has passed at 10 s";
    std::string views;
    for (const ui::Readouts::ClaimLine& line : readouts.claims) {
        EXPECT_TRUE(line.holds) << line.view << " " << line.says << ": " << line.measured;
        if (views.find(line.view) == std::string::npos) views += line.view;
        if (line.says == "B, four passes, still leaves 3.1 %") {
            EXPECT_EQ(line.view, 'B');
        }
        if (line.says == "its top sphere's centre at 1.95 m (39 r)") {
            EXPECT_EQ(line.view, 'C');
        }
    }
    EXPECT_EQ(views, "ABCD");
    // The four views are the text's four settings; two claims about A's momentum mark are
    // measured at a fifth and a sixth (mu = 1, response = momentum), which no view shows, as
    // the panel says.
    EXPECT_EQ(readouts.claimsElsewhere, 2u);
    std::set<std::string> elsewhere;
    for (const scenes::Claim& claim : simulation.scene().claims) {
        if (claim.in != scenes::ClaimSource::Description) continue;
        const bool shown = std::any_of(readouts.claims.begin(), readouts.claims.end(),
                                       [&](const ui::Readouts::ClaimLine& line) { return line.says == claim.says; });
        if (!shown) elsewhere.insert(claim.says);
    }
    EXPECT_EQ(elsewhere, (std::set<std::string>{"slide 13's static contact (v \u2190 \u03bc v",
                                                "(response = momentum keeps it)"}));
    EXPECT_EQ(app::makeReadouts(simulation, ui::FrameTimes{}).claimsWatched, simulation.claimsWatched());
}

// Presented on a projector, 16's labels say what each solver breaks, the slide's lesson in
// one line of large type (the five marks broke inside their words): A the symmetry, B the
// energy, C and D nothing.
TEST(SideBySide, PresentedLabelsSayWhatEachSolverBreaks) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("16_bernoulli")));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 4);
    while (simulation.world().time < 0.5) session.advance(1.0 / 30.0);
    const auto labels = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Presented);
    const std::vector<std::string> expected{"\u2717\u00a0symmetry", "\u2717\u00a0energy", "\u2713\u00a0nothing broken",
                                            "\u2713\u00a0nothing broken"};
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_FALSE(labels[k].empty());
        EXPECT_EQ(labels[k].back(), expected[k]) << k;
    }
    // Titled by the values alone where the views differ in one name (the slider names it):
    // "solver = generalized-reflections" took four lines of large type.
    EXPECT_EQ(labels[0].front(), "A   sequential");
    EXPECT_EQ(labels[3].front(), "D   generalized-reflections");
    app::Simulation column(scenes::loadScene(scenes::presetPath("21_shock_column")));
    app::Session columns(column);
    columns.sceneChanged();
    const auto twoNames = app::comparisonReadouts(column, *columns.comparison(), app::LabelLines::Presented);
    EXPECT_EQ(twoNames[0].front(), "A   shock = off, passes = 1") << "two names: both said";
    // 21 compares the sweep: its text explains A's and B's marks, so its labels show them
    // too (they showed them only where the views compared solvers).
    while (column.world().time < 0.5) columns.advance(1.0 / 30.0);
    const auto swept = app::comparisonReadouts(column, *columns.comparison(), app::LabelLines::Presented);
    // A line a property: "✗ momentum, positivity" broke inside "momentum" in a quarter of 1280 px.
    const std::vector<std::vector<std::string>> broken{{"\u2717\u00a0momentum", "\u2717\u00a0positivity"},
                                                       {"\u2717\u00a0positivity"},
                                                       {"\u2713\u00a0nothing broken"},
                                                       {"\u2713\u00a0nothing broken"}};
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_EQ(swept[k].size(), 3 + broken[k].size()) << k;  // the title, E~ and the penetration, then the marks
        EXPECT_EQ(std::vector<std::string>(swept[k].begin() + 3, swept[k].end()), broken[k]) << k;
    }
    // 22 too: its text explains D's ✗ positivity (the floor's answers press its bottom layer back together).
    app::Simulation pyramid(scenes::loadScene(scenes::presetPath("22_shock_pyramid")));
    app::Session pyramids(pyramid);
    pyramids.sceneChanged();
    while (pyramid.world().time < 2.0) pyramids.advance(1.0 / 30.0);
    const auto marked = app::comparisonReadouts(pyramid, *pyramids.comparison(), app::LabelLines::Presented);
    const std::vector<std::string> pyramidMarks{"\u2717\u00a0positivity", "\u2717\u00a0positivity",
                                                "\u2713\u00a0nothing broken", "\u2717\u00a0positivity"};
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_EQ(marked[k].size(), 4u) << k;
        EXPECT_EQ(marked[k].back(), pyramidMarks[k]) << k;
    }
}

// 14's text counts its bounces ("0.47 at the fifth", "0.43 at the seventh"); the labels say
// which bounce their apex ratio is, so that the class finds the text's numbers on screen
// (they showed the newest ratio alone, and the fifth had gone by unnoticed).
TEST(SideBySide, TheLabelsNumberTheBounceOfTheirApexRatio) {
    app::Simulation simulation(preset("14_three_answers"));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 3);
    while (simulation.world().time < 5.0) session.advance(1.0 / 30.0);
    const auto labels = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Full);
    const auto apexLine = [](const std::vector<std::string>& lines) {
        for (const std::string& line : lines) {
            if (line.rfind("apex ratio", 0) == 0) return line;
        }
        return std::string();
    };
    EXPECT_EQ(apexLine(labels[0]), "apex ratio 0.467 at bounce 5 (\u03b2\u00b2 0.640)");
    EXPECT_EQ(apexLine(labels[1]), "apex ratio 0.428 at bounce 7 (\u03b2\u00b2 0.640)");
}

// Under the continuous method only the symmetry is measured (the sequential solver, meeting
// Bernoulli's two impacts of one instant, breaks it there too): the short line says so, not
// "nothing broken" (which claimed all five from the symmetry alone), and so do the marks.
TEST(SideBySide, PresentedLabelsUnderTheContinuousMethodSayWhatIsNotMeasured) {
    app::Simulation simulation(preset("16_bernoulli", {"method=continuous"}));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 4);
    while (simulation.world().time < 0.5) session.advance(1.0 / 30.0);
    const auto presented = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Presented);
    const auto full = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Full);
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_FALSE(presented[k].empty());
        EXPECT_EQ(presented[k].back(), std::string(k == 0 ? "\u2717" : "\u2713") + "\u00a0symmetry, others not measured (continuous)") << k;
        ASSERT_FALSE(full[k].empty());
        EXPECT_EQ(full[k].back(), "others not measured (continuous)") << k;
    }
}

// Slide 7's three answers side by side at a coarse step: each view's label (the projector's
// too) shows its newest floor bounce's apex ratio beside beta^2, the lesson of 14's text: A
// (projection) under 0.64, B (reflection) above it by then, C (back to the contact) 0.640.
// Before, the panel refused every one of them as slower than 20 g h and no label had them.
TEST(SideBySide, EachViewShowsItsApexRatioBesideBetaSquared) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("14_three_answers")));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 3);
    const auto labels = [&] { return app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Presented); };
    for (const auto& label : labels()) {
        ASSERT_EQ(label.size(), 4u);
        EXPECT_EQ(label[3], "apex ratio\u00a0\u2013 (\u03b2\u00b2\u00a00.640)") << "a dash until the first bounce";
    }
    std::vector<std::vector<double>> shown(3);  // each view's ratios as they changed (by more than 1e-6)
    for (int frame = 0; frame < 600 && simulation.world().time < 10.0; ++frame) {
        session.advance(1.0 / 30.0);
        const std::vector<app::ViewReadout> views = app::viewReadouts(simulation, *session.comparison());
        for (std::size_t k = 0; k < 3; ++k) {
            if (views[k].apexRatio && (shown[k].empty() || std::abs(shown[k].back() - *views[k].apexRatio) > 1e-6)) {
                shown[k].push_back(*views[k].apexRatio);
            }
        }
    }
    const auto near = [](const std::vector<double>& values, std::vector<double> expected) {
        if (values.size() != expected.size()) return testing::AssertionFailure() << values.size() << " bounces";
        for (std::size_t k = 0; k < values.size(); ++k) {
            if (std::abs(values[k] - expected[k]) > 0.005) return testing::AssertionFailure() << k << ": " << values[k];
        }
        return testing::AssertionSuccess();
    };
    // Bounces at least 4 g h fast (1.3 m/s): later hops measure the step more than the method
    // (B's went to 3.8 at 4.9 s, C's hopping in place to 0.41).
    ASSERT_GE(shown[0].size(), 3u);
    ASSERT_GE(shown[1].size(), 3u);
    const auto first3 = [](const std::vector<double>& v) { return std::vector<double>(v.begin(), v.begin() + 3); };
    EXPECT_TRUE(near(first3(shown[0]), {0.59, 0.57, 0.55}));   // the text: 0.59, then 0.57
    EXPECT_TRUE(near(first3(shown[1]), {0.635, 0.74, 0.77}));  // 0.635, then 0.74 and 0.77
    EXPECT_LT(*std::max_element(shown[1].begin(), shown[1].end()), 0.8) << "a hop's 3.8 measured the step";
    EXPECT_TRUE(near(shown[2], {0.640}));                      // 0.640 at every bounce
    EXPECT_EQ(labels()[2][3], "apex ratio\u00a00.640 at bounce\u00a07 (\u03b2\u00b2\u00a00.640)");
}

// Beside the dock of a selected sphere, four full labels (seven lines each) left the views
// thumbnails of 100 pixels at 1280 x 720: the window shows compact ones there, which keep
// what the slides compare (the title, E~, the penetration, the five properties) in four lines.
TEST(SideBySide, CompactLabelsKeepWhatTheSlidesCompare) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("16_bernoulli")));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 4);
    for (int frame = 0; frame < 60; ++frame) session.advance(1.0 / 60.0);
    const auto full = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Full);
    const auto compact = app::comparisonReadouts(simulation, *session.comparison(), app::LabelLines::Compact);
    ASSERT_EQ(compact.size(), 4u);
    EXPECT_EQ(full[1].size(), 7u);
    EXPECT_EQ(compact[1].size(), 4u);
    EXPECT_EQ(compact[1][0], full[1][0]);                                                 // B   solver = simultaneous
    EXPECT_EQ(compact[1][1], "E~\u00a00.875\u00a0J   penetration 0.00\u00a0%\u00a0r");  // grown 1.75 times
    EXPECT_EQ(compact[1][2], full[1][5]);                                                 // ✓ momentum  ✗ energy ...
    EXPECT_EQ(compact[1][3], full[1][6]);
}

// Side by side, each view's label says the most work its solver took in one step since the
// restart (the panel says the last step's, for view A only; a label of the last step read 0
// but in the frame of an impact): on Bernoulli's problem, lcp's sweeps in view C and the
// reflection rounds in view D, kept after the impact; nothing for the sequential passes.
TEST(SideBySide, EachViewsLabelSaysTheMostWorkItsSolverTookInAStep) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("16_bernoulli")));
    app::Session session(simulation);
    session.sceneChanged();
    ASSERT_EQ(session.runCount(), 4);
    std::uint64_t most = 0;
    for (int frame = 0; frame < 120; ++frame) {
        session.advance(1.0 / 60.0);
        most = std::max(most, session.run(2).lastStepStats().lcpSweeps);
    }
    ASSERT_GT(most, 0u) << "lcp swept nothing in 2 s";
    EXPECT_EQ(session.run(2).lastStepStats().lcpSweeps, 0u) << "the spheres have parted";
    const std::vector<app::ViewReadout> views = app::viewReadouts(simulation, *session.comparison());
    EXPECT_EQ(views[0].work, "");
    EXPECT_EQ(views[2].work, "most in one step: " + std::to_string(most) + "\u00a0lcp sweeps");
    EXPECT_EQ(views[3].work.rfind("most in one step: ", 0), 0u) << views[3].work;
    EXPECT_EQ(views[3].work, "most in one step: 1\u00a0reflection round") << "one round, said in the singular";
    const std::vector<std::string> label = app::viewReadoutLines(views[2]);
    EXPECT_NE(std::find(label.begin(), label.end(), views[2].work), label.end());
    simulation.restart();
    EXPECT_EQ(app::viewReadouts(simulation, *session.comparison())[0].work, "");
    EXPECT_EQ(simulation.mostWorkAStep().lcpSweeps, 0u);
}

// One view measures the claims at its settings; the list says how many more the text makes
// (at the settings it suggests, or a ratio of two runs) and that `spheres claims` measures
// them, so that "13 of 13" is not read as the whole text.
TEST(SideBySide, TheListSaysHowManyClaimsItLeavesToTheCommand) {
    const scenes::Scene scene = scenes::loadScene(scenes::presetPath("01_bounce_response_only"));
    app::Simulation simulation(scene);
    std::size_t atOtherSettings = 0;
    for (const scenes::Claim& c : scene.claims) {
        atOtherSettings += c.in == scenes::ClaimSource::Description && (!c.settings.empty() || c.ratioTo);
    }
    const ui::Readouts readouts = app::makeReadouts(simulation, ui::FrameTimes{});
    EXPECT_GT(readouts.claimsWatched, 0u);
    EXPECT_EQ(readouts.claimsElsewhere, atOtherSettings);
    EXPECT_GE(atOtherSettings, 2u) << "method=position, substeps=4, h=0.05 in its text";
}

// The side-by-side field offers, until the user writes there, the scene's own overrides,
// else the other of the slides' methods: method=velocity on the cradle (velocity based
// already) opened two identical views.
TEST(SideBySide, TheFieldOffersWhatChangesSomething) {
    const scenes::Scene cradle = scenes::loadScene(scenes::presetPath("08_newtons_cradle"));
    const scenes::Scene pile = scenes::loadScene(scenes::presetPath("11_pile"));
    const scenes::Scene column = scenes::loadScene(scenes::presetPath("21_shock_column"));
    EXPECT_EQ(app::suggestedOverrides(cradle), "method=position");
    EXPECT_EQ(app::suggestedOverrides(pile), "method=velocity");
    EXPECT_EQ(app::suggestedOverrides(column), "shock=off,on,passes=1,4");
    for (const scenes::Scene* scene : {&cradle, &pile}) {
        app::Simulation simulation(*scene);
        app::Session session(simulation);
        ASSERT_EQ(session.startComparison({app::suggestedOverrides(*scene)}), "");
        EXPECT_FALSE(session.comparison()->changesNothing(simulation.scene())) << scene->title;
    }
}
