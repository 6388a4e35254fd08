// Loop subdivision ("loopsubdiv"): topology of the refined mesh, the limit surface of closed and
// open meshes (symmetric, inside the control hull, flat where the control mesh is flat), limit
// normals oriented with the faces and varying smoothly, and the shape created from a scene's
// parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "../textures/param_helpers.h"
#include "core/geometry/loop_subdivision.h"
#include "core/geometry/shape.h"

namespace kiln {
namespace {

// A regular octahedron of radius 1, triangles wound counter-clockwise seen from outside.
const std::vector<Point3f> kOctahedronP = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                           {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
const std::vector<int> kOctahedron = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                      2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

// Every edge of a closed mesh is shared by exactly two triangles, once in each direction.
void ExpectClosedManifold(const std::vector<int>& idx) {
    std::map<std::pair<int, int>, int> directed;
    for (size_t f = 0; f < idx.size(); f += 3)
        for (int k = 0; k < 3; ++k) ++directed[{idx[f + k], idx[f + (k + 1) % 3]}];
    for (const auto& [e, count] : directed) {
        ASSERT_EQ(count, 1) << e.first << "-" << e.second;
        ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "open edge";
    }
}

TEST(LoopSubdivision, RefinesClosedMeshesIntoClosedMeshes) {
    for (int levels : {0, 1, 2, 3}) {
        SubdividedMesh m = LoopSubdivide(kOctahedron, kOctahedronP, levels);
        size_t faces = 8 * size_t(std::pow(4, levels));
        ASSERT_EQ(m.indices.size(), 3 * faces);
        // Euler: V - E + F = 2 with E = 3F/2
        EXPECT_EQ(m.p.size(), 2 + faces / 2);
        ExpectClosedManifold(m.indices);
    }
}

TEST(LoopSubdivision, OctahedronLimitIsSymmetricInsideTheHullWithOutwardNormals) {
    SubdividedMesh m = LoopSubdivide(kOctahedron, kOctahedronP, 4);
    // The six original vertices are alike; so are the twelve edge midpoints of level 1
    for (int v = 1; v < 6; ++v)
        EXPECT_NEAR(Length(Vector3f(m.p[size_t(v)])), Length(Vector3f(m.p[0])), 1e-5f);
    for (size_t v = 0; v < m.p.size(); ++v) {
        Vector3f p(m.p[v]);
        // Inside the control hull |x| + |y| + |z| <= 1 (Loop's weights are positive), and
        // not collapsed towards the centre
        ASSERT_LE(std::abs(p.x) + std::abs(p.y) + std::abs(p.z), 1 + 1e-5f);
        ASSERT_GT(Length(p), 0.4f);  // the original vertices end at 0.5, face centres nearer
        ASSERT_NEAR(Length(Vector3f(m.n[v])), 1, 1e-4f);
        ASSERT_GT(Dot(Vector3f(m.n[v]), Normalize(p)), 0.8f) << "normal not outward at " << v;
    }
    // The octahedron's mirror symmetries hold for the limit surface: every vertex's mirror
    // image in x = 0 and its image under x -> y -> z -> x are vertices too
    auto has = [&](Point3f q) {
        for (const Point3f& r : m.p)
            if (Distance(q, r) < 1e-5f) return true;
        return false;
    };
    for (const Point3f& q : m.p) {
        ASSERT_TRUE(has(Point3f(-q.x, q.y, q.z)));
        ASSERT_TRUE(has(Point3f(q.z, q.x, q.y)));
    }
    // Smooth: the largest angle between the normals of an edge's two ends shrinks with each
    // level (by about 0.7 near the valence-4 vertices, where convergence is slowest)
    auto maxAngle = [](const SubdividedMesh& mesh) {
        Float worst = 0;
        for (size_t f = 0; f < mesh.indices.size(); f += 3)
            for (int k = 0; k < 3; ++k) {
                Normal3f a = mesh.n[size_t(mesh.indices[f + k])],
                         b = mesh.n[size_t(mesh.indices[f + (k + 1) % 3])];
                worst = std::max(worst, std::acos(Clamp(Dot(a, b), -1, 1)));
            }
        return worst;
    };
    Float coarse = maxAngle(LoopSubdivide(kOctahedron, kOctahedronP, 3)), fine = maxAngle(m);
    EXPECT_LT(fine, 0.8f * coarse);
    // Each vertex's limit normal is the normal of the surface the refined triangles around it
    // approximate: within 0.05 radians of the mean of their normals at level 4
    std::vector<Vector3f> faces(m.p.size());
    for (size_t f = 0; f < m.indices.size(); f += 3) {
        Point3f p0 = m.p[size_t(m.indices[f])], p1 = m.p[size_t(m.indices[f + 1])],
                p2 = m.p[size_t(m.indices[f + 2])];
        for (int k = 0; k < 3; ++k)
            faces[size_t(m.indices[f + k])] += Normalize(Cross(p0 - p2, p1 - p2));
    }
    for (size_t v = 0; v < m.p.size(); ++v)
        ASSERT_GT(Dot(Normalize(faces[v]), Vector3f(m.n[v])), std::cos(0.05f)) << v;
    // Triangles keep the control mesh's winding: their normals point outwards too
    for (size_t f = 0; f < m.indices.size(); f += 3) {
        Point3f p0 = m.p[size_t(m.indices[f])], p1 = m.p[size_t(m.indices[f + 1])],
                p2 = m.p[size_t(m.indices[f + 2])];
        Vector3f n = Cross(p0 - p2, p1 - p2);
        ASSERT_GT(Dot(n, Vector3f(p0) + Vector3f(p1) + Vector3f(p2)), 0);
    }
}

TEST(LoopSubdivision, FlatOpenMeshStaysFlatWithItsBoundary) {
    // A 3 x 3 grid of squares in z = 0, each split in two, wound counter-clockwise from +z
    std::vector<Point3f> p;
    std::vector<int> idx;
    for (int y = 0; y <= 3; ++y)
        for (int x = 0; x <= 3; ++x) p.push_back(Point3f(x, y, 0));
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) {
            int a = y * 4 + x, b = a + 1, c = a + 4, d = c + 1;
            for (int v : {a, b, d, a, d, c}) idx.push_back(v);
        }
    SubdividedMesh m = LoopSubdivide(idx, p, 3);
    EXPECT_EQ(m.indices.size(), idx.size() * 64);
    for (size_t v = 0; v < m.p.size(); ++v) {
        ASSERT_NEAR(m.p[v].z, 0, 1e-6f);
        ASSERT_GE(m.p[v].x, -1e-5f);
        ASSERT_LE(m.p[v].x, 3 + 1e-5f);
        ASSERT_NEAR(m.n[v].z, 1, 1e-5f) << v;
    }
    // The boundary curve follows the boundary line (y = 0) away from the corners, which the
    // rules round off (pbrt-v4 has no corner rule either): there are vertices every 1/8
    int onBottom = 0;
    for (const Point3f& q : m.p)
        if (q.x >= 1.25f - 1e-4f && q.x <= 1.75f + 1e-4f && q.y < 0.05f) {
            EXPECT_NEAR(q.y, 0, 1e-6f);
            ++onBottom;
        }
    EXPECT_EQ(onBottom, 5);
}

TEST(LoopSubdivision, LoopsubdivShapeFromSceneParameters) {
    using test::Dict;
    ParsedParameter P, indices, levels = test::Int1("levels", 2);
    P.type = "point3";
    P.name = "P";
    for (const Point3f& q : kOctahedronP) P.floats.insert(P.floats.end(), {q.x, q.y, q.z});
    indices.type = "integer";
    indices.name = "indices";
    indices.ints = kOctahedron;
    ObjectArena arena;
    Diagnostics diag(nullptr);
    Transform identity;
    auto create = [&](ParsedParameterVector params) {
        ParameterDictionary d(std::move(params), nullptr);
        return Shape::Create("loopsubdiv", &identity, &identity, false, d, test::TestLoc(), arena,
                             diag);
    };
    std::vector<Shape> shapes = create({P, indices, levels});
    EXPECT_EQ(shapes.size(), 8u * 16);
    EXPECT_EQ(diag.WarningCount(), 0);
    // Errors: negative or absurd levels, indices out of range, no indices
    EXPECT_THROW(create({P, indices, test::Int1("levels", -1)}), SceneError);
    EXPECT_THROW(create({P, indices, test::Int1("levels", 30)}), SceneError);
    ParsedParameter bad = indices;
    bad.ints[4] = 17;
    EXPECT_THROW(create({P, bad}), SceneError);
    EXPECT_THROW(create({P}), SceneError);
}

}  // namespace
}  // namespace kiln
