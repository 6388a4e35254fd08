// ParsedParameter: one "type name" value list from a scene directive, as pbrt-v4 has it.
//
// Declarations are "type name". Types (pbrt-v4 names, with the aliases pbrt-v3 scenes used):
//   integer, float, bool, string, texture, point2, vector2, point3 (point), vector3 (vector),
//   normal (normal3), rgb (color), spectrum, blackbody.
// Aliases are stored under their canonical name. Values are a bracketed list or one value.
// Integers go to `ints` (a non-integral number is truncated toward zero with a
// warning, as pbrt-v4 does); float, point*, vector*, normal, rgb and blackbody values to `floats`;
// bools (bare or quoted true/false) to `bools`; string and texture values to `strings`. A spectrum
// holds either (wavelength, value) pairs in `floats` or quoted named spectra / filenames in
// `strings`, never both. The parser has already checked value kinds and counts (a multiple of
// 2 for point2/vector2 and spectrum pairs, of 3 for point3, vector3, normal and rgb); an
// empty list [ ] is accepted here and rejected by the ParameterDictionary lookups.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/vecmath.h"
#include "core/parser/file_loc.h"

namespace kiln {

struct ParsedParameter {
    std::string type;  // Canonical type name.
    std::string name;
    FileLoc loc;  // Where the declaration string starts.
    std::vector<Float> floats;
    std::vector<int> ints;
    std::vector<std::string> strings;
    std::vector<uint8_t> bools;
    // The top-level scene file's directory ("" for ParseString without one): relative
    // filenames in the values are resolved against it (ResolveFilename, search_path.h).
    std::string searchDirectory;
    // Set by ParameterDictionary lookups; parameters never looked up are reported.
    mutable bool lookedUp = false;
    // Set by the scene builder for parameters that need not be used (e.g. from Attribute).
    bool mayBeUnused = false;

    // "type name", as in warnings: unused parameter 'float foo'.
    std::string Declaration() const { return type + " " + name; }
    // The parameter in scene-file syntax: "float foo" [ 1 2 ].
    std::string ToString() const;
};

using ParsedParameterVector = std::vector<ParsedParameter>;

// What the values of a parameter type are written as.
enum class ParameterValueKind { Int, Float, Bool, String, FloatOrString };

// The canonical type for `type` (resolving aliases), or "" if `type` is unknown.
std::string_view CanonicalParameterType(std::string_view type);
// For canonical types only.
ParameterValueKind ValueKindOf(std::string_view canonicalType);
// Numbers per item: 2 for point2/vector2 and spectrum pairs, 3 for point3/vector3/normal/rgb,
// 1 otherwise.
int ValuesPerItem(std::string_view canonicalType);

}  // namespace kiln
