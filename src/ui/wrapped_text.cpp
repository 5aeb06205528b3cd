#include "ui/wrapped_text.h"

#include <algorithm>

#include <imgui.h>

namespace ui {
namespace {

float widthOf(std::string_view text) { return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x; }

// Where a line may end after `from`: at the next space (which the break eats), or
// after the next '/' (a long path breaks between its folders); text.size() if none.
std::size_t nextBreak(std::string_view text, std::size_t from) {
    const std::size_t space = text.find(' ', from), slash = text.find('/', from);
    if (slash != std::string_view::npos && (space == std::string_view::npos || slash + 1 < space)) return slash + 1;
    return std::min(space, text.size());
}

// One paragraph (no newline), as lines of whole words that fit `width`.
void paragraph(std::string_view text, float width) {
    while (!text.empty()) {
        std::size_t end = nextBreak(text, 1);  // the line is text[0, end): at least one word
        for (std::size_t next = end; next < text.size(); end = next) {
            next = nextBreak(text, next + 1);
            if (widthOf(text.substr(0, next)) > width) break;
        }
        ImGui::TextUnformatted(text.data(), text.data() + end);
        text.remove_prefix(end);
        if (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    }
}

}  // namespace

void textWrappedAtSpaces(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f);
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t newline = std::min(text.find('\n', start), text.size());
        paragraph(text.substr(start, newline - start), width);
        start = newline + 1;
    }
}

}  // namespace ui
