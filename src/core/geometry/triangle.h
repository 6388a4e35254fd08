// Triangle meshes and the Triangle shape (pbrt-v4 semantics).
//
// A TriangleMesh stores render-space positions and normals (transformed once at creation;
// normals flipped when ReverseOrientation is set), optional tangents, uv and per-face indices,
// plus named per-vertex float attributes (kiln extension, e.g. "temperature" in K) that are
// interpolated with the barycentrics of a hit. Triangles with zero area are removed when the
// mesh is built.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

class TriangleMesh {
  public:
    // indices: 3 per triangle. n, s, uv: empty or one per vertex; faceIndices: empty or one
    // per triangle; attributes: each vector one value per vertex. Degenerate (zero-area)
    // triangles are dropped and counted in nDegenerate.
    TriangleMesh(const Transform& renderFromObject, bool reverseOrientation,
                 std::vector<int> indices, std::vector<Point3f> p, std::vector<Normal3f> n,
                 std::vector<Vector3f> s, std::vector<Point2f> uv, std::vector<int> faceIndices,
                 std::map<std::string, std::vector<Float>> attributes = {});

    int NumTriangles() const { return nTriangles; }
    int NumVertices() const { return nVertices; }
    std::array<int, 3> VertexIndices(int triIndex) const {
        const int* v = &vertexIndices[3 * triIndex];
        return {v[0], v[1], v[2]};
    }
    // Interpolates the named per-vertex attribute with barycentrics b (b0 + b1 + b2 = 1);
    // nullopt when the mesh has no such attribute.
    std::optional<Float> InterpolateAttribute(const std::string& name, int triIndex,
                                              const std::array<Float, 3>& b) const;
    bool HasAttribute(const std::string& name) const { return attributes.count(name) > 0; }

    int nTriangles = 0, nVertices = 0, nDegenerate = 0;
    bool reverseOrientation = false, transformSwapsHandedness = false;
    std::vector<int> vertexIndices;
    // Render space. p has capacity for one more element so Embree's 16-byte loads stay in
    // the allocation.
    std::vector<Point3f> p;
    std::vector<Normal3f> n;
    std::vector<Vector3f> s;
    std::vector<Point2f> uv;
    std::vector<int> faceIndices;
    std::map<std::string, std::vector<Float>> attributes;
};

// One triangle of a mesh.
class Triangle {
  public:
    Triangle() = default;
    Triangle(const TriangleMesh* mesh, int triIndex) : mesh(mesh), triIndex(triIndex) {}

    // The Triangle shapes of a mesh, in an array owned by the caller (e.g. an ObjectArena).
    static std::vector<Triangle> FromMesh(const TriangleMesh* mesh);

    Bounds3f Bounds() const;
    Float Area() const;
    // Watertight ray-triangle test (Woop et al. 2013, as in pbrt-v4).
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Uniform over the area (pdf 1/Area).
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction&) const { return 1 / Area(); }
    // Spherical triangle sampling, warped by the cosine at ctx when ctx has a normal, when
    // the subtended solid angle lies in [MinSphericalSampleArea, MaxSphericalSampleArea];
    // area sampling converted to solid angle otherwise.
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;
    // Shape::InteractionAt, SampleParametric, InvertParametric (shape.h); the parameterisation
    // is b0 = 1 - sqrt(u0), b1 = u1 sqrt(u0).
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const;
    // Solid angle (sr) subtended at p.
    Float SolidAngle(Point3f p) const;

    // The point at barycentrics b (position, oriented geometric normal, uv) as a sample is.
    Interaction PointAt(const std::array<Float, 3>& b, Float time) const;
    // Barycentrics (b0, b1, b2) of a point on (or near) the triangle's plane.
    std::array<Float, 3> Barycentrics(Point3f p) const;
    // Full differential geometry at barycentrics b (pbrt-v4 InteractionFromIntersection).
    SurfaceInteraction InteractionFromBarycentrics(const std::array<Float, 3>& b, Float time,
                                                   Vector3f wo) const;
    // What a ray crossing a medium boundary (an interface surface) needs at barycentrics b:
    // the point, the geometric normal oriented as InteractionFromBarycentrics orients it (so
    // SurfaceInteraction::MediumAfter picks the same side), wo, time and the triangle; no
    // parameterisation, derivatives or shading frame (shading.n = n).
    SurfaceInteraction BoundaryInteraction(const std::array<Float, 3>& b, Float time,
                                           Vector3f wo) const;

    const TriangleMesh* GetMesh() const { return mesh; }
    int TriangleIndex() const { return triIndex; }

    static constexpr Float MinSphericalSampleArea = 3e-4f;
    static constexpr Float MaxSphericalSampleArea = 6.22f;

  private:
    std::array<Point3f, 3> Vertices() const {
        auto v = mesh->VertexIndices(triIndex);
        return {mesh->p[v[0]], mesh->p[v[1]], mesh->p[v[2]]};
    }
    const TriangleMesh* mesh = nullptr;
    int triIndex = 0;
};

}  // namespace kiln
