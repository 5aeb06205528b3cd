#pragma once
// Internal to spheres_scenes: "did you mean ...?" for misspelt names and keys.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scenes::detail {

// The candidate closest to `word` (edit distance, ignoring case), when it is
// close enough to be a typo of it.
std::optional<std::string_view> closestName(std::string_view word,
                                            const std::vector<std::string_view>& candidates);

// "a, b, c"
std::string joinNames(const std::vector<std::string_view>& names);

// "unknown <what> 'word' (did you mean 'x'?); valid <plural>: a, b, c"
std::string unknownName(std::string_view what, std::string_view word,
                        const std::vector<std::string_view>& candidates);

}  // namespace scenes::detail
