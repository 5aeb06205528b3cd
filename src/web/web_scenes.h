#pragma once
// What the page's entry points share: a preset named as --scene names it, with
// settings as --set takes them, and their answers as JSON text.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "scenes/scene.h"

namespace web {

using Json = nlohmann::ordered_json;

// `json` as text, valid until the next answer (Module.ccall copies it at once).
const char* answer(const Json& json);

// A state hash as the desktop prints it: 16 hexadecimal digits.
std::string hexHash(std::uint64_t hash);

// The preset that `name` names, as the preset list names it ("cradle" -> "08_newtons_cradle").
std::string presetName(const std::string& name);

// The scene `name` with `settings`, one "name=value" per line; throws
// std::runtime_error saying what is wrong (a scene error, a refused setting).
scenes::Scene sceneWithSettings(const std::string& name, const std::string& settings);

}  // namespace web
