#include "app/window/window_settings.h"

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "platform/whole_file.h"
#include "ui/control_panel.h"

namespace app {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr int kColorings = 4;  // render::ColorBy's values

// A value as the warning names it: a number, true, "a string" (cut at 40 characters), or
// "an array" / "an object" (a file's nesting may be deep enough to overflow a dump).
std::string shown(const Json& value) {
    if (value.is_array()) return "an array";
    if (value.is_object()) return "an object";
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

// The field's value where it is `kind` and `accept`s it; else its name, its value and what it
// should be ("show_box \"yes\" (not true or false)") go into `wrong`, and `value` keeps its
// default.
template <class T, class Accept>
void take(const Json& json, const char* field, Json::value_t kind, const std::string& expected, T& value, const Accept& accept,
          std::string& wrong) {
    if (!json.contains(field)) return;
    const Json& given = json[field];
    const bool number = kind == Json::value_t::number_float && given.is_number();
    if ((given.type() == kind || number) && accept(given)) {
        value = given.get<T>();
        return;
    }
    wrong += std::string(wrong.empty() ? "" : ", ") + field + " " + shown(given) + " (not " + expected + ")";
}

}  // namespace

fs::path windowSettingsPath() {
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
        return fs::path(config) / "rigid-spheres" / "window.json";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return fs::path(home) / ".config" / "rigid-spheres" / "window.json";
    }
    return {};
}

WindowSettings readWindowSettings(const fs::path& path, std::string& warning) {
    WindowSettings settings;
    std::error_code error;
    if (path.empty() || !fs::exists(path, error)) return settings;
    Json json;
    try {  // a folder or an unreadable file throws from inside the parser
        std::ifstream file(path);
        json = fs::is_regular_file(path, error) && file ? Json::parse(file, nullptr, false) : Json(Json::value_t::discarded);
    } catch (const std::exception&) {
        json = Json::value_t::discarded;
    }
    if (json.is_discarded() || !json.is_object()) {
        warning = path.string() + ": not readable as a JSON object; the default view settings instead";
        // Kept beside it: the settings written at exit would replace what was typed there.
        const fs::path kept = path.string() + ".unreadable";
        if (fs::is_regular_file(path, error)) {
            fs::rename(path, kept, error);
            if (!error) warning += " (the file is kept as " + kept.filename().string() + ")";
        }
        return settings;
    }
    std::string wrong;
    char scales[64];
    std::snprintf(scales, sizeof scales, "a number from %g to %g", ui::kUiScaleRange[0], ui::kUiScaleRange[1]);
    take(json, "ui_scale", Json::value_t::number_float, scales, settings.uiScale, [](const Json& s) {
        return s.get<double>() >= ui::kUiScaleRange[0] && s.get<double>() <= ui::kUiScaleRange[1];
    }, wrong);
    take(json, "color_by", Json::value_t::number_unsigned, "0, 1, 2 or 3", settings.colorBy,
         [](const Json& c) { return c.get<std::uint64_t>() < kColorings; }, wrong);
    const auto anyBool = [](const Json&) { return true; };
    take(json, "show_box", Json::value_t::boolean, "true or false", settings.showBox, anyBool, wrong);
    take(json, "show_grid", Json::value_t::boolean, "true or false", settings.showGrid, anyBool, wrong);
    if (!wrong.empty()) warning = path.string() + ": " + wrong + "; the default instead";
    return settings;
}

std::string writeWindowSettings(const fs::path& path, const WindowSettings& settings) {
    if (path.empty()) return "no HOME or XDG_CONFIG_HOME to keep them in";
    std::error_code error;
    fs::create_directories(path.parent_path(), error);
    if (error) return path.parent_path().string() + ": " + error.message();
    Json json = {{"color_by", settings.colorBy}, {"show_box", settings.showBox}, {"show_grid", settings.showGrid}};
    if (settings.uiScale > 0.0f) json["ui_scale"] = std::round(double(settings.uiScale) * 100.0) / 100.0;
    // Whole or not at all: a full disk leaves the last settings as they were.
    if (!platform::writeWholeFile(path.string(), json.dump(2) + "\n")) return path.string() + ": cannot be written";
    return "";
}

}  // namespace app
