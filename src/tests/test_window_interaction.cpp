// The real window under Xvfb with the interaction features started from the
// command line: two views side by side (--compare), the selected sphere's
// inspector and explainer (--select, --explain), refused input, keys as typed and the
// view settings kept between sessions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/window/window_settings.h"
#include "render/image_io.h"
#include "scenes/scene_json.h"

namespace {

namespace fs = std::filesystem;

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

std::string screenshot(const std::string& name, const std::string& arguments) {
    const fs::path out = fs::path(SPHERES_TEST_OUTPUT_DIR) / (name + ".png");
    fs::remove(out);
    const std::string command = "xvfb-run -a -s '-screen 0 1280x800x24' '" SPHERES_EXECUTABLE "' " + arguments +
                                " --screenshot '" + out.string() + "' >/dev/null 2>&1";
    return std::system(command.c_str()) == 0 && fs::exists(out) ? out.string() : "";
}

render::Image load(const std::string& path) {
    render::Image image;
    EXPECT_TRUE(render::readPng(path, &image)) << path;
    return image;
}

bool saturated(glm::u8vec4 p) {
    return std::max({int(p.x), int(p.y), int(p.z)}) - std::min({int(p.x), int(p.y), int(p.z)}) > 60;
}

bool dark(glm::u8vec4 p) { return p.x + p.y + p.z < 3 * 45; }
bool notSky(glm::u8vec4 p) { return p.x + p.y + p.z < 3 * 110; }  // the sky is a light grey-blue

template <class Test>
double fraction(const render::Image& image, int x0, int y0, int x1, int y1, Test test) {
    int hits = 0, total = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            hits += test(image.pixel(x, y)) ? 1 : 0;
            ++total;
        }
    }
    return total ? double(hits) / total : 0.0;
}

// The scene right of the panel (425 px at UI scale 1 on a 1280 px window) is split
// into two views with a 4 px gap in the middle.
constexpr int kSceneX0 = 425, kGapX = 425 + (855 - 4) / 2;

TEST(WindowInteraction, CompareShowsTwoViewsSideBySide) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found";
    const std::string path = screenshot("window_compare", "--scene 11_pile --compare method=velocity --frames 30");
    ASSERT_FALSE(path.empty());
    const render::Image image = load(path);
    // The gap: dark from top to bottom of the views (above the timeline bar).
    EXPECT_GT(fraction(image, kGapX + 1, 200, kGapX + 3, 700, dark), 0.95);
    // Spheres on both sides of it.
    EXPECT_GT(fraction(image, kSceneX0, 400, kGapX, 720, saturated), 0.08);
    EXPECT_GT(fraction(image, kGapX + 4, 400, 1280, 720, saturated), 0.08);
}

// At 1280x800 the dock is a column on the right (the box keeps more room than under a
// strip at the bottom): the inspector at its top, the explanation under it, the view
// left of them uncovered.
TEST(WindowInteraction, SelectOpensTheInspectorAndTheExplainer) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found";
    const std::string plain = screenshot("window_unselected", "--scene 03_head_on --paused --frames 5");
    const std::string selected = screenshot("window_selected", "--scene 03_head_on --paused --frames 5 --select 0 --explain");
    ASSERT_FALSE(plain.empty() || selected.empty());
    constexpr int kDockX0 = 860;  // 1280 - 32 font sizes of 17 px, and a margin
    // The inspector: a dark window with blue fields at the top of the dock, over the sky.
    EXPECT_LT(fraction(load(plain), kDockX0, 40, 1270, 180, notSky), 0.05);
    EXPECT_GT(fraction(load(selected), kDockX0, 40, 1270, 180, notSky), 0.8);
    // The explainer: under it, down to the timeline bar.
    EXPECT_LT(fraction(load(plain), kDockX0, 300, 1270, 700, notSky), 0.3);
    EXPECT_GT(fraction(load(selected), kDockX0, 300, 1270, 700, notSky), 0.8);
    // The selected sphere stays in view: its yellow ring is drawn left of the dock.
    const auto ring = [](glm::u8vec4 p) { return p.x > 200 && p.y > 180 && p.z < 80; };
    EXPECT_GT(fraction(load(selected), kSceneX0, 40, kDockX0 - 10, 720, ring), 0.0005);
}

// Presenting four views with a contact explained, the explanation docked beside the panel
// left the views 170 px wide at 1280x720. The explanation now takes the panel's place
// while it is open: view A's sky where the panel's text was, and the four views each
// wider than a quarter of the window less a margin.
TEST(WindowInteraction, PresentingAnExplanationTakesThePanelsPlace) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found";
    const std::string path = screenshot("window_present_explained", "--scene 16_bernoulli --paused --frames 10 --present "
                                                                    "--select 1 --explain --width 1280 --height 720");
    ASSERT_FALSE(path.empty());
    const render::Image image = load(path);
    const auto sky = [](glm::u8vec4 p) { return !notSky(p); };
    const auto titleBlue = [](glm::u8vec4 p) { return p.z > 100 && p.z > p.x + 50; };  // the panel's title bar
    EXPECT_LT(fraction(image, 0, 2, 570, 30, titleBlue), 0.2) << "the panel's title bar is gone";
    EXPECT_GT(fraction(image, 0, 0, 570, 400, sky), 0.1) << "a view where the panel was";
    EXPECT_GT(fraction(image, 20, 480, 1260, 700, notSky), 0.8) << "the explanation, the window's width";
}

bool haveXdotool() { return std::system("command -v xdotool >/dev/null 2>&1") == 0; }

// Writes `script` (sh) into a fresh `folder` and runs it under Xvfb there (90 s at
// most); returns std::system's status. The window keeps its view settings in
// folder/config (XDG_CONFIG_HOME): no session reads another's, or the user's own; a
// `settings` text is written there first.
int runScript(const fs::path& folder, const std::string& script, const std::string& settings = "") {
    fs::remove_all(folder);
    fs::create_directories(folder / "config" / "rigid-spheres");
    std::ofstream(folder / "session.sh") << script;
    if (!settings.empty()) std::ofstream(folder / "config" / "rigid-spheres" / "window.json") << settings;
    const std::string command = "cd '" + folder.string() + "' && XDG_CONFIG_HOME='" + (folder / "config").string() +
                                "' timeout 90 xvfb-run -a -s '-screen 0 1280x800x24' sh session.sh >/dev/null 2>&1";
    return std::system(command.c_str());
}

// xdotool's lines that press `key` for 0.3 s (ImGui misses a key pressed and released
// within one frame), then wait a second.
std::string press(const std::string& key) { return "xdotool keydown " + key + " sleep 0.3 keyup " + key + " sleep 1\n"; }

// A session on the column preset with `options`: the window found and focused, the mouse
// over the scene, `keys` (xdotool's lines), then Ctrl+Q; the script ends with the app.
std::string sessionOnTheColumn(const std::string& options, const std::string& keys) {
    return "'" SPHERES_EXECUTABLE "' --scene 09_column " + options + " & pid=$!\n"
           "w=$(timeout 30 xdotool search --sync --onlyvisible --name 'Rigid Spheres')\n"
           "xdotool windowfocus --sync $w; sleep 2; xdotool mousemove 900 400 sleep 0.5\n" +
           keys + press("ctrl+q") + "wait $pid\n";
}

// xdotool's lines that type `value` into the slider at (x, y) as a student does: Ctrl+click
// opens its field, Ctrl+A selects the text, the keys typed, then Enter ("" types nothing:
// Enter alone). Every key and button is held 0.3 s, and the characters go 0.1 s apart: a
// window slowed by other work (the unit tests beside it) may take that long for a frame,
// and ImGui misses a press released within one.
std::string typedIntoSlider(int x, int y, const std::string& value) {
    return "xdotool mousemove " + std::to_string(x) + " " + std::to_string(y) +
           " sleep 0.3 keydown ctrl sleep 0.3 mousedown 1 sleep 0.3 mouseup 1 sleep 0.3 keyup ctrl sleep 0.5\n" +
           press("ctrl+a") + (value.empty() ? std::string() : "xdotool type --delay 100 " + value + "\n") +
           "xdotool sleep 0.3\n" + press("Return");
}

bool orange(glm::u8vec4 p) { return p.x > 200 && p.y > 120 && p.y < 190 && p.z < 110; }  // the panel's refusals

// A student drags the pile's N to a count the region cannot hold (typed here, Ctrl +
// click on the slider): the window stays open, says why under the slider, and the
// pile stays; F12 then writes a screenshot and Ctrl+Q ends the session (exit 0).
// Keys are held for 0.3 s: ImGui misses a key pressed and released within one frame.
// The panel is scrolled down three wheel notches first (the pile's text is long), so
// (88, 715) is the N slider at 1280x800 and UI scale 1: a change to the panel above it (the
// pile's text, its measured claims' line, a new control) moves it, and this test then
// fails, not passes.
TEST(WindowInteraction, ACountThePileCannotHoldIsRefusedUnderItsSliderAndTheWindowStays) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_refusal";
    // Paused: the pile stays in its lattice for the screenshot.
    const int status = runScript(folder,
                  "'" SPHERES_EXECUTABLE "' --scene 11_pile --paused & pid=$!\n"
                  "w=$(timeout 30 xdotool search --sync --onlyvisible --name 'Rigid Spheres')\n"
                  "xdotool windowfocus --sync $w; sleep 3\n"
                  "xdotool mousemove 200 500 sleep 0.3 click --repeat 3 --delay 30 5 sleep 1\n"
                  + typedIntoSlider(88, 715, "7483") +
                  "xdotool mousemove 700 300 sleep 2 \\\n"
                  "  keydown F12 sleep 0.3 keyup F12 sleep 2 keydown ctrl+q sleep 0.3 keyup ctrl+q\n"
                  "wait $pid\n");
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the window ended by itself, or did not end on Ctrl+Q";
    const fs::path shot = folder / "spheres_output" / "screenshot_0001.png";
    ASSERT_TRUE(fs::exists(shot)) << "F12 wrote no screenshot: the window was gone";
    const render::Image image = load(shot.string());
    // The refusal, in orange, under the N slider (the panel's lower left).
    EXPECT_GT(fraction(image, 5, 725, 420, 795, orange), 0.02);
    EXPECT_LT(fraction(image, 5, 40, 420, 700, orange), 0.001) << "orange elsewhere in the panel";
    // The pile (its lattice, paused) is still there, in the view.
    EXPECT_GT(fraction(image, kSceneX0 + 180, 220, 940, 480, saturated), 0.2);
}

// A student types into a slider (Ctrl+click); it counts when Enter is pressed, not key by key.
// A first session on the column, paused: Enter on h's field as it opened, nothing typed,
// leaves h as it was, not its text as shown (0.01667); 11/20 typed into beta, a fraction as
// the texts write h, is 0.55 (ImGui's own reading kept the 11, out of range). A second:
// beta = 1.5 is refused under the slider and beta stays 0.8 (key by key, the 1 typed on the
// way was applied before, and the refusal then left it). Save state writes what the run
// uses. Positions at 1280x800: beta's slider at (86, 524) and h's at (86, 626) in the
// column's panel as it opens; Save state at (102, 732) once the panel is scrolled to its end
// (ten wheel notches), where the line under it ("files go to" the working folder) is one
// line only in a short folder. (A second Save state in one session missed its button in a
// CI run: each session saves once.)
TEST(WindowInteraction, ANumberTypedIntoASliderCountsWhenEnterIsPressed) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_typed_value";
    const auto typeInto = [](int y, const std::string& value) { return typedIntoSlider(86, y, value); };
    // The run's parameters as Save state wrote them after `typing`.
    const auto saved = [&](const std::string& name, const std::string& typing) {
        const fs::path file = folder / (name + ".json");
        fs::remove(file);
        const std::string keys = typing +
                                 "xdotool mousemove 200 500 sleep 0.3 click --repeat 10 --delay 30 5 sleep 1\n"
                                 "xdotool mousemove 102 732 sleep 0.3 click 1 sleep 1\n";
        const int status = runScript(folder, "d=$(mktemp -d /tmp/stXXXXXX); cd \"$d\"\n" + sessionOnTheColumn("--paused", keys) +
                                                 "cp spheres_output/state_0001.json '" + file.string() + "'; s=$?\n"
                                                 "rm -rf \"$d\"; exit $s\n");
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << name << ": Save state was not clicked";
        return fs::exists(file) ? scenes::loadScene(file.string()).params : physics::Params{};
    };
    const physics::Params typed = saved("typed", typeInto(626, "") + typeInto(524, "11/20"));
    EXPECT_EQ(typed.timeStep, 1.0 / 60.0) << "the rounded text shown was applied";
    EXPECT_EQ(typed.beta, 0.55) << "a fraction, as the texts write h, read as its leading number";
    EXPECT_EQ(saved("refused", typeInto(524, "1.5")).beta, 0.8) << "1.5 was not refused whole";
}

// A lit alarm's red (255, 77, 64) and its text's edges; not the orange of "behind real time".
bool alarmRed(glm::u8vec4 p) { return p.x > 170 && p.y < 0.45 * p.x && p.z < 0.45 * p.x; }

// An alarm that fires while the pointer is over the panel waits until it leaves: shown at
// once, its lines would push every control below them down under the pointer. The bounce
// under the velocity method at beta = 1 creates energy at its first bounce (t = 0.55 s);
// the pointer rests on the panel from the start to past it (F12: no alarm's red in the
// panel), then leaves it (F12: the alarm is there).
TEST(WindowInteraction, AnAlarmWaitsUntilThePointerLeavesThePanel) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_alarm_waits";
    const int status = runScript(folder,
                  "'" SPHERES_EXECUTABLE "' --scene 02_bounce_projection --set method=velocity --set beta=1 --paused & pid=$!\n"
                  "w=$(timeout 30 xdotool search --sync --onlyvisible --name 'Rigid Spheres')\n"
                  "xdotool windowfocus --sync $w; sleep 2; xdotool mousemove 300 650 sleep 1\n" +
                  press("p") + "sleep 2\n" + press("F12") + "xdotool mousemove 900 400 sleep 1\n" + press("F12") +
                  press("ctrl+q") + "wait $pid\n");
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const fs::path over = folder / "spheres_output" / "screenshot_0001.png", left = folder / "spheres_output" / "screenshot_0002.png";
    ASSERT_TRUE(fs::exists(over) && fs::exists(left)) << "F12 wrote no screenshot";
    EXPECT_LT(fraction(load(over.string()), 5, 30, 410, 790, alarmRed), 0.0005) << "the alarm pushed the controls";
    EXPECT_GT(fraction(load(left.string()), 5, 30, 410, 790, alarmRed), 0.002) << "no alarm once the pointer left";
}

// A teacher presses F5 on the column: the presentation layout (the panel in large type
// is wider, the bar and the readouts' line are gone); F12's screenshot shows it and
// F5 again brings every control back (a second screenshot); a click on the readouts'
// line, on its words (not only its arrow), unfolds them into the dock (a third).
TEST(WindowInteraction, F5SwitchesToThePresentationLayoutAndBack) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_present_key";
    // After two screenshots, a click on the readouts' word "Readouts" (top left of the view):
    // they unfold into the dock; a third.
    const std::string unfold = "xdotool mousemove 480 11 sleep 0.3 mousedown 1 sleep 0.3 mouseup 1 sleep 1 mousemove 900 400 sleep 0.3\n";
    const int status = runScript(
        folder, sessionOnTheColumn("--paused", press("F5") + press("F12") + press("F5") + press("F12") + unfold + press("F12")));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const fs::path present = folder / "spheres_output" / "screenshot_0001.png";
    const fs::path back = folder / "spheres_output" / "screenshot_0002.png";
    ASSERT_TRUE(fs::exists(present) && fs::exists(back)) << "F12 wrote no screenshot";
    const render::Image a = load(present.string()), b = load(back.string());
    EXPECT_GT(fraction(a, 440, 300, 560, 780, dark), 0.6);  // the wider panel
    EXPECT_LT(fraction(a, 700, 770, 1270, 798, dark), 0.01);  // no bar
    EXPECT_LT(fraction(b, 440, 300, 560, 780, dark), 0.1);   // the panel as it was
    EXPECT_GT(fraction(b, 700, 770, 1270, 798, dark), 0.25);  // the bar again
    // A click on the readouts' line: their numbers fill a column on the right (the dock).
    const fs::path unfolded = folder / "spheres_output" / "screenshot_0003.png";
    ASSERT_TRUE(fs::exists(unfolded));
    EXPECT_LT(fraction(b, 1000, 100, 1270, 700, notSky), 0.3);
    EXPECT_GT(fraction(load(unfolded.string()), 1000, 100, 1270, 700, notSky), 0.8);
}

// The keys go by what the keyboard types. [ and ] open the previous and next preset, and
// the window's title names the scene: ] on the column opens the pyramid, [ the column
// again; then, on a German layout, AltGr+9 types ] (the pyramid), and the key where a US
// keyboard has [ types ü there, which opens nothing; AltGr+9 again, the pile, its title
// with its count. Last, on a French layout, Ctrl+Q (on
// the key where a US keyboard has A) quits.
TEST(WindowInteraction, KeysGoByWhatTheKeyboardTypes) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_brackets";
    const std::string name = "xdotool getwindowname $w >> names.txt\n";
    const std::string altGr9 = "xdotool keydown ISO_Level3_Shift keydown 9 sleep 0.3 keyup 9 keyup ISO_Level3_Shift sleep 1\n";
    const int status = runScript(folder, sessionOnTheColumn("--paused", name + press("bracketright") + name + press("bracketleft") +
                                                                            name + "setxkbmap de\n" + altGr9 + name +
                                                                            press("udiaeresis") + name + altGr9 + name +
                                                                            "setxkbmap fr\n"));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "Ctrl+Q on a French layout did not quit";
    std::ifstream names(folder / "names.txt");
    std::vector<std::string> titles;
    for (std::string line; std::getline(names, line);) titles.push_back(line);
    const std::string column = "Rigid Spheres: A column of ten spheres", pyramid = "Rigid Spheres: A pyramid of 55 spheres";
    const std::string pile = "Rigid Spheres: A pile of 1000 spheres";  // its count, not "{count}"
    EXPECT_EQ(titles, (std::vector<std::string>{column, pyramid, column, pyramid, pyramid, pile}));
}

// The view settings are kept between sessions. A session started with the last one's (a
// UI scale of 1.25, the colouring by number, no floor grid) shows the panel as wide as that
// scale makes it (F12); F5 enlarges the type for the presentation, and Ctrl+Q there keeps
// the scale the user chose, not the presentation's, in a file written anew.
TEST(WindowInteraction, TheViewSettingsAreKeptBetweenSessions) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_kept_settings";
    const std::string kept = R"({"ui_scale": 1.25, "color_by": 0, "show_box": true, "show_grid": false, "later": 1})";
    const int status = runScript(folder, sessionOnTheColumn("--paused", press("F12") + press("F5")), kept);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const fs::path shot = folder / "spheres_output" / "screenshot_0001.png";
    ASSERT_TRUE(fs::exists(shot)) << "F12 wrote no screenshot";
    const render::Image image = load(shot.string());
    EXPECT_GT(fraction(image, 445, 300, 520, 780, dark), 0.6);  // the panel a quarter wider
    EXPECT_LT(fraction(image, 580, 300, 640, 780, dark), 0.1);
    const fs::path file = folder / "config" / "rigid-spheres" / "window.json";
    std::string warning;
    EXPECT_TRUE(app::readWindowSettings(file, warning) == app::WindowSettings({1.25f, 0, true, false}));
    EXPECT_EQ(warning, "");
    std::ifstream text(file);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(text), {}).find("later"), std::string::npos) << "not written anew";
}

// A teacher in the presentation layout with a sphere explained presses Esc, as in a slide
// show, once too often: the first leaves the presentation (F12's first screenshot: the bar
// and the dock with the explanation are back), the next two close the explanation and
// deselect, and three more find nothing to close; the window stays (the second screenshot:
// no dock) until Ctrl+Q ends it with 0.
TEST(WindowInteraction, EscBacksOutOneLevelAtATimeAndNeverEndsTheSession) {
    if (!haveXvfb() || !haveXdotool()) GTEST_SKIP() << "xvfb-run or xdotool not found";
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_escape";
    const std::string esc = press("Escape");
    const int status = runScript(folder, sessionOnTheColumn("--paused --present --select 3 --explain",
                                                            esc + press("F12") + esc + esc + esc + esc + esc + press("F12")));
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const fs::path back = folder / "spheres_output" / "screenshot_0001.png";
    const fs::path closed = folder / "spheres_output" / "screenshot_0002.png";
    ASSERT_TRUE(fs::exists(back)) << "no screenshot after the first Esc: the window was gone";
    ASSERT_TRUE(fs::exists(closed)) << "no screenshot after six Esc: the window was gone";
    const render::Image a = load(back.string()), b = load(closed.string());
    EXPECT_LT(fraction(a, 440, 300, 560, 780, dark), 0.1);   // the panel at its own size
    EXPECT_GT(fraction(a, 700, 770, 1270, 798, dark), 0.25);  // the bar
    EXPECT_GT(fraction(a, 1000, 100, 1270, 700, notSky), 0.8);  // the dock: inspector and explanation
    EXPECT_LT(fraction(b, 1000, 100, 1270, 700, notSky), 0.3);  // nothing docked
}

TEST(WindowInteraction, RefusedOptionsExitWithCodeTwo) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found";
    for (const char* arguments : {"--scene 03_head_on --compare bogus=1 --frames 1",
                                  "--scene 03_head_on --select 99 --frames 1", "--scene 03_head_on --explain --frames 1"}) {
        const std::string command = "xvfb-run -a -s '-screen 0 1280x800x24' '" SPHERES_EXECUTABLE "' " +
                                    std::string(arguments) + " >/dev/null 2>&1";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << arguments;
        EXPECT_EQ(WEXITSTATUS(status), 2) << arguments;
    }
}

// A display whose GL driver cannot be loaded: the advice is about the driver, not "without
// a display" (there is one), and the exit code 2.
TEST(WindowInteraction, ADisplayWithoutAGlDriverIsSaidSo) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found";
    const fs::path out = fs::path(SPHERES_TEST_OUTPUT_DIR) / "no_gl_driver.txt";
    const std::string command = "xvfb-run -a -s '-screen 0 1280x800x24' env LIBGL_DRIVERS_PATH=/nonexistent '" SPHERES_EXECUTABLE
                                "' --scene 03_head_on --frames 1 >'" + out.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    std::ifstream file(out);
    const std::string said((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_NE(said.find("The display is there, its GL driver gave no OpenGL 3.3 core context"), std::string::npos) << said;
}

}  // namespace
