// Shape: the closed set of geometric shapes (pbrt-v4's Shape interface), and their creation
// from scene-description parameters.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/bilinear_patch.h"
#include "core/geometry/quadrics.h"
#include "core/geometry/shape_sample.h"
#include "core/geometry/triangle.h"

namespace kiln {

class ParameterDictionary;
struct MeshDisplacement;
class Diagnostics;
struct FileLoc;

class Shape : public ClosedSet<const Sphere*, const Disk*, const Cylinder*, const Triangle*,
                               const BilinearPatch*> {
  public:
    using ClosedSet::ClosedSet;
    // Bounds in render space (scene units), surface area (scene units^2).
    Bounds3f Bounds() const;
    Float Area() const;
    // A point uniformly (or nearly so) distributed over the area; pdf per unit area.
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction& intr) const;
    // A point sampled from the viewpoint ctx; pdf per steradian.
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;
    // The full differential geometry at point p of the surface (render space), exactly as a ray
    // hit there computes it (shading frame, uv, triangle and barycentrics), for outgoing
    // direction wo at shutter time `time`.
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    // A bijective parameterisation of the surface by [0,1]^2 for sampling emitters in
    // proportion to power (lights/thermal_area_light.h): the point at u with the area density
    // (per unit area) that a uniform u gives it, and the parameter of a point on the surface.
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const;
    // The directions of the surface normals (w, cos of the spread; cos -1: all directions), for
    // light bounds (pbrt-v4's Shape::NormalBounds).
    std::pair<Vector3f, Float> NormalBounds() const;
    // tMax in the parametric units of ray (ray.d need not be unit).
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;

    // The shapes of a "Shape" directive (pbrt-v4 names and defaults). Unsupported shapes are
    // warned about and yield nothing; malformed parameters throw SceneError. displacement: a
    // plymesh's "displacement" texture and "edgelength" (mesh_displacement.h), read by the
    // caller, who has the named textures; without it a displacement is warned about.
    static std::vector<Shape> Create(const std::string& name, const Transform* renderFromObject,
                                     const Transform* objectFromRender, bool reverseOrientation,
                                     const ParameterDictionary& params, const FileLoc& loc,
                                     ObjectArena& arena, Diagnostics& diag,
                                     const MeshDisplacement* displacement = nullptr);
};

}  // namespace kiln
