// Bilinear patch meshes and the BilinearPatch shape (pbrt-v4 semantics). Each patch has
// corners p00, p10, p01, p11 (indices in that order); p(u, v) interpolates them bilinearly.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

class BilinearPatchMesh {
  public:
    // indices: 4 per patch; n, uv: empty or one per vertex; faceIndices: empty or one per patch.
    // Positions and normals are transformed to render space (normals flipped when
    // reverseOrientation).
    BilinearPatchMesh(const Transform& renderFromObject, bool reverseOrientation,
                      std::vector<int> indices, std::vector<Point3f> p, std::vector<Normal3f> n,
                      std::vector<Point2f> uv, std::vector<int> faceIndices);

    int nPatches = 0, nVertices = 0;
    bool reverseOrientation = false, transformSwapsHandedness = false;
    std::vector<int> vertexIndices;
    std::vector<Point3f> p;
    std::vector<Normal3f> n;
    std::vector<Point2f> uv;
    std::vector<int> faceIndices;
};

class BilinearPatch {
  public:
    BilinearPatch() = default;
    BilinearPatch(const BilinearPatchMesh* mesh, int blpIndex);
    static std::vector<BilinearPatch> FromMesh(const BilinearPatchMesh* mesh);

    Bounds3f Bounds() const;
    Float Area() const { return area; }
    // Ray-patch intersection after Reshetov (2019), as in pbrt-v4.
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Area measure: (u, v) drawn with a bilinear density approximating |dp/du x dp/dv|; the
    // returned pdf is exact.
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction& intr) const;
    // Area sampling converted to solid angle.
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;

    // Shape::InteractionAt, SampleParametric, InvertParametric (shape.h); the parameterisation
    // is the patch's own (u, v), with area density 1 / |dp/du x dp/dv|.
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const { return Parameters(p); }
    // The patch parameters (u, v) of a point on (or near) the patch, by Newton iterations.
    Point2f Parameters(Point3f p) const;
    // Differential geometry at patch parameters (u, v).
    SurfaceInteraction InteractionFromParameters(Point2f uv, Float time, Vector3f wo) const;
    bool IsRectangle() const;
    const BilinearPatchMesh* GetMesh() const { return mesh; }
    int PatchIndex() const { return blpIndex; }

  private:
    std::array<Point3f, 4> Corners() const;
    std::array<Float, 4> SamplingWeights() const;
    const BilinearPatchMesh* mesh = nullptr;
    int blpIndex = 0;
    Float area = 0;
};

}  // namespace kiln
