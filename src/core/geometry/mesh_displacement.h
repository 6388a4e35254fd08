// Displacement of PLY meshes (pbrt-v4's "plymesh" "texture displacement" and "float
// edgelength"): the mesh is refined until every edge is shorter than the edge length, then each
// vertex moves along its normal by the displacement there, and the normals are recomputed.
#pragma once

#include <cstddef>
#include <functional>

#include "base/transform.h"
#include "core/geometry/ply_reader.h"

namespace kiln {

struct MeshDisplacement {
    // The displacement (object-space units along the unit vertex normal) at an object-space
    // point with its normal and uv, as pbrt-v4 evaluates it.
    std::function<Float(Point3f p, Normal3f n, Point2f uv)> displace;
    // Longest edge after refinement, measured in render space (> 0).
    Float edgeLength = 1;
};

// Displaces mesh in place, as pbrt-v4's TriQuadMesh::Displace: quads become two triangles
// (p00 p10 p11, p00 p11 p01); missing normals are computed first; each triangle is split at the
// midpoint of its longest edge (shared between neighbours, so the mesh stays watertight) until
// all edges are shorter than edgeLength, or until a midpoint falls on an end of its edge in
// single precision; vertex attributes, uv and normals are interpolated at the midpoints and face
// indices inherited; after displacing, each vertex normal is the normalised sum of its
// triangles' unit normals. Throws std::length_error when the refined mesh would have more than
// maxTriangles triangles (before refining when the longest edges alone need more),
// std::invalid_argument without uv.
void DisplaceMesh(TriQuadMesh& mesh, const MeshDisplacement& displacement,
                  const Transform& renderFromObject, size_t maxTriangles);

// The vertex normals of a triangle mesh: per vertex the normalised sum of the unit normals of
// the triangles around it (zero where all of them are degenerate).
std::vector<Normal3f> VertexNormals(const std::vector<Point3f>& p, const std::vector<int>& tris);

}  // namespace kiln
