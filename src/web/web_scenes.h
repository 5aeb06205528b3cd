#pragma once
// The page's scenes: a preset named as --scene names it, with settings as --set takes
// them.
#include <string>

#include "scenes/scene.h"

namespace web {

// The scene `name` with `settings`, one "name=value" per line; throws
// std::runtime_error saying what is wrong (a scene error, a refused setting).
scenes::Scene sceneWithSettings(const std::string& name, const std::string& settings);

}  // namespace web
