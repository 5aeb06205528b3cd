#pragma once
// Text wrapped to the window's width at spaces, not beside '=' ("passes = 1" stays whole)
// unless "name = value" alone is wider than the line; a word wider than the line breaks
// after a '/' or a hyphen between letters (a path, a hyphenated name), never inside a
// number, else where it is full.
// ImGui's own wrapping also breaks after '.' and ',', which splits a number across
// lines ("-1." / "193").
#include <string>
#include <string_view>

namespace ui {

// The text, wrapped at spaces to the content region's width (a word wider than the
// line breaks after a '/' or '-', else where the line is full). Newlines are kept, an empty
// line too.
void textWrappedAtSpaces(std::string_view text);
// The same text broken into lines ('\n') that fit `width` (ImGui units, current font).
std::string wrapAtSpaces(std::string_view text, float width);
// The width of its widest word (ImGui units, current font): what no line narrower than
// it holds whole. Words end where wrapAtSpaces may break ("passes = 1" is one word,
// "generalized-reflections" two).
// With `upTo`: the widest no wider than that (0 where none is).
float widestWord(std::string_view text, float upTo = 1e30f);

}  // namespace ui
