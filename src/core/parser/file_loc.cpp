#include "core/parser/file_loc.h"

namespace kiln {

std::string FileLoc::ToString() const {
    std::string s(filename);
    if (line > 0) {
        s += ':' + std::to_string(line);
        if (column > 0) s += ':' + std::to_string(column);
    }
    return s;
}

}  // namespace kiln
