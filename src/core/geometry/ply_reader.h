// PLY reader (ascii, binary_little_endian, binary_big_endian) for triangle and quad meshes,
// as pbrt-v4's plymesh shape reads them.
//
// Vertex properties: x y z; nx ny nz; u v (or s t, texture_u texture_v, texture_s
// texture_t); every other scalar vertex property is kept by name as a float attribute (e.g.
// "temperature"). Faces: a list property vertex_indices (or vertex_index) of 3 or 4 entries
// and an optional face_indices scalar. Quads that are planar become two triangles, the others
// bilinear patches (corner order p00 p10 p01 p11). Malformed files throw SceneError naming
// the file.
#pragma once

#include "base/file_reading.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct TriQuadMesh {
    std::vector<Point3f> p;
    std::vector<Normal3f> n;
    std::vector<Point2f> uv;
    std::vector<int> triIndices;                       // 3 per triangle
    std::vector<int> quadIndices;                      // 4 per bilinear patch: p00 p10 p01 p11
    std::vector<int> triFaceIndices, quadFaceIndices;  // empty, or one per triangle / patch
    std::map<std::string, std::vector<Float>> vertexAttributes;  // one value per vertex

    // Reads the file; throws SceneError (file name, and line for ascii) when malformed.
    // beforeData, if given, learns the vertex and face counts the header declares before any
    // element is read (to charge their memory; it may throw). A file whose bytes (decompressed)
    // pass maxBytes is an error.
    using HeaderCounts = std::function<void(double vertices, double faces)>;
    static TriQuadMesh ReadPLY(const std::string& filename, const HeaderCounts& beforeData = {},
                               uint64_t maxBytes = DefaultMaxInputBytes());
    // The same from the file's bytes (filename only names it in errors).
    static TriQuadMesh ParsePLY(const std::string& data, const std::string& filename,
                                const HeaderCounts& beforeData = {});
};

}  // namespace kiln
