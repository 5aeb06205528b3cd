#include "scenes/suggest.h"

#include <algorithm>
#include <cctype>

namespace scenes::detail {

namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

bool same(char a, char b) { return lower(a) == lower(b); }

// Edits (insert, delete, change, swap two neighbours) from a to b, ignoring case.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                                d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}

// "grav" for "gravity": the start of a name, at least three letters of it.
bool isPrefix(std::string_view word, std::string_view name) {
    if (word.size() < 3 || word.size() > name.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i) {
        if (!same(word[i], name[i])) return false;
    }
    return true;
}

}  // namespace

std::optional<std::string_view> closestName(std::string_view word,
                                            const std::vector<std::string_view>& candidates) {
    // A typo is about one edit in three letters; a longer distance is another word.
    std::optional<std::string_view> best;
    if (word.size() > 64) return best;  // no name is this long
    std::size_t bestDistance = std::max<std::size_t>(1, word.size() / 3) + 1;
    for (std::string_view candidate : candidates) {
        const std::size_t d = isPrefix(word, candidate) ? 1 : editDistance(word, candidate);
        if (d < bestDistance) {
            best = candidate;
            bestDistance = d;
        }
    }
    return best;
}

std::string joinNames(const std::vector<std::string_view>& names) {
    std::string out;
    for (std::string_view name : names) {
        if (!out.empty()) out += ", ";
        out += name;
    }
    return out;
}

std::string unknownName(std::string_view what, std::string_view word,
                        const std::vector<std::string_view>& candidates) {
    const std::string shown =
        word.size() > 60 ? std::string(word.substr(0, 57)) + "..." : std::string(word);
    std::string out = "unknown " + std::string(what) + " '" + shown + "'";
    if (const auto best = closestName(word, candidates)) {
        out += " (did you mean '" + std::string(*best) + "'?)";
    }
    return out + "; valid: " + joinNames(candidates);
}

}  // namespace scenes::detail
