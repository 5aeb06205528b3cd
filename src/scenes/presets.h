#pragma once
// The scenes shipped in assets/scenes/, one per lecture slide that needs one.
// The folder is found through SPHERES_ASSET_DIR, set at build time to the
// source tree's assets/, so the program runs from any directory.
#include <string>
#include <string_view>
#include <vector>

namespace scenes {

// The assets folder (SPHERES_ASSET_DIR).
std::string assetDirectory();

// The shipped presets, by name (file name without ".json"), sorted by file name:
// "01_bounce_response_only", "02_bounce_projection", ...
std::vector<std::string> listPresets();

// The file of a preset, from its name (with or without ".json"). Throws
// SceneError naming the presets when there is none of that name.
std::string presetPath(std::string_view name);

// The preset a name means: its full name ("11_pile"), its number ("11", or "8" for
// 08, as a teacher says "slide 8's preset"), its name without the number ("pile"), or
// any part of its name no other preset shares ("cradle"). Returns its file, or "" with
// `why` ("more than one preset matches: ...", or empty: none does).
std::string matchPreset(std::string_view name, std::string& why);

}  // namespace scenes
