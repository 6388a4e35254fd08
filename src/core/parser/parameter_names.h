// The names of scene-file parameters that kiln or pbrt-v4 reads anywhere. A parameter that no
// object used is an error when its name is not one of these (a misspelling: "temprature"), with
// the nearest name suggested, and a warning when it is (a pbrt-v4 parameter kiln does not use,
// or a valid name in the wrong place): ParameterDictionary::ReportUnused.
#pragma once

#include <span>
#include <string_view>

namespace kiln {

// Sorted, unique.
std::span<const std::string_view> KnownParameterNames();
bool IsKnownParameterName(std::string_view name);

}  // namespace kiln
