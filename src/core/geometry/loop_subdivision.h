// Loop subdivision surfaces (pbrt-v4's "loopsubdiv" shape; C. Loop, "Smooth Subdivision
// Surfaces Based on Triangles", 1987): a triangle mesh refined `levels` times, each triangle
// split in four, new edge vertices at 3/8 (a + b) + 1/8 (c + d) (1/2 (a + b) on boundaries) and
// old vertices smoothed with Warren's weights beta = 3 / (8 n) (3/16 for valence 3; 3/4 and 1/8
// along boundaries); then every vertex is moved to its limit position and given the limit
// surface's normal (the tangent masks of Hoppe et al. 1994), oriented with the faces around it.
// Edges shared by other than two triangles are treated as boundaries, and vertices on other than
// two boundary edges stay where they are.
#pragma once

#include <span>
#include <vector>

#include "base/vecmath.h"

namespace kiln {

struct SubdividedMesh {
    std::vector<Point3f> p;
    std::vector<Normal3f> n;  // per vertex, unit (zero where the limit normal is undefined)
    std::vector<int> indices;
};

// indices: triangles into p (checked by the caller). levels >= 0.
SubdividedMesh LoopSubdivide(std::span<const int> indices, std::span<const Point3f> p, int levels);

}  // namespace kiln
