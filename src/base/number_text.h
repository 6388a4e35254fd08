// Text files of numbers (spectrum files, lens files): '#' comments to the end of a line, numbers
// separated by white space or commas, every number finite.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

// The numbers of `text` in order; nullopt with "line N: not a finite number: 'token'" in *error
// for the first token that is not one.
std::optional<std::vector<Float>> ParseNumberText(const std::string& text, std::string* error);

}  // namespace kiln
