// The real window under Xvfb: starts `spheres` as a user would, takes screenshots
// with --screenshot and checks what a teacher would see on them.
#include <gtest/gtest.h>

#include <algorithm>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

#include "render/image_io.h"

namespace {

namespace fs = std::filesystem;

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Runs the window for `frames` frames on a screen of `screen` pixels and returns the
// screenshot; "" on failure.
std::string screenshot(const std::string& name, const std::string& arguments, const std::string& screen = "1280x800") {
    const fs::path out = fs::path(SPHERES_TEST_OUTPUT_DIR) / (name + ".png");
    fs::remove(out);
    const std::string command = "xvfb-run -a -s '-screen 0 " + screen + "x24' '" SPHERES_EXECUTABLE "' " +
                                arguments + " --screenshot '" + out.string() + "' >/dev/null 2>&1";
    return std::system(command.c_str()) == 0 && fs::exists(out) ? out.string() : "";
}

render::Image load(const std::string& path) {
    render::Image image;
    EXPECT_TRUE(render::readPng(path, &image)) << path;
    return image;
}

// Fraction of the pixels of a rectangle for which `test` holds.
template <class Test>
double fraction(const render::Image& image, int x0, int y0, int x1, int y1, Test test) {
    int hits = 0, total = 0;
    for (int y = y0; y < y1; y += 2) {
        for (int x = x0; x < x1; x += 2) {
            hits += test(image.pixel(x, y)) ? 1 : 0;
            ++total;
        }
    }
    return total ? double(hits) / total : 0.0;
}

// Mean absolute channel difference over a rectangle, 0..255.
double meanDifference(const render::Image& a, const render::Image& b, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    int count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const glm::ivec4 d = glm::abs(glm::ivec4(a.pixel(x, y)) - glm::ivec4(b.pixel(x, y)));
            sum += d.x + d.y + d.z;
            count += 3;
        }
    }
    return sum / count;
}

bool saturated(glm::u8vec4 p) {  // sphere colours; the box, floor, panel and background are greys
    const int hi = std::max({int(p.x), int(p.y), int(p.z)}), lo = std::min({int(p.x), int(p.y), int(p.z)});
    return hi - lo > 60;
}

bool dark(glm::u8vec4 p) { return p.x + p.y + p.z < 3 * 45; }

// The scene right of the panel, under the readouts' line (which shows FPS, and so
// changes by itself) and above the timeline bar.
constexpr int kSceneX0 = 460, kSceneX1 = 1270, kSceneY0 = 40, kSceneY1 = 720;

}  // namespace

TEST(Window, ShowsThePanelAndTheSpheresInTheBox) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: install the xvfb package to run the window tests";
    const std::string path = screenshot("window_pile", "--scene 11_pile --frames 40");
    ASSERT_FALSE(path.empty()) << "spheres did not run or wrote no screenshot under Xvfb";
    const render::Image image = load(path);
    ASSERT_EQ(image.width, 1280);
    ASSERT_EQ(image.height, 800);
    // The panel: its label column is ImGui's dark window background behind light text.
    EXPECT_GT(fraction(image, 180, 250, 400, 780, dark), 0.6);
    // The spheres: coloured pixels in the lower half of the scene (the pile), none
    // in its top rows (the sky above the box).
    EXPECT_GT(fraction(image, kSceneX0, 450, kSceneX1, 780, saturated), 0.15);
    EXPECT_LT(fraction(image, kSceneX0, 0, kSceneX1, 60, saturated), 0.01);
}

// The window opens no larger than the screen: the default 1280 x 800 on a 1366 x 768 laptop
// put the timeline bar and the side-by-side field below its edge (a student's review).
TEST(Window, OpensNoLargerThanTheScreenAndLargerOnALargeOne) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: install the xvfb package to run the window tests";
    const std::string path = screenshot("window_small_screen", "--scene 03_head_on --frames 5", "1366x768");
    ASSERT_FALSE(path.empty()) << "spheres did not run or wrote no screenshot under Xvfb";
    const render::Image image = load(path);
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 768);
    // The timeline bar along the bottom, in sight: dark right of the panel.
    EXPECT_GT(fraction(image, 700, 740, 1270, 766, dark), 0.25);
    // A projector's 1920x1080 screen: 80 % of it, not 1280x800 in a corner; a size asked for
    // is kept.
    const render::Image projector = load(screenshot("window_projector", "--scene 03_head_on --frames 5", "1920x1080"));
    EXPECT_EQ(projector.width, 1536);
    EXPECT_EQ(projector.height, 864);
    const render::Image asked = load(screenshot("window_asked", "--scene 03_head_on --frames 5 --width 1000 --height 700", "1920x1080"));
    EXPECT_EQ(asked.width, 1000);
    EXPECT_EQ(asked.height, 700);
}

// Slide 7's preset opens side by side in three views (its "compare" key), each with
// its floor: in one row right of the panel, the grid that keeps each box largest at
// 1280x800, each view's label in a strip above it, never over it. (The floor, not the
// ball: the window runs in real time.)
TEST(Window, ThePresetOfThreeAnswersOpensInThreeViews) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: install the xvfb package to run the window tests";
    const std::string path = screenshot("window_three_answers", "--scene 14_three_answers --frames 30");
    ASSERT_FALSE(path.empty()) << "spheres did not run or wrote no screenshot under Xvfb";
    const render::Image image = load(path);
    const auto floorGrid = [](glm::u8vec4 p) {  // the floor's light grey tiles
        return p.x > 200 && p.y > 200 && p.z > 200 && std::max({p.x, p.y, p.z}) - std::min({p.x, p.y, p.z}) < 20;
    };
    for (int k = 0; k < 3; ++k) {
        const int x = 435 + 286 * k;  // each view's floor, in the lower half of the window
        EXPECT_GT(fraction(image, x, 500, x + 260, 600, floorGrid), 0.05) << "view " << char('A' + k);
        // Under the labels (up to nine lines: the apex ratio, C's impacts) the view starts
        // with sky: no label's dark box reaches into it.
        EXPECT_LT(fraction(image, x, 265, x + 260, 365, dark), 0.01) << "view " << char('A' + k);
        // The label above it: dark, with its text.
        EXPECT_GT(fraction(image, x, 40, x + 260, 170, dark), 0.5) << "label " << char('A' + k);
    }
}

// The presentation layout from the command line: the panel holds the scene's text and
// its sliders in large type, with no timeline bar under the view and no readouts'
// line over it (the scene reaches the window's top and bottom edges).
TEST(Window, ThePresentationLayoutLeavesTheViewToTheScene) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: install the xvfb package to run the window tests";
    const std::string normal = screenshot("window_column", "--scene 09_column --frames 20");
    const std::string present = screenshot("window_present", "--scene 09_column --present --frames 20");
    ASSERT_FALSE(normal.empty() || present.empty());
    const render::Image a = load(normal), b = load(present);
    // The bottom rows right of the panel: the timeline bar (dark) normally, the floor's sky in the presentation.
    EXPECT_GT(fraction(a, 700, 770, 1270, 798, dark), 0.25);  // its slider and text are lighter
    EXPECT_LT(fraction(b, 700, 770, 1270, 798, dark), 0.01);
    // The top rows: the readouts' line, or the sky.
    EXPECT_GT(fraction(a, 700, 2, 1270, 18, dark), 0.5);
    EXPECT_LT(fraction(b, 700, 2, 1270, 18, dark), 0.01);
    // The panel: wider (larger type), dark down to its bottom.
    EXPECT_GT(fraction(b, 440, 300, 560, 780, dark), 0.6);
    EXPECT_LT(fraction(a, 440, 300, 560, 780, dark), 0.1);
}

TEST(Window, FramesChangeWhileRunningAndNotWhilePaused) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found: install the xvfb package to run the window tests";
    const std::string early = screenshot("window_run_early", "--scene 11_pile --frames 5");
    const std::string late = screenshot("window_run_late", "--scene 11_pile --frames 70");
    const std::string pausedEarly = screenshot("window_paused_early", "--scene 11_pile --paused --frames 5");
    const std::string pausedLate = screenshot("window_paused_late", "--scene 11_pile --paused --frames 70");
    ASSERT_FALSE(early.empty() || late.empty() || pausedEarly.empty() || pausedLate.empty());
    const double running = meanDifference(load(early), load(late), kSceneX0, kSceneY0, kSceneX1, kSceneY1);
    const double paused = meanDifference(load(pausedEarly), load(pausedLate), kSceneX0, kSceneY0, kSceneX1, kSceneY1);
    EXPECT_GT(running, 2.0);   // the spheres fell
    EXPECT_LT(paused, 0.01);   // nothing moved
}

TEST(Window, WithoutADisplayExitsWithCodeTwoAndSaysHowToRunHeadless) {
    const fs::path log = fs::path(SPHERES_TEST_OUTPUT_DIR) / "no_display.txt";
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY '" SPHERES_EXECUTABLE "' --frames 1 2>'" +
                                log.string() + "'";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    std::FILE* file = std::fopen(log.c_str(), "r");
    ASSERT_NE(file, nullptr);
    char line[1024] = {};
    ASSERT_NE(std::fgets(line, sizeof line, file), nullptr);
    std::fclose(file);
    EXPECT_NE(std::string(line).find("cannot open a window"), std::string::npos) << line;
    EXPECT_NE(std::string(line).find("spheres capture"), std::string::npos) << line;
}

// Bad input on the command line: one line naming the problem, exit code 2, before any work.
TEST(CommandLine, BadInputExitsWithCodeTwoAndOneLineNamingIt) {
    const std::pair<std::string, std::string> cases[] = {
        {"simulate --scene pile --steps -1", "--steps"},
        {"simulate --scene pile --steps 5 --every 0 --out x.csv", "--every"},
        {"simulate --scene pile", "--steps"},
        {"simulate --scene /tmp --steps 1", "folder"},
        {"simulate --scene pile --steps 1 --set alpha=2", "alpha"},
        {"simulate --scene pile --steps 1 --out /nonexistent/x.csv", "/nonexistent/x.csv"},
        {"--scene pile --frames 1 --screenshot /nonexistent/x.png", "--screenshot"},
        {"--scene pile --frames 1 --screenshot x.jpg", "must end in .png"},
        {"simulate --scene pile --steps 1 --state x.json", "must end in .csv"},
        {"simulate --scene pile --steps 1 --save x.csv", "must end in .json"},
    };
    for (const auto& [arguments, named] : cases) {
        const fs::path log = fs::path(SPHERES_TEST_OUTPUT_DIR) / "bad_input.txt";
        const std::string command = "cd '" SPHERES_TEST_OUTPUT_DIR "' && '" SPHERES_EXECUTABLE "' " + arguments +
                                    " >/dev/null 2>'" + log.string() + "'";
        const int status = std::system(command.c_str());
        ASSERT_TRUE(WIFEXITED(status)) << arguments;
        EXPECT_EQ(WEXITSTATUS(status), 2) << arguments;
        std::FILE* file = std::fopen(log.c_str(), "r");
        ASSERT_NE(file, nullptr);
        char first[1024] = {}, second[1024] = {};
        ASSERT_NE(std::fgets(first, sizeof first, file), nullptr) << arguments;
        EXPECT_EQ(std::fgets(second, sizeof second, file), nullptr) << arguments << ": more than one line";
        std::fclose(file);
        EXPECT_NE(std::string(first).find(named), std::string::npos) << arguments << ": " << first;
    }
}
