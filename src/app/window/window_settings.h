#pragma once
// The window's view settings, kept from one session to the next as Box2D's samples keep
// theirs: the panel's UI scale (a projector's teacher sets it once), the colouring, the box
// and the floor grid. Never the scene or its parameters: a run is reproduced from its scene
// file or link, not from whatever the last session left.
#include <filesystem>
#include <string>

namespace app {

struct WindowSettings {
    float uiScale = 0.0f;  // multiplies the panel's font; 0: the screen's own scale (not kept)
    int colorBy = 2;       // render::ColorBy: 0 id, 1 speed, 2 contact state, 3 penetration
    bool showBox = true;
    bool showGrid = true;
};

inline bool operator==(const WindowSettings& a, const WindowSettings& b) {
    return a.uiScale == b.uiScale && a.colorBy == b.colorBy && a.showBox == b.showBox && a.showGrid == b.showGrid;
}

// $XDG_CONFIG_HOME/rigid-spheres/window.json, else ~/.config/rigid-spheres/window.json;
// empty where neither variable is set (nothing is kept).
std::filesystem::path windowSettingsPath();

// The settings in `path`: the defaults where it does not exist. A file that cannot be read
// or a value out of range gives the defaults for what is wrong, and `warning` names it.
WindowSettings readWindowSettings(const std::filesystem::path& path, std::string& warning);

// Writes `settings` to `path` (its folder made if needed); returns "" or why not.
std::string writeWindowSettings(const std::filesystem::path& path, const WindowSettings& settings);

}  // namespace app
