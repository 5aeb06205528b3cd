#pragma once
// Text wrapped to the window's width at spaces only (a path wider than the line also
// after a '/').
// ImGui's own wrapping also breaks after '.' and ',', which splits a number across
// lines ("-1." / "193").
#include <string>
#include <string_view>

namespace ui {

// The text, wrapped at spaces to the content region's width (a word wider than the
// line stands alone on its line, or breaks after a '/'). Newlines are kept, an empty
// line too.
void textWrappedAtSpaces(std::string_view text);
// The same text broken into lines ('\n') that fit `width` (ImGui units, current font).
std::string wrapAtSpaces(std::string_view text, float width);

}  // namespace ui
