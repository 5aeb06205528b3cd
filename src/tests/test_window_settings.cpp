// The window's kept view settings (app/window/window_settings.h): read back as written,
// and a broken or out-of-range file named in one line, never taken.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "app/window/window_settings.h"

namespace fs = std::filesystem;

namespace {

fs::path freshFile(const std::string& name, const std::string& text) {
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_settings";
    fs::create_directories(folder);
    const fs::path path = folder / name;
    std::ofstream(path) << text;
    return path;
}

// Sets an environment variable for one scope, then puts back what was there.
class ScopedVariable {
  public:
    ScopedVariable(const char* name, const char* value) : name_(name) {
        if (const char* was = std::getenv(name)) was_ = was, had_ = true;
        value ? setenv(name, value, 1) : unsetenv(name);
    }
    ~ScopedVariable() { had_ ? setenv(name_, was_.c_str(), 1) : unsetenv(name_); }

  private:
    const char* name_;
    std::string was_;
    bool had_ = false;
};

}  // namespace

TEST(WindowSettings, WhatIsWrittenIsReadBack) {
    const fs::path path = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_settings" / "made" / "window.json";
    fs::remove_all(path.parent_path());
    ASSERT_EQ(app::writeWindowSettings(path, {1.5f, 1, false, true}), "");
    std::string warning;
    EXPECT_TRUE(app::readWindowSettings(path, warning) == app::WindowSettings({1.5f, 1, false, true}));
    EXPECT_EQ(warning, "");
    // The slider's 1.1 (a float) is written as 1.1, and nothing is left beside the file.
    ASSERT_EQ(app::writeWindowSettings(path, {1.1f, 1, false, true}), "");
    std::ifstream file(path);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"ui_scale\": 1.1\n"), std::string::npos) << text;
    EXPECT_EQ(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator()), 1);
}

TEST(WindowSettings, TheScreensOwnScaleIsNotKept) {
    const fs::path path = freshFile("screen_scale.json", "");
    ASSERT_EQ(app::writeWindowSettings(path, {0.0f, 2, true, true}), "");
    std::ifstream file(path);
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("ui_scale"), std::string::npos) << text;
    std::string warning;
    EXPECT_EQ(app::readWindowSettings(path, warning).uiScale, 0.0f);
    EXPECT_EQ(warning, "");
}

TEST(WindowSettings, NoFileGivesTheDefaultsSilently) {
    std::string warning;
    EXPECT_TRUE(app::readWindowSettings(fs::path(SPHERES_TEST_OUTPUT_DIR) / "no_such.json", warning) ==
                app::WindowSettings());
    EXPECT_EQ(warning, "");
}

// A broken file is kept beside it as window.json.unreadable: the settings written at exit
// replaced what was typed there.
TEST(WindowSettings, ABrokenFileIsNamedKeptAsidAndTheDefaultsServe) {
    for (const char* text : {"{\"ui_scale\": 2", "[1, 2]", "", "\x01\x02", "{\"ui_scale\": 1e400}"}) {
        const fs::path path = freshFile("broken.json", text);
        const fs::path kept = path.string() + ".unreadable";
        fs::remove(kept);
        std::string warning;
        const app::WindowSettings read = app::readWindowSettings(path, warning);
        EXPECT_EQ(warning, path.string() +
                               ": not readable as a JSON object; the default view settings instead (the file is kept as "
                               "broken.json.unreadable)")
            << text;
        EXPECT_EQ(read.uiScale, 0.0f) << text;
        EXPECT_EQ(read.colorBy, 2) << text;
        std::ifstream file(kept);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(file), {}), text);
        EXPECT_FALSE(fs::exists(path)) << "moved aside, not copied";
    }
}

// A folder where the file should be: named when read (it threw from inside the parser,
// and the window never opened), and refused when written.
TEST(WindowSettings, AFolderInItsPlaceIsNamedNotThrown) {
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "window_settings" / "a_folder.json";
    fs::create_directories(folder);
    std::string warning;
    EXPECT_TRUE(app::readWindowSettings(folder, warning) == app::WindowSettings());
    EXPECT_EQ(warning, folder.string() + ": not readable as a JSON object; the default view settings instead");
    EXPECT_NE(app::writeWindowSettings(folder, {}), "");
    EXPECT_TRUE(fs::is_directory(folder));
}

TEST(WindowSettings, ValuesOutOfRangeAreNamedAndNotTaken) {
    const fs::path path = freshFile(
        "out_of_range.json", R"({"ui_scale": 9, "color_by": 7, "show_box": "yes", "show_grid": false, "later": 1})");
    std::string warning;
    const app::WindowSettings read = app::readWindowSettings(path, warning);
    EXPECT_EQ(warning, path.string() + ": ui_scale 9 (not a number from 0.75 to 3), color_by 7 (not 0, 1, 2 or 3), "
                                       "show_box \"yes\" (not true or false); the default instead");
    EXPECT_TRUE(read == app::WindowSettings({0.0f, 2, true, false}));  // the one good value is taken
    // A value nested 300 000 deep overflowed the stack while the warning was written.
    const std::string deep = "{\"ui_scale\": " + std::string(300000, '[') + std::string(300000, ']') + "}";
    std::string deepWarning;
    app::readWindowSettings(freshFile("deep.json", deep.c_str()), deepWarning);
    EXPECT_NE(deepWarning.find("ui_scale an array (not a number from 0.75 to 3)"), std::string::npos)
        << deepWarning.substr(0, 200);
    std::string longWarning;
    app::readWindowSettings(freshFile("long.json", ("{\"ui_scale\": \"" + std::string(100000, 'x') + "\"}").c_str()), longWarning);
    EXPECT_LT(longWarning.size(), 200u);
    for (const char* bad : {R"({"color_by": -1})", R"({"color_by": 1.5})", R"({"color_by": 4294967297})",
                            R"({"ui_scale": 0.5})", R"({"ui_scale": null})"}) {
        std::string said;
        app::readWindowSettings(freshFile("bad.json", bad), said);
        EXPECT_NE(said.find(" (not "), std::string::npos) << bad;
    }
}

TEST(WindowSettings, KeptInTheUsersConfigurationFolder) {
    {
        const ScopedVariable config("XDG_CONFIG_HOME", "/tmp/config"), home("HOME", "/home/student");
        EXPECT_EQ(app::windowSettingsPath(), fs::path("/tmp/config/rigid-spheres/window.json"));
    }
    {
        const ScopedVariable config("XDG_CONFIG_HOME", nullptr), home("HOME", "/home/student");
        EXPECT_EQ(app::windowSettingsPath(), fs::path("/home/student/.config/rigid-spheres/window.json"));
    }
    {
        const ScopedVariable config("XDG_CONFIG_HOME", nullptr), home("HOME", nullptr);
        EXPECT_EQ(app::windowSettingsPath(), fs::path());
        EXPECT_EQ(app::writeWindowSettings(app::windowSettingsPath(), {}), "no HOME or XDG_CONFIG_HOME to keep them in");
    }
}
