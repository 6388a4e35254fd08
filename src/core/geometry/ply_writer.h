// Writes triangle meshes as binary little-endian PLY files that kiln's (and pbrt-v4's) PLY
// reader reads back exactly: vertex x y z, optionally nx ny nz, u v and further float vertex
// attributes (e.g. "temperature"), and faces as uchar-counted int vertex_indices with an
// optional int face_indices.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct PlyTriangles {
    std::vector<Point3f> p;
    std::vector<Normal3f> n;                                     // empty or one per vertex
    std::vector<Point2f> uv;                                     // empty or one per vertex
    std::vector<int> indices;                                    // three per triangle
    std::vector<int> faceIndices;                                // empty or one per triangle
    std::map<std::string, std::vector<Float>> vertexAttributes;  // one value per vertex each
};

// The bytes of the PLY file. Throws std::invalid_argument for inconsistent sizes.
std::string EncodePly(const PlyTriangles& mesh);

}  // namespace kiln
