#include "ui/wrapped_text.h"

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>  // ImTextCharFromUtf8

namespace ui {
namespace {

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

float widthOf(std::string_view text) { return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x; }

// No line is as wide as this many bytes of text (at least a few pixels a character, on a
// panel at most a few thousand pixels wide): a word is searched and measured no further,
// so that a text of one long word (a broken scene file's) wraps in linear time.
constexpr std::size_t kMostMeasured = 2048;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The word of `text` that ends just before `at` (a space), and the one that starts just
// after it.
std::string_view wordBefore(std::string_view text, std::size_t at) {
    const std::size_t space = text.rfind(' ', at == 0 ? 0 : at - 1);
    const std::size_t start = space == std::string_view::npos || space >= at ? 0 : space + 1;
    return text.substr(start, at - start);
}
std::string_view wordAfter(std::string_view text, std::size_t at) {
    const std::size_t end = std::min(text.find(' ', at + 1), text.size());
    return text.substr(at + 1, end - at - 1);
}

// A formula's operator standing as a word: "v ← μ v" and "|g| h / substeps" break around it no more than
// "passes = 1" does.
bool isOperator(std::string_view word) {
    for (const char* op : {"=", "\u2190", "\u2192", "+", "\u2212", "\u00d7", "\u00b7", "/", "\u2264", "\u2265", "\u2248", "<", ">"}) {
        if (word == op) return true;
    }
    return false;
}

// A unit after a number: "0.2 m/s", "10 s", "3.1 %" stay on one line (a class read "0.87" / "m/s").
bool isUnit(std::string_view word) {
    while (!word.empty() && std::string_view(",.;:)").find(word.back()) != std::string_view::npos) word.remove_suffix(1);
    for (const char* unit : {"m", "m/s", "cm/s", "mm/s", "\u00b5m/s", "m/s\u00b2", "s", "ms", "J", "kg", "%", "r", "mm", "cm",
                             "\u00b5m", "\u00b0", "Hz", "N", "px"}) {
        if (word == unit) return true;
    }
    return false;
}

// Whether a line may break at the space text[at]: not beside '=' or another operator, nor
// between a number and its unit.
bool breaksAt(std::string_view text, std::size_t at) {
    const std::string_view before = wordBefore(text, at), after = wordAfter(text, at);
    if (!before.empty() && before.back() == '=') return false;
    if (!after.empty() && after.front() == '=') return false;
    if (isOperator(before) || isOperator(after)) return false;
    return !(!before.empty() && isDigit(before.back()) && isUnit(after));
}

// The next space at or after `from` where a line may break (breaksAt). Searched up to
// kMostMeasured bytes on: none there, it returns where the search stopped (a line that long
// does not fit).
std::size_t nextBreak(std::string_view text, std::size_t from) {
    const std::size_t stop = std::min(text.size(), from + kMostMeasured);
    const std::string_view searched = text.substr(0, stop);
    for (std::size_t at = searched.find(' ', from); at != std::string_view::npos; at = searched.find(' ', at + 1)) {
        if (breaksAt(text, at)) return at;
    }
    return stop;
}

// The longest start of `word` that fits `width`, cut between characters (not inside a
// UTF-8 sequence), at least one character. The widths are summed character by character.
std::size_t cutToFit(std::string_view word, float width) {
    const ImFont* font = ImGui::GetFont();
    const float scale = ImGui::GetFontSize() / font->FontSize;
    float x = 0.0f;
    std::size_t fits = 0;
    for (std::size_t at = 0; at < word.size();) {
        unsigned int c = 0;
        const int bytes = ImTextCharFromUtf8(&c, word.data() + at, word.data() + word.size());
        x += font->GetCharAdvance(static_cast<ImWchar>(c)) * scale;
        if (x > width) break;
        at += std::size_t(std::max(bytes, 1));
        fits = at;
    }
    if (fits > 0) return std::min(fits, word.size());
    std::size_t one = 1;
    while (one < word.size() && (static_cast<unsigned char>(word[one]) & 0xC0) == 0x80) ++one;
    return one;
}

// Where a line that starts at text[0] ends: after as many whole words (up to a space,
// which the break eats) as fit `width`, at least one. A first word wider than the line
// breaks after its last '/' or hyphen between letters that fits (a long path,
// "generalized-reflections"),
// else at its last space that fits (beside an '=' if need be), else where the line is
// full (a hash in a narrow label: cut, not clipped).
std::size_t lineEnd(std::string_view text, float width) {
    std::size_t end = nextBreak(text, 1);
    if (widthOf(text.substr(0, end)) > width) {
        const std::size_t fit = cutToFit(text.substr(0, end), width);  // at least one character
        for (std::size_t mark = text.find_last_of("/-", fit - 1); mark != std::string_view::npos && mark > 0;
             mark = text.find_last_of("/-", mark - 1)) {
            if (text[mark] == '-' && !(isLetter(text[mark - 1]) && mark + 1 < text.size() && isLetter(text[mark + 1]))) {
                continue;  // a minus sign or an exponent ("-0.87", "1.2e-05"): a number stays whole
            }
            return mark + 1;
        }
        // "a = b" wider than the line: broken after its '=' rather than clipped ("method =" /
        // "reflection" in a view a third of a projector wide).
        const std::size_t space = text.rfind(' ', fit);
        return space != std::string_view::npos && space > 0 ? space : fit;
    }
    while (end < text.size()) {
        const std::size_t next = nextBreak(text, end + 1);
        if (widthOf(text.substr(0, next)) > width) break;
        end = next;
    }
    return end;
}

// One paragraph (no newline) as lines that fit `width`, each ended by '\n', into `out`. A
// last line of one short word takes the word before it too, where the line before keeps two
// or more ("v2⊥." alone under a paragraph).
void paragraph(std::string_view text, float width, std::string& out) {
    if (text.empty()) out += '\n';
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const std::size_t end = lineEnd(text, width);
        lines.push_back(text.substr(0, end));
        text.remove_prefix(end);
        if (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    }
    constexpr float kWidow = 0.3f;  // of the line's width: a word that short alone on the last line
    if (lines.size() >= 2 && nextBreak(lines.back(), 0) == lines.back().size() && widthOf(lines.back()) < kWidow * width) {
        std::string_view& before = lines[lines.size() - 2];
        std::size_t last = std::string_view::npos, breaks = 0;  // before's last break, and how many it has
        for (std::size_t at = nextBreak(before, 0); at < before.size(); at = nextBreak(before, at + 1)) last = at, ++breaks;
        if (breaks >= 2) {  // the lines are views of one text: the moved word, its space and the last line
            const char* from = before.data() + last + 1;
            const std::string_view moved(from, std::size_t(lines.back().data() + lines.back().size() - from));
            if (widthOf(moved) <= width) {
                before = before.substr(0, last);
                lines.back() = moved;
            }
        }
    }
    for (const std::string_view line : lines) {
        out.append(line.data(), line.size());
        out += '\n';
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

float widestWord(std::string_view text, float upTo) {
    float widest = 0.0f;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t newline = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, newline - start);
        for (std::size_t word = 0; word < line.size();) {
            const std::size_t end = nextBreak(line, word + 1);
            // A hyphen between letters, or a '/', breaks a word as lineEnd breaks it.
            for (std::size_t part = word; part < end;) {
                std::size_t next = part + 1;
                while (next < end && !(line[next - 1] == '/' || (line[next - 1] == '-' && next >= 2 &&
                                                                  isLetter(line[next - 2]) && isLetter(line[next])))) {
                    ++next;
                }
                const float width = widthOf(line.substr(part, next - part));
                if (width <= upTo) widest = std::max(widest, width);
                part = next;
            }
            word = end + 1;
        }
        start = newline + 1;
    }
    return widest;
}

void textWrappedAtSpaces(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f);
    const std::string lines = wrapAtSpaces(text, width);  // drawn as one item: as close as ImGui's own wrapped text
    ImGui::TextUnformatted(lines.data(), lines.data() + lines.size());
}

}  // namespace ui
