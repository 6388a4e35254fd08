#include "core/parser/suggestions.h"

#include <algorithm>
#include <vector>

namespace kiln {

size_t EditDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::optional<std::string> NearestName(std::string_view name,
                                       std::span<const std::string_view> candidates) {
    std::optional<std::string> best;
    size_t bestDistance = std::min<size_t>(3, (name.size() + 1) / 2);
    for (std::string_view c : candidates) {
        if (c == name) return std::nullopt;
        if (size_t d = EditDistance(name, c); d < bestDistance) {
            bestDistance = d;
            best = std::string(c);
        }
    }
    return best;
}

std::string DidYouMean(std::string_view name, std::span<const std::string_view> candidates) {
    std::optional<std::string> nearest = NearestName(name, candidates);
    return nearest ? "; did you mean \"" + *nearest + "\"?" : "";
}

}  // namespace kiln
