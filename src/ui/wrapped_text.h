#pragma once
// Text wrapped to the window's width at spaces (and after the '/' of a path) only.
// ImGui's own wrapping also breaks after '.' and ',', which splits a number across
// lines ("-1." / "193").
#include <string_view>

namespace ui {

// The text, wrapped at spaces to the content region's width (a word wider than the
// line stands alone on its line). Newlines in the text are kept.
void textWrappedAtSpaces(std::string_view text);

}  // namespace ui
