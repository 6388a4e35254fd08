#include "core/parser/search_path.h"

#include <filesystem>

namespace kiln {

namespace fs = std::filesystem;

std::string SearchDirectoryFor(const std::string& sceneFilename) {
    std::error_code ec;
    fs::path path(sceneFilename);
    if (fs::is_directory(path, ec)) return path.string();
    return path.parent_path().string();
}

std::string ResolveFilename(const std::string& searchDirectory, const std::string& filename) {
    if (filename.empty() || searchDirectory.empty() || fs::path(filename).is_absolute())
        return filename;
    fs::path candidate = (fs::path(searchDirectory) / filename).lexically_normal();
    std::error_code ec;
    if (fs::exists(candidate, ec)) return candidate.string();
    return filename;
}

}  // namespace kiln
