// The window's layout (app/views/window_layout.h) without a window: nothing a
// teacher opens may cover the views, the dock goes where the box stays largest, and
// the views side by side make the grid (and label places) that keep each one largest.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>  // ImGui::FindWindowByName: the tooltip's window

#include "app/views/window_layout.h"
#include "app/window/short_key_presses.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "ui/control_panel.h"
#include "ui/tooltip_timing.h"
#include "ui/wrapped_text.h"

namespace {

using app::Rect;

constexpr float kFont = 17.0f;  // ImGui units, UI scale 1

bool overlap(const Rect& a, const Rect& b) {
    return !a.empty() && !b.empty() && a.min.x < b.max().x - 0.5f && b.min.x < a.max().x - 0.5f &&
           a.min.y < b.max().y - 0.5f && b.min.y < a.max().y - 0.5f;
}

bool inside(const Rect& inner, const Rect& outer) {
    return inner.min.x >= outer.min.x - 0.5f && inner.min.y >= outer.min.y - 0.5f &&
           inner.max().x <= outer.max().x + 0.5f && inner.max().y <= outer.max().y + 0.5f;
}

// The window as a teacher finds it: the panel, the bar, the readouts' line.
app::LayoutRequest request(glm::vec2 window, float scale = 1.0f) {
    app::LayoutRequest q;
    q.window = window;
    q.font = kFont * scale;
    q.panelWidth = std::min(25.0f * q.font, 0.45f * window.x);
    q.barHeight = 2.5f * q.font + 16.0f * scale;
    q.readoutsLine = 1.4f * q.font;
    return q;
}

// Every rectangle a window lays out other than the views.
std::vector<Rect> panels(const app::WindowLayout& l) {
    std::vector<Rect> all{l.panel, l.readoutsLine, l.timeline, l.inspector, l.explainer, l.readouts};
    for (int k = 0; k < l.views.count; ++k) all.push_back(l.labels[k]);
    return all;
}

void expectNothingCoversTheViews(const app::LayoutRequest& q, const std::string& what) {
    const app::WindowLayout l = app::layoutWindow(q);
    const Rect window{{0.0f, 0.0f}, q.window};
    ASSERT_EQ(l.views.count, q.views) << what;
    for (int k = 0; k < l.views.count; ++k) {
        const Rect view = l.views.rect(k);
        EXPECT_TRUE(inside(view, window)) << what << " view " << k;
        EXPECT_GT(view.size.x, 50.0f) << what << " view " << k;
        EXPECT_GT(view.size.y, 50.0f) << what << " view " << k;
        for (const Rect& panel : panels(l)) EXPECT_FALSE(overlap(view, panel)) << what << " view " << k;
        for (int j = 0; j < k; ++j) EXPECT_FALSE(overlap(view, l.views.rect(j))) << what << " views " << j << k;
    }
    for (const Rect& panel : panels(l)) EXPECT_TRUE(panel.empty() || inside(panel, window)) << what;
    // The dock's windows lie in the dock and do not cover each other.
    for (const Rect* w : {&l.inspector, &l.explainer, &l.readouts}) {
        EXPECT_TRUE(w->empty() || inside(*w, l.dock)) << what;
    }
    EXPECT_FALSE(overlap(l.inspector, l.explainer)) << what;
    EXPECT_FALSE(overlap(l.explainer, l.readouts)) << what;
    EXPECT_FALSE(overlap(l.inspector, l.readouts)) << what;
}

}  // namespace

// Projector sizes and a HiDPI screen, with every combination of what a teacher may
// open: no view lies under a panel, a label, a bar or a docked window.
TEST(WindowLayout, NothingCoversTheViewsAtAnyClassroomSize) {
    struct Size {
        glm::vec2 window;
        float pixelsPerUnit;
    };
    const Size sizes[] = {{{1024, 768}, 1}, {{1280, 720}, 1}, {{1280, 800}, 1}, {{1920, 1080}, 1}, {{1280, 720}, 2}};
    for (const Size& size : sizes) {
        for (int open = 0; open < 8; ++open) {
            for (int views = 1; views <= app::kMostViews; views += 3) {
                app::LayoutRequest q = request(size.window);
                q.pixelsPerUnit = glm::vec2(size.pixelsPerUnit);
                q.inspectorHeight = (open & 1) ? 9.0f * kFont : 0.0f;
                q.explainer = (open & 2) != 0;
                q.readouts = (open & 4) != 0;
                if (q.readouts) q.readoutsLine = 0.0f;
                q.views = views;
                q.labelWidth = 17.0f * kFont;
                q.labelHeight = [](float width) { return 8.0f * kFont * std::max(1.0f, 17.0f * kFont / width); };
                expectNothingCoversTheViews(q, std::to_string(int(size.window.x)) + "x" +
                                                   std::to_string(int(size.window.y)) + " open " +
                                                   std::to_string(open) + " views " + std::to_string(views));
            }
        }
    }
}

// The readouts start as one line along the top; unfolded they take the dock.
TEST(WindowLayout, FoldedReadoutsAreALineOnTopAndUnfoldedOnesTakeTheDock) {
    app::LayoutRequest q = request({1280, 720});
    const app::WindowLayout folded = app::layoutWindow(q);
    EXPECT_EQ(folded.readoutsLine.min, glm::vec2(q.panelWidth, 0.0f));
    EXPECT_EQ(folded.readoutsLine.size, glm::vec2(1280.0f - q.panelWidth, q.readoutsLine));
    EXPECT_TRUE(folded.dock.empty());
    EXPECT_EQ(folded.scene.min, glm::vec2(q.panelWidth, q.readoutsLine));
    EXPECT_EQ(folded.scene.max(), glm::vec2(1280.0f, 720.0f - q.barHeight));
    q.readoutsLine = 0.0f;
    q.readouts = true;
    const app::WindowLayout open = app::layoutWindow(q);
    EXPECT_FALSE(open.readouts.empty());
    EXPECT_EQ(open.readouts.size.y, open.dock.size.y);
    EXPECT_TRUE(open.readoutsLine.empty());
}

// The explanation beside the view where the window is wide, under it where it is not:
// whichever leaves the box larger. On a 4:3 projector a column of 32 font sizes would
// leave the view a sliver; on a wide screen the column costs the box nothing.
TEST(WindowLayout, TheDockGoesWhereTheBoxStaysLargest) {
    app::LayoutRequest narrow = request({1024, 768});
    narrow.inspectorHeight = 9.0f * kFont;
    narrow.explainer = true;
    const app::WindowLayout a = app::layoutWindow(narrow);
    EXPECT_TRUE(a.dockAtBottom);
    EXPECT_EQ(a.inspector.min, a.dock.min);                   // the inspector on the left of the strip
    EXPECT_EQ(a.explainer.min.x, a.inspector.max().x);        // the explanation beside it
    EXPECT_FLOAT_EQ(a.explainer.max().x, 1024.0f);
    EXPECT_FLOAT_EQ(a.dock.max().y, 768.0f - narrow.barHeight);  // on the bar

    app::LayoutRequest wide = request({1920, 1080});
    wide.inspectorHeight = 9.0f * kFont;
    wide.explainer = true;
    const app::WindowLayout b = app::layoutWindow(wide);
    EXPECT_FALSE(b.dockAtBottom);
    EXPECT_FLOAT_EQ(b.dock.max().x, 1920.0f);
    EXPECT_FLOAT_EQ(b.dock.size.x, app::kExplainerFonts * kFont);
    EXPECT_EQ(b.inspector.min, b.dock.min);                   // the inspector above the explanation
    EXPECT_FLOAT_EQ(b.inspector.size.y, 9.0f * kFont);
    EXPECT_FLOAT_EQ(b.explainer.min.y, b.inspector.max().y);
    EXPECT_FLOAT_EQ(b.explainer.max().y, b.dock.max().y);
    // A tall box (the column, 0.45 as wide as high) keeps the column on the right at 1024 too.
    narrow.boxAspect = 0.45f;
    EXPECT_FALSE(app::layoutWindow(narrow).dockAtBottom);
}

// Three views in a row on a wide area, four in two rows with A at the top left; the
// last column and row reach the area's edges.
TEST(WindowLayout, ViewsMakeTheGridThatKeepsEachViewLargest) {
    glm::ivec4 views[app::kMostViews], labels[app::kMostViews];
    app::arrangeViews({0, 0, 1920, 600}, 3, 4, 0, {}, 1.0f, views, labels);
    EXPECT_EQ(views[0], glm::ivec4(0, 0, 637, 600));
    EXPECT_EQ(views[2], glm::ivec4(1282, 0, 638, 600));
    app::arrangeViews({400, 60, 880, 740}, 4, 4, 0, {}, 1.0f, views, labels);
    EXPECT_EQ(views[0], glm::ivec4(400, 432, 438, 368));  // top left
    EXPECT_EQ(views[1], glm::ivec4(842, 432, 438, 368));
    EXPECT_EQ(views[3], glm::ivec4(842, 60, 438, 368));   // bottom right
    app::arrangeViews({400, 60, 880, 740}, 2, 4, 0, {}, 1.0f, views, labels);
    EXPECT_EQ(views[0], glm::ivec4(400, 60, 438, 740));
    EXPECT_EQ(views[1], glm::ivec4(842, 60, 438, 740));
}

// Labels take the room the box does not use: four views of the column (a tall box)
// stand in one row with each label above its view; two views of a wide box lie one
// above the other with each label beside its view. Never over it.
TEST(WindowLayout, LabelsTakeTheRoomTheBoxDoesNotUse) {
    glm::ivec4 views[app::kMostViews], labels[app::kMostViews];
    // Seven lines of readouts, 300 px wide; narrower, each line wraps in two.
    const app::LabelHeight label = [](int width) { return width >= 300 ? 160 : 320; };
    const float tall = app::arrangeViews({0, 0, 1280, 800}, 4, 4, 300, label, 0.45f, views, labels);
    EXPECT_EQ(labels[0], glm::ivec4(0, 640, 317, 160));  // above view A
    EXPECT_EQ(views[0], glm::ivec4(0, 0, 317, 640));
    EXPECT_EQ(views[3], glm::ivec4(963, 0, 317, 640));
    EXPECT_FLOAT_EQ(tall, 640.0f);  // px: in a 2 x 2 grid the box would be 398 high
    const float wide = app::arrangeViews({0, 0, 1280, 800}, 2, 4, 300, label, 2.0f, views, labels);
    EXPECT_EQ(labels[0], glm::ivec4(0, 402, 300, 398));  // left of view A, at the top
    EXPECT_EQ(views[0], glm::ivec4(300, 402, 980, 398));
    EXPECT_EQ(views[1], glm::ivec4(300, 0, 980, 398));
    EXPECT_FLOAT_EQ(wide, 398.0f);
    // Beside its view a label needs its lines' height: two rows of 148 px would have left
    // each box 148 px high and cut 200 px of label (18's "✗ break-away" at 1280 x 768);
    // one row of four keeps the labels whole beside boxes of 147.
    const app::LabelHeight lines = [](int) { return 200; };
    const float whole = app::arrangeViews({0, 0, 1200, 300}, 4, 4, 150, lines, 1.0f, views, labels);
    EXPECT_EQ(views[3].y, views[0].y) << "one row";
    EXPECT_EQ(labels[0].w, 300);
    EXPECT_FLOAT_EQ(whole, 147.0f);
}

// The box's aspect on screen: a cube seen from the default angles (from above: its
// top shows) is about as wide as high; the column's box (1 x 1 x 2.5 m) is tall.
TEST(WindowLayout, TheBoxAspectFollowsTheBoxAndTheAngles) {
    const render::Camera camera;
    const float cube = app::boxAspectOnScreen(camera, glm::vec3(-1, -1, 0), glm::vec3(1, 1, 2));
    EXPECT_NEAR(cube, 0.93f, 0.01f);
    const float column = app::boxAspectOnScreen(camera, glm::vec3(-0.5f, -0.5f, 0), glm::vec3(0.5f, 0.5f, 2.5f));
    EXPECT_NEAR(column, 0.48f, 0.01f);
}

// The panel's and the labels' text wraps at spaces, never beside '=' (a view's label
// "A shock = off, passes = 1" broke into "passes =" / "1"), and a word wider than the
// line (a hash in a narrow label) is cut where the line is full rather than clipped, or after a
// hyphen when it has one ("generalized-reflections" in a view a quarter of a projector wide).
TEST(WrappedText, KeepsNameEqualsValueWholeAndCutsAWordWiderThanTheLine) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // writes no imgui.ini where the tests run
    io.DisplaySize = ImVec2(800.0f, 600.0f);
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // builds the default font
    ImGui::NewFrame();
    const float glyph = ImGui::CalcTextSize("0").x;  // the default font's digits are all as wide
    EXPECT_EQ(ui::wrapAtSpaces("shock = off, passes = 1", ImGui::CalcTextSize("shock = off, passes =").x),
              "shock = off,\npasses = 1");
    EXPECT_EQ(ui::wrapAtSpaces("hash bf78370cf05532d3", 10.5f * glyph), "hash\nbf78370cf0\n5532d3");
    EXPECT_EQ(ui::wrapAtSpaces("files go to /tmp/a/b", ImGui::CalcTextSize("files go to /tmp/").x), "files go to\n/tmp/a/b");
    // A name too wide for a narrow view's label, kept whole with its value by '=': after its hyphen.
    EXPECT_EQ(ui::wrapAtSpaces("D solver = generalized-reflections", ImGui::CalcTextSize("solver = generalized-").x),
              "D\nsolver = generalized-\nreflections");
    EXPECT_EQ(ui::wrapAtSpaces("B method = reflection", ImGui::CalcTextSize("method = reflec").x),
              "B\nmethod =\nreflection");  // rather than clipped
    EXPECT_EQ(ui::wrapAtSpaces("c = -0.8660 m/s", ImGui::CalcTextSize("c = -0.8").x), "c =\n-0.8660\nm/s");  // not "-" / "0.8660"
    // A number keeps its unit and a formula its operators (a projector's text read "0.87" /
    // "m/s", "v ←" / "μ v", "|g| h /" / "substeps"), and a short last word takes the one before
    // it ("v2⊥." alone under a paragraph).
    EXPECT_EQ(ui::wrapAtSpaces("leave at 0.87 m/s now", ImGui::CalcTextSize("leave at 0.87 m").x), "leave at\n0.87 m/s now");
    EXPECT_EQ(ui::wrapAtSpaces("slows it: v \u2190 \u03bc v", ImGui::CalcTextSize("slows it: v \u2190").x),
              "slows it:\nv \u2190 \u03bc v");
    EXPECT_EQ(ui::wrapAtSpaces("adds |g| h / substeps", ImGui::CalcTextSize("adds |g| h /").x), "adds |g|\nh / substeps");
    EXPECT_EQ(ui::wrapAtSpaces("one two three four five six", ImGui::CalcTextSize("one two three four five").x),
              "one two three four\nfive six");
    EXPECT_EQ(ui::wrapAtSpaces("one two three four a-long-last-word", ImGui::CalcTextSize("one two three four a-long").x),
              "one two three four\na-long-last-word") << "a long last word stays alone";
    // The widest word, as the wrapping sees words (what a label's type is made smaller for):
    // "shock = off," is one, and so is a mark with its name.
    EXPECT_EQ(ui::widestWord("A shock = off, passes = 1\n\u2717\u00a0pos"),
              std::max(ImGui::CalcTextSize("shock = off,").x, ImGui::CalcTextSize("\u2717\u00a0pos").x));
    EXPECT_EQ(ui::widestWord("hash bf78370cf05532d3"), ImGui::CalcTextSize("bf78370cf05532d3").x);
    EXPECT_EQ(ui::widestWord("generalized-reflections"), ImGui::CalcTextSize("generalized-").x);
    // Up to a width: a hash too wide for any type a label takes does not hide the words that fit.
    EXPECT_EQ(ui::widestWord("hash bf78370cf05532d3 momentum", ImGui::CalcTextSize("momentum").x),
              ImGui::CalcTextSize("momentum").x);
    ImGui::EndFrame();
    ImGui::DestroyContext(context);
}

// An ImGui context of a display's size (px) with the default font, for the panel's layout.
struct ImGuiWithoutAWindow {
    ImGuiContext* context = ImGui::CreateContext();
    ImGuiWithoutAWindow(float width, float height) {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // writes no imgui.ini where the tests run
        io.DisplaySize = ImVec2(width, height);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the default font
    }
    ~ImGuiWithoutAWindow() { ImGui::DestroyContext(context); }
    ImGuiWithoutAWindow(const ImGuiWithoutAWindow&) = delete;
    ImGuiWithoutAWindow& operator=(const ImGuiWithoutAWindow&) = delete;
};

// A tooltip stays on the display: a view label's five properties, in a projector's large
// type, ran off its right side and its foot. Wrapped at 45 % of the display's width at most,
// and set in smaller type (to half) where it would be taller than 85 % of its height, as
// measured in the lines it is drawn in: long paragraphs and short lines alike.
TEST(Tooltips, ALongTextStaysWithinTheDisplay) {
    const ImGuiWithoutAWindow imgui(600.0f, 400.0f);
    ImGui::GetIO().MousePos = ImVec2(300.0f, 200.0f);  // so that the tooltip is placed by the pointer
    std::string paragraphs, lines;
    for (int k = 0; k < 30; ++k) paragraphs += "A property, what it measures and why the lecture's answers keep it or not. ";
    for (int k = 0; k < 40; ++k) lines += "property " + std::to_string(k) + ": 1.000 after/before\n";
    for (const std::string& text : {paragraphs, lines}) {
        float type = 1.0f;
        for (int frame = 0; frame < 3; ++frame) {  // an auto-sized window takes its size from the frame before
            ImGui::NewFrame();
            type = ui::showTooltip(text);
            ImGui::Render();
        }
        const ImGuiWindow* tooltip = ImGui::FindWindowByName("##Tooltip_00");
        ASSERT_NE(tooltip, nullptr);
        EXPECT_LT(type, 1.0f) << "taller than the display in the panel's type";
        EXPECT_LE(tooltip->Size.x, 0.45f * 600.0f + ImGui::GetStyle().WindowPadding.x + 1.0f);
        EXPECT_GE(tooltip->Pos.y, 0.0f);
        EXPECT_LE(tooltip->Pos.y + tooltip->Size.y, 400.0f) << text.substr(0, 20);
        EXPECT_LE(tooltip->Pos.x + tooltip->Size.x, 600.0f);
    }
    ImGui::NewFrame();  // ImGui's own tooltips share the window: the panel's type again
    ImGui::SetTooltip("t = 1.000 s");
    ImGui::Render();
    EXPECT_EQ(ImGui::FindWindowByName("##Tooltip_00")->FontWindowScale, 1.0f);
    ImGui::NewFrame();  // a short one keeps the panel's type
    EXPECT_EQ(ui::showTooltip("short"), 1.0f);
    ImGui::Render();
}

// Presented at 1280x800, where the sliders under the text begin (px from the top): a few
// frames, as the window draws them (the text's fold takes the frame before's height).
float presentedSlidersTop(const scenes::Scene& scene, const ui::Readouts& readouts) {
    ui::PanelState state;
    state.present = true;
    double timeScale = 1.0;
    for (int frame = 0; frame < 3; ++frame) {
        ImGui::NewFrame();
        ui::drawControlPanel(scene, timeScale, readouts, state, {});
        ImGui::Render();
    }
    return state.presentedSlidersTop;
}

// A click on a sphere, presented, moved the sliders under the text up a line: its |v| line
// appeared under them (07's text asks the class to click one). The line is kept while none
// is selected, saying what a click shows; and P keeps them too ("running (P pauses)" and
// "paused (P runs, O steps)" take the same room).
TEST(PresentedPanel, AClickOnASphereOrPMovesNoSlider) {
    const ImGuiWithoutAWindow imgui(1280.0f, 800.0f);
    const scenes::Scene scene = scenes::loadScene(scenes::presetPath("07_inclined_plane"));
    ui::Readouts readouts;
    readouts.time = 0.633;
    const float none = presentedSlidersTop(scene, readouts);
    ASSERT_GT(none, 100.0f) << "under the text";
    readouts.selected = "sphere #0: |v|\u00a00.599 cm/s";
    EXPECT_EQ(presentedSlidersTop(scene, readouts), none);
    readouts.paused = true;
    EXPECT_EQ(presentedSlidersTop(scene, readouts), none);
    // A text that asks for no click keeps no line for it: the sliders go up a line.
    const scenes::Scene other = scenes::loadScene(scenes::presetPath("02_bounce_projection"));
    readouts.paused = false;
    readouts.selected.clear();
    const float otherNone = presentedSlidersTop(other, readouts);
    readouts.selected = "sphere #0: |v|\u00a01.00 m/s";
    EXPECT_LT(presentedSlidersTop(other, readouts), otherNone);
}

#if IMGUI_VERSION_NUM < 18700  // ShortKeyPresses does nothing from 1.87 on
// ImGui 1.86 reads the keys once a frame: a key pressed and let go between two frames (a
// quick Enter at a few frames a second) is held down through one frame, then let go; a key
// still held is left to its release event; a modifier is never held on (a Ctrl held after
// Ctrl+A made ImGui drop the digits typed next: the window test of the count slider).
TEST(ShortKeyPresses, AKeyPressedAndLetGoBetweenFramesIsDownForOneFrame) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    app::ShortKeyPresses presses;
    constexpr int kEnter = 257, kBackspace = 259, kControl = 341;  // GLFW_KEY_ENTER, _BACKSPACE, _LEFT_CONTROL
    presses.pressed(kEnter);  // pressed; the backend's release came in the same poll
    io.KeysDown[kEnter] = false;
    presses.pressed(kBackspace);  // pressed and still held
    io.KeysDown[kBackspace] = true;
    presses.pressed(kControl);  // Ctrl+A: pressed and let go in the same poll
    io.KeysDown[kControl] = false;
    presses.beforeNewFrame(io);
    EXPECT_TRUE(io.KeysDown[kEnter]);
    EXPECT_TRUE(io.KeysDown[kBackspace]);
    EXPECT_FALSE(io.KeysDown[kControl]);
    presses.beforeNewFrame(io);  // the next frame, no events
    EXPECT_FALSE(io.KeysDown[kEnter]);
    EXPECT_TRUE(io.KeysDown[kBackspace]);
    presses.pressed(kEnter);  // a second quick press: held through one frame again
    io.KeysDown[kEnter] = false;
    presses.beforeNewFrame(io);
    EXPECT_TRUE(io.KeysDown[kEnter]);
    presses.pressed(kEnter);  // while we hold it: pressed again, and held by the user this time
    io.KeysDown[kEnter] = true;
    presses.beforeNewFrame(io);
    EXPECT_TRUE(io.KeysDown[kEnter]);
    presses.beforeNewFrame(io);  // not let go by us a frame later: the user still holds it
    EXPECT_TRUE(io.KeysDown[kEnter]);
    ImGui::DestroyContext(context);
}
#endif
