// Scene-file parser for the pbrt-v4 format: turns text into ParserTarget calls.
//
// Directives are checked for argument count and kind (e.g. Translate takes exactly three
// numbers, Transform and ConcatTransform sixteen numbers in brackets, LookAt nine, Rotate
// four, TransformTimes two) and parameter lists for known types, value kinds and counts; any
// violation throws SceneError with the file:line:column of the offending token. Warnings
// (deprecated TransformBegin/End, repeated parameter names, extra words in a parameter
// declaration) go to the Diagnostics.
//
// Filenames (pbrt-v4 behaviour): the search directory is the directory of the top-level scene
// file. `Include "f"` and `Import "f"` resolve f with ResolveFilename(searchDirectory, f) (see
// search_path.h): relative names are taken relative to the top-level file's directory even
// in nested includes, falling back to the working directory when no such file exists there.
//  - Include splices the file's tokens into the stream at that point; it may appear anywhere.
//  - Import is only allowed after WorldBegin (as in pbrt-v4). It is parsed synchronously, as
//    a self-contained file, enclosed in AttributeBegin/AttributeEnd calls (located at the
//    Import) so that graphics-state changes inside it do not leak out, which is what
//    pbrt-v4's separate import parse achieves. Named materials, textures and objects it
//    defines stay visible afterwards, as in pbrt-v4.
// Including or importing a file that is already being parsed (directly or indirectly) is an
// error. Every ParsedParameter gets the search directory in its `searchDirectory` field.
// Parameter lists end at the first token that is not a quoted string (the next directive).
// WorldEnd (pbrt-v3) is ignored with a warning. Numbers are parsed with std::from_chars
// (no inf/nan/hex); a 10 MB mesh parses in well under 0.1 s.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/file_reading.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parser_target.h"
#include "core/parser/search_path.h"

namespace kiln {

// Parses `filename` (its directory becomes the search directory), then calls EndOfFiles().
// Returns the files read: `filename`, then those of every Include and Import, in order. A file
// whose contents (decompressed) pass maxFileBytes is an error (kiln --memory-limit).
std::vector<std::string> ParseFile(ParserTarget& target, const std::string& filename,
                                   Diagnostics& diagnostics,
                                   uint64_t maxFileBytes = DefaultMaxInputBytes());

// Parses `text`; FileLocs report `pseudoFilename`. Relative Include/Import names resolve
// against `searchDirectory` ("" = the working directory). Calls EndOfFiles() at the end.
void ParseString(ParserTarget& target, std::string_view text, Diagnostics& diagnostics,
                 std::string_view pseudoFilename = "<string>",
                 const std::string& searchDirectory = "");

}  // namespace kiln
