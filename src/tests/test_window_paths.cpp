// The window's own code paths, headless: what the panel and the inspector call
// (Session::setParameter, Session::editSelected, Session::restart, stepping). Every
// preset x every parameter of the table x {min, max, 3 between, 2 out of range}, and
// every field of the inspector likewise: the session stays alive (nothing throws, so
// nothing ends the window), no value that is not finite enters the state, every
// refusal is a message and leaves the value as it was.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/run/interaction.h"
#include "app/views/frame_builder.h"
#include "app/window/interaction_input.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "ui/control_panel.h"
#include "ui/ui_font.h"

namespace {

// min, max, three between (evenly, or evenly in log for a wide positive range), and
// two out of range; for a choice every index and one beyond each end.
std::vector<double> valuesToTry(const scenes::Parameter& p) {
    if (p.kind == scenes::ParameterKind::Choice) {
        std::vector<double> values{-1.0, double(p.choices.size())};
        for (std::size_t k = 0; k < p.choices.size(); ++k) values.push_back(double(k));
        return values;
    }
    const bool logarithmic = p.min > 0.0 && p.max / p.min > 100.0;
    std::vector<double> values{p.min, p.max};
    for (double f : {0.25, 0.5, 0.75}) {
        double v = logarithmic ? p.min * std::pow(p.max / p.min, f) : p.min + f * (p.max - p.min);
        if (p.kind == scenes::ParameterKind::Integer) v = std::round(v);
        values.push_back(v);
    }
    const double span = std::max(1.0, p.max - p.min);
    values.push_back(p.min - 0.5 * span);
    values.push_back(p.max + 0.5 * span);
    return values;
}

bool finiteState(const physics::World& world) {
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (int a = 0; a < 3; ++a) {
            if (!std::isfinite(world.position[i][a]) || !std::isfinite(world.velocity[i][a])) return false;
        }
    }
    return true;
}

// A few steps of the window (a frame of 1/30 s, then a single step).
void stepLikeTheWindow(app::Session& session) {
    session.advance(1.0 / 30.0);
    session.singleStep();
}

struct Tally {
    int tried = 0, refused = 0;
};

TEST(WindowPaths, EveryParameterOfEveryPresetIsAppliedOrRefusedWithAMessage) {
    Tally tally;
    for (const std::string& name : scenes::listPresets()) {
        app::Simulation simulation(scenes::loadScene(scenes::presetPath(name)));
        app::Session session(simulation);
        for (const scenes::Parameter& p : scenes::parameterTable()) {
            if (!p.availableIn(simulation.scene())) continue;
            const double original = p.get(simulation.scene());
            for (double value : valuesToTry(p)) {
                SCOPED_TRACE(name + ": " + std::string(p.name) + " = " + scenes::formatNumber(value));
                const std::string before = scenes::formatValue(p, simulation.scene());
                const bool inRange = scenes::checkValue(p, value).empty();
                std::string refusal;
                ++tally.tried;
                ASSERT_NO_THROW(refusal = session.setParameter(p, value));
                if (!refusal.empty()) {
                    ++tally.refused;
                    EXPECT_EQ(scenes::formatValue(p, simulation.scene()), before) << "refused, yet changed";
                } else {
                    EXPECT_TRUE(inRange) << "out of range, yet taken";
                    EXPECT_EQ(p.get(simulation.scene()), value);
                }
                ASSERT_NO_THROW(session.restart());
                ASSERT_NO_THROW(stepLikeTheWindow(session));
                ASSERT_TRUE(finiteState(simulation.world())) << "a value not finite entered the state";
            }
            ASSERT_EQ(session.setParameter(p, original), "") << name << ": " << p.name << " back to the preset's";
        }
    }
    // Every out-of-range value at least (two per parameter) was refused.
    EXPECT_GT(tally.refused, tally.tried / 5);
    std::printf("window paths: %d values tried, %d refused with a message\n", tally.tried, tally.refused);
}

// The first finding of the student's session: the pile's N dragged to 7 483. Refused
// where it was entered, with the limit; the pile, its timeline and settings stay.
TEST(WindowPaths, ACountThePileCannotHoldIsRefusedWithItsLimitAndTheRunGoesOn) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("11_pile")));
    app::Session session(simulation);
    stepLikeTheWindow(session);
    const std::uint64_t steps = simulation.world().stepCount;
    const scenes::Parameter& count = *scenes::findParameter("count");
    const std::string refusal = session.setParameter(count, 7483);
    EXPECT_NE(refusal.find("count = 7483 refused (it stays 1000): the region holds only 1764"), std::string::npos) << refusal;
    EXPECT_EQ(count.get(simulation.scene()), 1000.0);
    EXPECT_EQ(simulation.world().size(), 1000u);
    EXPECT_EQ(simulation.world().stepCount, steps) << "the running pile was not restarted";
    EXPECT_EQ(session.setParameter(count, 1500), "");
    EXPECT_EQ(simulation.world().size(), 1500u);
}

// Each field of the inspector: x, y, z of p and v, r, m; the same values as above.
struct Field {
    const char* name;
    double lo, hi;  // the range the window takes for it
    double* (*of)(app::SphereFields&);
};

TEST(WindowPaths, EveryInspectorFieldOfEveryPresetIsAppliedOrRefusedWithAMessage) {
    Tally tally;
    for (const std::string& name : scenes::listPresets()) {
        const scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
        if (!scene.box) continue;  // the fields of p are tried within the box
        app::Simulation simulation(scene);
        app::Session session(simulation);
        if (simulation.world().size() == 0) continue;  // the rain starts empty: nothing to select
        const glm::dvec3 half = 0.5 * scene.box->size;
        const std::vector<Field> fields{
            {"p.x", -half.x, half.x, [](app::SphereFields& f) { return &f.p.x; }},
            {"p.y", -half.y, half.y, [](app::SphereFields& f) { return &f.p.y; }},
            {"p.z", 0.0, scene.box->size.z, [](app::SphereFields& f) { return &f.p.z; }},
            {"v.x", -app::kEditSpeed, app::kEditSpeed, [](app::SphereFields& f) { return &f.v.x; }},
            {"v.y", -app::kEditSpeed, app::kEditSpeed, [](app::SphereFields& f) { return &f.v.y; }},
            {"v.z", -app::kEditSpeed, app::kEditSpeed, [](app::SphereFields& f) { return &f.v.z; }},
            {"r", app::kEditRadius[0], app::kEditRadius[1], [](app::SphereFields& f) { return &f.r; }},
            {"m", app::kEditMass[0], app::kEditMass[1], [](app::SphereFields& f) { return &f.m; }},
        };
        for (const Field& field : fields) {
            const double span = field.hi - field.lo;
            for (double value : {field.lo, field.hi, field.lo + 0.25 * span, field.lo + 0.5 * span,
                                 field.lo + 0.75 * span, field.lo - 0.5 * span - 1.0, field.hi + 0.5 * span + 1.0,
                                 std::nan("")}) {
                SCOPED_TRACE(name + ": " + field.name + " = " + scenes::formatNumber(value));
                session.restart();
                session.select(0);
                const physics::World& world = simulation.world();
                app::SphereFields edit{world.position[0], world.velocity[0], world.radius[0], world.mass[0]};
                *field.of(edit) = value;
                const std::uint64_t hashBefore = physics::stateHash(world);
                std::string refusal;
                ++tally.tried;
                ASSERT_NO_THROW(refusal = session.editSelected(edit));
                if (!refusal.empty()) {
                    ++tally.refused;
                    EXPECT_EQ(physics::stateHash(world), hashBefore) << "refused, yet changed";
                } else {
                    EXPECT_TRUE(app::checkSphereFields(world, edit).empty());
                    EXPECT_EQ(*field.of(edit), value);
                }
                ASSERT_NO_THROW(stepLikeTheWindow(session));
                ASSERT_TRUE(finiteState(simulation.world())) << "a value not finite entered the state";
            }
        }
    }
    EXPECT_GT(tally.refused, tally.tried / 5);
    std::printf("inspector paths: %d values tried, %d refused with a message\n", tally.tried, tally.refused);
}

// The second finding: r = 5 m in a box about 3 m wide is refused with the radius that fits.
TEST(WindowPaths, TheInspectorRefusesARadiusTheBoxCannotHoldAndSaysWhatFits) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("11_pile")));
    app::Session session(simulation);
    session.select(0);
    const physics::World& world = simulation.world();
    const double radius = world.radius[0];
    app::SphereFields edit{world.position[0], world.velocity[0], 5.0, world.mass[0]};
    EXPECT_NE(session.editSelected(edit).find("r = 5 m is outside 0.005 to 0.5 m"), std::string::npos);
    edit.r = 0.5;  // in range, but sphere 0 sits near the floor
    const std::string refusal = session.editSelected(edit);
    EXPECT_NE(refusal.find("a sphere of r = 0.5 m crosses a wall; at most r = "), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("at p = ("), std::string::npos) << refusal;
    EXPECT_EQ(world.radius[0], radius);
}

}  // namespace

namespace {

// Side by side: Enter in the overrides' field applies the new overrides while it is
// on; overrides that change nothing say that the two views are the same.
TEST(WindowPaths, SideBySideTakesNewOverridesOnEnterAndSaysWhenTheViewsAreTheSame) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("08_newtons_cradle")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    EXPECT_EQ(input.tools().compareText, "method=position");  // offered: not the cradle's own method
    input.tools().compareText = "method=velocity";  // typed: the cradle's own method
    ASSERT_TRUE(input.applyCompare(0.0));
    ASSERT_NE(session.comparison(), nullptr);
    EXPECT_NE(input.tools().message.find("method = velocity in both views"), std::string::npos)
        << input.tools().message;
    EXPECT_NE(input.tools().message.find("the two views are the same"), std::string::npos) << input.tools().message;

    input.tools().compareText = "order=reversed,passes=1";  // edited, then Enter (the cradle runs 1 pass too)
    app::ToolActions enter;
    enter.applyCompare = true;
    input.apply(enter, app::ViewLayout{}, render::Camera{}, 1.0);
    EXPECT_EQ(session.comparison()->label(), "order = reversed, passes = 1");
    EXPECT_EQ(session.run(1).scene().params.passes, 1);
    EXPECT_NE(input.tools().message.find("order = index, passes = 1 against order = reversed, passes = 1"),
              std::string::npos)
        << input.tools().message;

    input.tools().compareText = "order=sideways";  // refused: the runs stay as they were
    input.apply(enter, app::ViewLayout{}, render::Camera{}, 3.0);
    EXPECT_NE(input.tools().message.find("cannot compare"), std::string::npos) << input.tools().message;
    EXPECT_EQ(session.comparison()->label(), "order = reversed, passes = 1");
}

// The bar offers the other method on a scene without a "compare" of its own, the scene's
// own otherwise, and keeps what the user wrote from scene to scene.
TEST(WindowPaths, TheOverridesOfferedFollowTheSceneUntilTheUserWritesThere) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("08_newtons_cradle")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    EXPECT_EQ(input.tools().compareText, "method=position");
    const auto open = [&](const char* preset) {
        simulation.setScene(scenes::loadScene(scenes::presetPath(preset)));
        input.sceneChanged();
        return input.tools().compareText;
    };
    EXPECT_EQ(open("11_pile"), "method=velocity");
    EXPECT_EQ(open("21_shock_column"), "shock=off,on,passes=1,4");
    EXPECT_EQ(open("08_newtons_cradle"), "method=position");
    input.tools().compareText = "order=reversed";  // written
    EXPECT_EQ(open("11_pile"), "order=reversed");
}

// The window opened on a scene with its own "compare" (14's three answers) stops that side
// by side at the next preset, as one opened with [ ] does: started as the command line's
// --compare, 14's three views had stayed on 13 and on 01 (22's). One asked with --compare stays.
TEST(WindowPaths, TheFirstScenesOwnSideBySideStopsAtTheNextPreset) {
    const auto views = [](const app::Session& session) { return session.comparison() ? session.comparison()->count() + 1 : 1; };
    for (const bool asked : {false, true}) {
        app::Simulation simulation(scenes::loadScene(scenes::presetPath("14_three_answers")));
        app::Session session(simulation);
        app::InteractionInput input(session);
        const std::vector<std::string> compare = asked ? std::vector<std::string>{"beta=0.5"} : std::vector<std::string>{};
        ASSERT_EQ(input.openFirstScene(compare), "");
        EXPECT_EQ(views(session), asked ? 2 : 3);
        simulation.openScene(scenes::loadScene(scenes::presetPath("13_tunnelling")));
        input.sceneChanged();
        EXPECT_EQ(views(session), asked ? 2 : 1) << (asked ? "--compare beta=0.5" : "14's own");
    }
    // A scene's own side by side that its settings refuse is said, not dropped: 22's shock
    // views with --set method=response-only (shock acts only with the position, velocity or
    // reflection method).
    scenes::Scene pyramid = scenes::loadScene(scenes::presetPath("22_shock_pyramid"));
    ASSERT_EQ(scenes::applySetting(pyramid, "method=response-only"), "");
    app::Simulation simulation(std::move(pyramid));
    app::Session session(simulation);
    app::InteractionInput input(session);
    EXPECT_NE(input.openFirstScene({}).find("shock"), std::string::npos);
}

// Side by side with the offer, the next scene's offer replaces it ([ and ]): the cradle's
// "method=position" kept on the pile had compared the velocity method with itself, one run in
// two views (a student read that the setting changed nothing). Overrides the user wrote stay.
TEST(WindowPaths, SideBySideWithTheOfferFollowsTheNextScenesOffer) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("08_newtons_cradle")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    const auto open = [&](const char* preset) {
        simulation.setScene(scenes::loadScene(scenes::presetPath(preset)));
        input.sceneChanged();
        return session.comparison() ? session.comparison()->label() : std::string("one view");
    };
    ASSERT_TRUE(input.applyCompare(0.0));  // V: the offer, method=position
    EXPECT_EQ(open("11_pile"), "method = velocity");
    EXPECT_FALSE(session.comparison()->changesNothing(session.run(0).scene()));
    open("21_shock_column");
    EXPECT_EQ(session.comparison()->count(), 3) << "the scene's own four views";
    EXPECT_EQ(open("11_pile"), "one view") << "a scene's own views close with it";
    input.tools().compareText = "passes=1";  // written
    ASSERT_TRUE(input.applyCompare(1.0));
    EXPECT_EQ(open("09_column"), "passes = 1");
}

// Esc backs out one level at a time (the window leaves the presentation layout first):
// the explainer, then the selection, then nothing, which it reports so the window can say
// how to quit instead of quitting.
TEST(WindowPaths, EscClosesTheExplainerThenTheSelectionThenNothing) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("09_column")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    session.select(3);
    input.toggleExplainer();
    ASSERT_TRUE(input.tools().explainer);
    EXPECT_TRUE(input.backOut());
    EXPECT_FALSE(input.tools().explainer);
    EXPECT_EQ(session.selected(), 3);
    EXPECT_TRUE(input.backOut());
    EXPECT_EQ(session.selected(), -1);
    EXPECT_FALSE(input.backOut());
    EXPECT_FALSE(input.backOut());
    EXPECT_EQ(session.selected(), -1);
}

namespace {

// An ImGui context for a display of `size` (window units), its font built, drawing nowhere.
ImGuiContext* headlessImGui(ImVec2 size) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = size;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    return context;
}

// One click of the left button at `at` (window units): pressed in a frame, released in the next.
void clickAt(app::InteractionInput& input, const app::ViewLayout& views, const render::Camera& camera, ImVec2 at) {
    ImGuiIO& io = ImGui::GetIO();
    for (const bool down : {true, false}) {
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = at;
        io.MouseDown[ImGuiMouseButton_Left] = down;
        ImGui::NewFrame();
        input.handleMouse(views, camera, 0.0);
        ImGui::EndFrame();
    }
}

}  // namespace

// A teacher explaining a contact clicks at a moving sphere and misses it: the explanation
// stays, with a line that says so (before, the click deselected and the contact was lost).
// With the explanation closed, a click on nothing deselects as before.
TEST(WindowPaths, AClickThatMissesASphereKeepsTheExplanation) {
    ImGuiContext* context = headlessImGui(ImVec2(800.0f, 600.0f));
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("09_column")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    app::ViewLayout views;
    views.framebuffer = {800, 600};
    views.views[0] = {0, 0, 800, 600};
    render::Camera camera;
    camera.reset(glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 1.0f, 2.0f), views.aspect());
    const ImVec2 sky(5.0f, 5.0f);  // the top left corner: above the box
    ASSERT_LT(app::pickSphere(simulation.world(), views.ray(camera, 0, glm::vec2(sky.x, sky.y))), 0);
    input.toggleExplainer();  // E with nothing selected: said, not ignored
    EXPECT_FALSE(input.tools().explainer);
    EXPECT_NE(input.tools().message.find("click a sphere first"), std::string::npos) << input.tools().message;
    session.select(3);
    input.toggleExplainer();
    clickAt(input, views, camera, sky);
    EXPECT_EQ(session.selected(), 3);
    EXPECT_TRUE(input.tools().explainer);
    EXPECT_NE(input.tools().message.find("no sphere there: the explanation of #3 stays"), std::string::npos)
        << input.tools().message;
    input.toggleExplainer();
    clickAt(input, views, camera, sky);
    EXPECT_EQ(session.selected(), -1);
    ImGui::DestroyContext(context);
}


// F12's confirmation lies over the lower views' spheres: it goes after 2 s, where a result
// or a refusal stays 8 (in front of a class, it stayed in the next screenshot too).
TEST(WindowPaths, AScreenshotsConfirmationGoesSoonerThanARefusal) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("09_column")));
    app::Session session(simulation);
    app::InteractionInput input(session);
    input.sayBriefly(10.0, "saved screenshot_0001.png");
    input.expireMessage(11.5);
    EXPECT_EQ(input.tools().message, "saved screenshot_0001.png");
    input.expireMessage(12.5);
    EXPECT_EQ(input.tools().message, "");
    input.say(20.0, "cannot %s", "shoot here");
    input.expireMessage(27.0);
    EXPECT_EQ(input.tools().message, "cannot shoot here") << "a refusal stays as long as before";
    input.expireMessage(28.5);
    EXPECT_EQ(input.tools().message, "");
}

// The unfolded claims' list holds still while the pointer is over the panel (a new line
// would push the sliders under it), and then says how many it will add: a teacher who left
// the pointer on the panel read "9 of 9 measured" above a list of 4 and "5 more are measured
// as the run reaches their moment (the last at t = 10 s)", at t = 25 s.
TEST(WindowPaths, TheHeldClaimsListSaysHowManyMoreWereMeasured) {
    ImGuiContext* context = headlessImGui(ImVec2(1280.0f, 800.0f));
    ImGuiIO& io = ImGui::GetIO();
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("13_tunnelling")));
    ui::PanelState state;
    double timeScale = 1.0;
    const auto frame = [&](ImVec2 pointer, bool down) {
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = pointer;
        io.MouseDown[ImGuiMouseButton_Left] = down;
        ImGui::NewFrame();
        ui::drawControlPanel(simulation.scene(), timeScale, app::makeReadouts(simulation, ui::FrameTimes{}), state, {});
        ImGui::EndFrame();
    };
    // The header is the first control under the scene's text: clicked down the panel until
    // the list unfolds.
    ImVec2 header(100.0f, 30.0f);
    for (; header.y < 500.0f && !state.claimsWereOpen; header.y += 8.0f) {
        frame(header, true);
        frame(header, false);
        frame(header, false);
    }
    ASSERT_TRUE(state.claimsWereOpen) << "no claims' header found";
    frame(header, false);
    const std::size_t shown = state.claimsMeasuredShown;
    ASSERT_LT(shown, simulation.claimsWatched());
    while (simulation.world().time < 12.0) simulation.singleStep();  // every moment passed
    frame(header, false);
    EXPECT_EQ(state.claimsMeasuredShown, shown) << "the list moved under the pointer";
    ASSERT_GT(state.claimLinesShown.size(), shown);
    const std::string more = std::to_string(simulation.claimsWatched() - shown) + " more measured since";
    EXPECT_EQ(state.claimLinesShown[shown].first.rfind(more, 0), 0u) << state.claimLinesShown[shown].first;
    frame(ImVec2(900.0f, 400.0f), false);  // the pointer leaves: the list shows them
    EXPECT_EQ(state.claimsMeasuredShown, simulation.claimsWatched());
    ImGui::DestroyContext(context);
}

// Presenting, the texts of 14 and 18-22 are longer than the panel: their conclusions are
// below the fold. Page Down (what a presenter's remote sends) moves the text on by a page
// less a line, in whole lines, so that the line under the fold comes to the top; Page Up
// goes back; the scroll stops at the text's end.
TEST(WindowPaths, PageDownMovesThePresentedTextOnByAPageInWholeLines) {
    // A low window (a projector's 1024 x 576 at the 720 lines' type), so that the text is
    // more than two pages.
    ImGuiContext* context = headlessImGui(ImVec2(1024.0f, 576.0f));
    ui::applyStyle(ui::presentedScale(1.0f, 576.0f));  // the presented type, as the window sets it
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("22_shock_pyramid")));
    ui::PanelState state;
    state.present = true;
    double timeScale = 1.0;
    const auto frame = [&] {
        ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
        ImGui::NewFrame();
        ui::drawControlPanel(simulation.scene(), timeScale, app::makeReadouts(simulation, ui::FrameTimes{}), state, {});
        ImGui::EndFrame();
    };
    const auto pages = [&](int count) {
        state.pagesToScroll = count;
        frame();
        frame();  // ImGui moves the scroll at the next frame's start
        EXPECT_EQ(state.pagesToScroll, 0);
        return state.textScrollY;
    };
    for (int k = 0; k < 3; ++k) frame();
    ASSERT_EQ(state.textScrollY, 0.0f);
    const float line = ImGui::GetFontSize();
    const float first = pages(1);
    EXPECT_GT(first, 4.0f * line) << "a page is several lines";
    EXPECT_LT(std::abs(first - std::round(first / line) * line), 1.0f) << "whole lines (ImGui scrolls by whole pixels)";
    EXPECT_LT(first, state.presentedContentHeight);
    EXPECT_EQ(pages(-1), 0.0f);
    float last = 0.0f;
    for (int k = 0; k < 20; ++k) last = pages(1);  // far past the end: it stops there
    EXPECT_GT(last, first);
    EXPECT_EQ(pages(1), last) << "no page past the text's end";
    // A new scene opens at its top, whatever was pressed in the same frame.
    state.scrollToTop = true;
    EXPECT_EQ(pages(1), 0.0f);
    // Hidden, the panel keeps no presses for later.
    state.visible = false;
    state.pagesToScroll = 3;
    frame();
    state.visible = true;
    frame();
    frame();
    EXPECT_EQ(state.textScrollY, 0.0f);
    // The full panel (all its controls: longer than the window) pages too.
    state.present = false;
    for (int k = 0; k < 3; ++k) frame();
    const float full = pages(1);
    EXPECT_GT(full, 4.0f * line);
    EXPECT_LT(full, 576.0f) << "less than the window";
    EXPECT_EQ(pages(-1), 0.0f);
    ImGui::DestroyContext(context);
}

}  // namespace
