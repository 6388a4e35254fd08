// What a render reads, for its identity: checkpoints and kiln merge compare it, so that a render
// is not resumed or merged with one whose scene, included files, meshes, textures, spectra or
// volumes have changed since.
#pragma once

#include <string>
#include <vector>

#include "render/scene_description.h"

namespace kiln {

// The files a scene reads: `parsed` (the scene file and its includes, as ParseFile returns
// them), then every regular file a string or spectrum parameter names (resolved as the
// parameter is: PLY meshes, image textures, spectrum files, .vdb volumes, ...), except the
// film's output. Each once, in that order.
std::vector<std::string> SceneInputFiles(const SceneDescription& desc,
                                         const std::vector<std::string>& parsed);

// 16 hexadecimal digits: a 64-bit hash of each file's name and bytes (after gzip
// decompression), in order; a file that cannot be read contributes its name and the reason.
std::string HashInputFiles(const std::vector<std::string>& files);

}  // namespace kiln
