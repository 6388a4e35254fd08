// FileLoc: a position in a scene file, carried by every token, directive and parameter.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace kiln {

// Line and column are 1-based; columns count bytes (a tab is one column). `filename` views a
// string kept alive by `storage`, so a FileLoc stays valid after its file has been parsed and
// may be copied freely. A default FileLoc (line 0) means "no position known".
struct FileLoc {
    std::string_view filename;
    int line = 0;
    int column = 0;
    std::shared_ptr<const std::string> storage;

    FileLoc() = default;
    FileLoc(std::shared_ptr<const std::string> file, int line, int column)
        : filename(file ? std::string_view(*file) : std::string_view()),
          line(line),
          column(column),
          storage(std::move(file)) {}

    // "file:line:column", "file" when the line is unknown, "" when nothing is known.
    std::string ToString() const;
};

}  // namespace kiln
