#include "ui/wrapped_text.h"

#include <algorithm>
#include <string>

#include <imgui.h>

namespace ui {
namespace {

float widthOf(std::string_view text) { return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x; }

// Where a line that starts at text[0] ends: after as many whole words (up to a
// space, which the break eats) as fit `width`, at least one. A first word wider than
// the line (a long path) breaks after its last '/' that fits, if it has one.
std::size_t lineEnd(std::string_view text, float width) {
    std::size_t end = std::min(text.find(' ', 1), text.size());
    if (widthOf(text.substr(0, end)) > width) {
        for (std::size_t slash = text.rfind('/', end - 1); slash != std::string_view::npos && slash > 0;
             slash = text.rfind('/', slash - 1)) {
            if (widthOf(text.substr(0, slash + 1)) <= width) return slash + 1;
        }
        return end;
    }
    while (end < text.size()) {
        const std::size_t next = std::min(text.find(' ', end + 1), text.size());
        if (widthOf(text.substr(0, next)) > width) break;
        end = next;
    }
    return end;
}

// One paragraph (no newline) as lines that fit `width`, each ended by '\n', into `out`.
void paragraph(std::string_view text, float width, std::string& out) {
    if (text.empty()) out += '\n';
    while (!text.empty()) {
        const std::size_t end = lineEnd(text, width);
        out.append(text.data(), end);
        out += '\n';
        text.remove_prefix(end);
        if (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    }
}

}  // namespace

std::string wrapAtSpaces(std::string_view text, float width) {
    std::string lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t newline = std::min(text.find('\n', start), text.size());
        paragraph(text.substr(start, newline - start), width, lines);
        start = newline + 1;
    }
    if (!lines.empty()) lines.pop_back();  // the last line's '\n'
    return lines;
}

void textWrappedAtSpaces(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f);
    const std::string lines = wrapAtSpaces(text, width);  // drawn as one item: as close as ImGui's own wrapped text
    ImGui::TextUnformatted(lines.data(), lines.data() + lines.size());
}

}  // namespace ui
