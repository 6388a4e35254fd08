// "Did you mean" suggestions for misspelled names (options, shapes, parameters).
#pragma once

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace kiln {

// Levenshtein distance between a and b (insertions, deletions, substitutions).
size_t EditDistance(std::string_view a, std::string_view b);

// The candidate nearest to `name` when it is close: at most two edits away and fewer edits than
// half of name's length (so "sp" does not suggest "spot"); ties go to the first. nullopt when
// none is close, or name is itself a candidate.
std::optional<std::string> NearestName(std::string_view name,
                                       std::span<const std::string_view> candidates);

// "; did you mean \"X\"?" for NearestName, "" when there is none.
std::string DidYouMean(std::string_view name, std::span<const std::string_view> candidates);
inline std::string DidYouMean(std::string_view name,
                              std::initializer_list<std::string_view> candidates) {
    return DidYouMean(name,
                      std::span<const std::string_view>(candidates.begin(), candidates.size()));
}

}  // namespace kiln
