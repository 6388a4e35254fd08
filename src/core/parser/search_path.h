// Scene search directory and filename resolution, following pbrt-v4.
//
// pbrt-v4 sets one "search directory" per scene: the directory containing the top-level scene
// file (or the argument itself if it is a directory). Every relative filename in the scene --
// Include, Import, textures, PLY meshes, spectrum files -- is looked up there, whatever file
// (including a nested Include) it was written in. ResolveFilename(dir, f) returns
//   - f unchanged if f is empty, absolute, or dir is empty;
//   - dir/f (lexically normalised) if that file exists;
//   - f unchanged otherwise, so it is then tried relative to the working directory.
#pragma once

#include <string>

namespace kiln {

// The search directory for a top-level scene file: its parent directory ("" for a bare
// filename in the working directory), or the path itself if it names a directory.
std::string SearchDirectoryFor(const std::string& sceneFilename);

std::string ResolveFilename(const std::string& searchDirectory, const std::string& filename);

}  // namespace kiln
