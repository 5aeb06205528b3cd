#include "scenes/json_locate.h"

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

namespace scenes::detail {

namespace {

// Nesting deeper than this is skipped, not searched for duplicate keys (scenes need 5).
constexpr int kMaxDepth = 64;

// A cursor over a JSON text that nlohmann has accepted (up to where it failed):
// it skips values without building them and never reads past the end.
class Walker {
  public:
    explicit Walker(std::string_view text) : text_(text) {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // UTF-8 byte order mark
    }

    std::size_t at() {
        skipSpace();
        return at_;
    }
    char peek() { return at() < text_.size() ? text_[at_] : '\0'; }
    bool take(char c) {
        if (peek() != c) return false;
        ++at_;
        return true;
    }

    // At '"': the decoded string, the cursor after it.
    std::string readString() {
        const std::size_t start = at();
        skipString();
        const std::string_view raw = text_.substr(start, at_ - start);
        if (raw.find('\\') == std::string_view::npos) {
            return std::string(raw.substr(1, raw.size() - 2));
        }
        try {
            return nlohmann::json::parse(raw).get<std::string>();
        } catch (const nlohmann::json::exception&) {
            return std::string(raw);
        }
    }

    // Any value, however deep, without recursion.
    void skipValue() {
        int depth = 0;
        do {
            const char c = peek();
            if (c == '\0') return;
            if (c == '"') {
                skipString();
            } else if (c == '{' || c == '[') {
                ++depth;
                ++at_;
            } else if (c == '}' || c == ']') {
                --depth;
                ++at_;
            } else if (c == ',' || c == ':') {
                ++at_;
            } else {
                skipToken();
            }
        } while (depth > 0);
    }

  private:
    void skipSpace() {
        while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' ||
                                      text_[at_] == '\n' || text_[at_] == '\r')) {
            ++at_;
        }
    }
    void skipString() {
        ++at_;  // the opening quote
        while (at_ < text_.size() && text_[at_] != '"') at_ += text_[at_] == '\\' ? 2 : 1;
        at_ = std::min(at_ + 1, text_.size());
    }
    // A number or a literal (true, false, null).
    void skipToken() {
        const std::size_t start = at_;
        while (at_ < text_.size() &&
               std::string_view("{}[],:\" \t\n\r").find(text_[at_]) == std::string_view::npos) {
            ++at_;
        }
        if (at_ == start) ++at_;  // never stall on a stray character
    }

    std::string_view text_;
    std::size_t at_ = 0;
};

std::vector<std::string> splitPointer(std::string_view pointer) {
    std::vector<std::string> tokens;
    std::size_t start = 1;
    while (start <= pointer.size() && !pointer.empty()) {
        const std::size_t end = std::min(pointer.find('/', start), pointer.size());
        std::string token(pointer.substr(start, end - start));
        for (std::size_t i = 0; (i = token.find('~', i)) != std::string::npos; ++i) {
            token.replace(i, 2, i + 1 < token.size() && token[i + 1] == '1' ? "/" : "~");
        }
        tokens.push_back(token);
        start = end + 1;
    }
    return tokens;
}

bool isIndex(const std::string& token) {
    return !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
}

// Moves the walker onto member `key` of the object it stands on; the key's offset.
std::optional<std::size_t> enterMember(Walker& w, const std::string& key) {
    if (!w.take('{')) return std::nullopt;
    while (w.peek() == '"') {
        const std::size_t keyAt = w.at();
        const bool found = w.readString() == key;
        w.take(':');
        if (found) return keyAt;
        w.skipValue();
        if (!w.take(',')) break;
    }
    return std::nullopt;
}

// Moves the walker onto element `index` of the array it stands on.
bool enterElement(Walker& w, const std::string& token) {
    if (!isIndex(token) || token.size() > 9 || !w.take('[')) return false;
    for (long n = std::stol(token); n > 0; --n) {
        if (w.peek() == ']' || w.peek() == '\0') return false;
        w.skipValue();
        if (!w.take(',')) return false;
    }
    return w.peek() != ']' && w.peek() != '\0';
}

std::optional<DuplicateKey> findDuplicate(Walker& w, const std::string& pointer, int depth) {
    if (depth > kMaxDepth || (w.peek() != '{' && w.peek() != '[')) {
        w.skipValue();
        return std::nullopt;
    }
    const bool object = w.take('{');
    if (!object) w.take('[');
    std::set<std::string> seen;
    for (std::size_t index = 0; w.peek() != '}' && w.peek() != ']' && w.peek() != '\0'; ++index) {
        std::string child = childPointer(pointer, index);
        if (object) {
            const std::size_t keyAt = w.at();
            const std::string key = w.readString();
            child = childPointer(pointer, key);
            if (!seen.insert(key).second) return DuplicateKey{child, keyAt};
            w.take(':');
        }
        if (auto found = findDuplicate(w, child, depth + 1)) return found;
        if (!w.take(',')) break;
    }
    w.take(object ? '}' : ']');
    return std::nullopt;
}

}  // namespace

TextPosition positionOf(std::string_view text, std::size_t offset) {
    TextPosition position;
    offset = std::min(offset, text.size());
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++position.line;
            position.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++position.column;  // count code points, not UTF-8 continuation bytes
        }
    }
    return position;
}

std::size_t offsetOf(std::string_view text, std::string_view pointer, bool atKey) {
    Walker w(text);
    std::size_t best = w.at();
    const std::vector<std::string> tokens = splitPointer(pointer);
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const bool last = i + 1 == tokens.size();
        if (w.peek() == '{') {
            const auto keyAt = enterMember(w, tokens[i]);
            if (!keyAt) return best;
            if (last && atKey) return *keyAt;
        } else if (!enterElement(w, tokens[i])) {
            return best;
        }
        best = w.at();
    }
    return best;
}

std::optional<std::size_t> nonFiniteNumber(std::string_view text) {
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            if (c == '"') inString = false;
            continue;
        }
        if (c == '"') inString = true;
        if (c != '-' && (c < '0' || c > '9')) continue;
        const std::size_t end = text.find_first_not_of("+-.0123456789eE", i);
        const std::string token(text.substr(i, end - i));
        if (!std::isfinite(std::strtod(token.c_str(), nullptr))) return i;
        i = std::min(end, text.size()) - 1;
    }
    return std::nullopt;
}

std::optional<DuplicateKey> duplicateKey(std::string_view text) {
    Walker w(text);
    return findDuplicate(w, "", 0);
}

std::string readablePath(std::string_view pointer) {
    std::string out;
    for (const std::string& token : splitPointer(pointer)) {
        if (isIndex(token)) {
            out += "[" + token + "]";
        } else {
            out += (out.empty() ? "" : ".") + token;
        }
    }
    return out;
}

std::string childPointer(const std::string& pointer, std::string_view key) {
    std::string escaped;
    for (char c : key) {
        escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    }
    return pointer + "/" + escaped;
}

std::string childPointer(const std::string& pointer, std::size_t index) {
    return pointer + "/" + std::to_string(index);
}

}  // namespace scenes::detail
