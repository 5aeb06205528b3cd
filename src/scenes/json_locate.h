#pragma once
// Internal to spheres_scenes: where things are in a JSON text, so that every
// error of a scene file can point at a line and column.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace scenes::detail {

struct TextPosition {
    std::size_t line = 1;    // 1-based
    std::size_t column = 1;  // 1-based, in characters (UTF-8 code points)
};

// The line and column of a byte offset (clamped to the text).
TextPosition positionOf(std::string_view text, std::size_t offset);

// The byte offset of the value at a JSON pointer ("/spheres/3/p"), or of its
// key when `atKey`, in a text nlohmann accepted. Where the pointer leads
// nowhere: the offset of the deepest value on its way.
std::size_t offsetOf(std::string_view text, std::string_view pointer, bool atKey = false);

// The offset of the first number that is not finite as a double (1e999).
std::optional<std::size_t> nonFiniteNumber(std::string_view text);

// A key that appears twice in one object: its JSON pointer and the offset of the second.
struct DuplicateKey {
    std::string pointer;
    std::size_t offset = 0;
};
std::optional<DuplicateKey> duplicateKey(std::string_view text);

// "/spheres/3/r" -> "spheres[3].r", for messages.
std::string readablePath(std::string_view pointer);

// Appends a key or an index to a JSON pointer (escaping '~' and '/').
std::string childPointer(const std::string& pointer, std::string_view key);
std::string childPointer(const std::string& pointer, std::size_t index);

}  // namespace scenes::detail
