// Displaced PLY meshes (core/geometry/mesh_displacement.h): refined until every render-space
// edge is shorter than the edge length, watertight, each vertex moved along its normal by the
// displacement, normals recomputed from the displaced surface; bad input reported.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "core/geometry/mesh_displacement.h"

namespace kiln {
namespace {

// The unit square z = 0 as one quad (p00 p10 p01 p11) with uv = (x, y) and a per-vertex
// attribute equal to x.
TriQuadMesh Square() {
    TriQuadMesh m;
    m.p = {Point3f(0, 0, 0), Point3f(1, 0, 0), Point3f(0, 1, 0), Point3f(1, 1, 0)};
    m.uv = {Point2f(0, 0), Point2f(1, 0), Point2f(0, 1), Point2f(1, 1)};
    m.quadIndices = {0, 1, 2, 3};
    m.quadFaceIndices = {7};
    m.vertexAttributes["temperature"] = {0, 1, 0, 1};
    return m;
}

Float MaxEdge(const TriQuadMesh& m, const Transform& t) {
    Float e = 0;
    for (size_t i = 0; i < m.triIndices.size(); i += 3)
        for (int k = 0; k < 3; ++k)
            e = std::max(e, Distance(t(m.p[size_t(m.triIndices[i + k])]),
                                     t(m.p[size_t(m.triIndices[i + (k + 1) % 3])])));
    return e;
}

TEST(MeshDisplacement, RefinesWatertightAndDisplacesAlongNormals) {
    TriQuadMesh m = Square();
    MeshDisplacement d{[](Point3f, Normal3f, Point2f uv) { return 0.5f * uv.x; }, 0.2f};
    DisplaceMesh(m, d, Transform(), 1 << 20);
    EXPECT_TRUE(m.quadIndices.empty());
    EXPECT_LT(MaxEdge(m, Transform()), 0.2f);
    EXPECT_GT(m.triIndices.size() / 3, 50u);
    EXPECT_EQ(m.triFaceIndices.size(), m.triIndices.size() / 3);
    for (int f : m.triFaceIndices) EXPECT_EQ(f, 7);
    // Watertight: every edge is shared by two triangles, or lies on the square's boundary
    std::map<std::pair<int, int>, int> edges;
    for (size_t i = 0; i < m.triIndices.size(); i += 3)
        for (int k = 0; k < 3; ++k) {
            int a = m.triIndices[i + k], b = m.triIndices[i + (k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}] += 1;
        }
    for (auto& [e, count] : edges) {
        Point2f ua = m.uv[size_t(e.first)], ub = m.uv[size_t(e.second)];
        bool boundary = (ua.x == ub.x && (ua.x == 0 || ua.x == 1)) ||
                        (ua.y == ub.y && (ua.y == 0 || ua.y == 1));
        EXPECT_EQ(count, boundary ? 1 : 2);
    }
    // z = 0.5 x everywhere, normals those of that plane, attributes still linear in x
    const std::vector<Float>& attr = m.vertexAttributes["temperature"];
    ASSERT_EQ(attr.size(), m.p.size());
    Vector3f plane = Normalize(Vector3f(-0.5f, 0, 1));
    for (size_t i = 0; i < m.p.size(); ++i) {
        EXPECT_NEAR(m.p[i].z, 0.5f * m.uv[i].x, 1e-5f);
        EXPECT_NEAR(m.p[i].x, m.uv[i].x, 1e-6f);
        EXPECT_NEAR(attr[i], m.uv[i].x, 1e-6f);
        EXPECT_NEAR(Dot(Vector3f(m.n[i]), plane), 1, 1e-4f);
    }
}

TEST(MeshDisplacement, EdgeLengthIsMeasuredInRenderSpace) {
    TriQuadMesh m = Square();
    MeshDisplacement d{[](Point3f, Normal3f, Point2f) { return 0.f; }, 1.f};
    Transform scale = Scale(10, 10, 10);
    DisplaceMesh(m, d, scale, 1 << 20);
    EXPECT_LT(MaxEdge(m, scale), 1.f);
    EXPECT_GT(MaxEdge(m, scale), 0.5f);  // split no further than needed
}

TEST(MeshDisplacement, BadInputIsReported) {
    MeshDisplacement d{[](Point3f, Normal3f, Point2f) { return 0.f; }, 0.001f};
    TriQuadMesh tooFine = Square();
    EXPECT_THROW(DisplaceMesh(tooFine, d, Transform(), 10000), std::length_error);
    TriQuadMesh noUV = Square();
    noUV.uv.clear();
    EXPECT_THROW(DisplaceMesh(noUV, d, Transform(), 10000), std::invalid_argument);
}

// Edge lengths below single precision's resolution of the mesh. An edge length of 1e-38 fails
// at once (its longest edges alone need more pieces than allowed; it refined 2^25 triangles,
// 84 s, first). A square 1e7 from the origin, where float's spacing is 1, refined to 0.3
// bisected until midpoints fell on their ends, then recursed until the stack overflowed; it
// now stops there.
TEST(MeshDisplacement, EdgeLengthsBelowFloatResolutionEndInErrorsOrStopAtIt) {
    MeshDisplacement tiny{[](Point3f, Normal3f, Point2f) { return 0.f; }, 1e-38f};
    TriQuadMesh square = Square();
    EXPECT_THROW(DisplaceMesh(square, tiny, Transform(), 1 << 25), std::length_error);
    MeshDisplacement fine{[](Point3f, Normal3f, Point2f) { return 0.f; }, 0.3f};
    TriQuadMesh far = Square();
    for (Point3f& p : far.p) p = Point3f(1e7f + 4 * p.x, 1e7f + 4 * p.y, 0);
    DisplaceMesh(far, fine, Transform(), 1 << 20);
    EXPECT_GT(far.triIndices.size(), 6u);
    EXPECT_LE(MaxEdge(far, Transform()), 2.f);  // split to float's spacing (1), not to 0.3
}

}  // namespace
}  // namespace kiln
