// Accelerator: Embree 3 BVH over every primitive of the scene. Triangle meshes are native
// Embree triangle geometries sharing the meshes' buffers, curves native curve geometries; quadrics
// and bilinear patches are user geometries whose callbacks call Shape::Intersect. Object instances
// are Embree instance geometries over one scene per definition; moving shapes and instances are
// user geometries that trace the definition's scene at each ray's time.
#pragma once

#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <span>

#include "base/animated_transform.h"
#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/alpha_mask.h"
#include "core/geometry/curve.h"
#include "core/geometry/shape.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

class Material;
class ThermalEmission;

// The context of a closest-hit query on Accelerator::EmbreeScene(): kiln's user-geometry
// callbacks (quadrics, bilinear patches) store their full hit after the Embree context, so raw
// Embree queries on that scene (e.g. throughput benchmarks) must pass one of these.
struct EmbreeQueryContext {
    RTCIntersectContext context;
    std::optional<ShapeIntersection> userHit;
    EmbreeQueryContext() { rtcInitIntersectContext(&context); }
};

// An Embree ray-hit record for ray over [0, tMax], with no hit yet.
RTCRayHit MakeEmbreeRayHit(const Ray& ray, Float tMax);

class Accelerator {
  public:
    Accelerator();
    ~Accelerator();
    Accelerator(const Accelerator&) = delete;
    Accelerator& operator=(const Accelerator&) = delete;

    // The shapes of one Shape directive with their material (nullptr = interface), the indices
    // of their lights in the scene's light list (empty, or one per shape in the same order),
    // their thermal emission (nullptr when cold) and the media they separate. Shapes,
    // materials and emission must outlive the accelerator; hits report them in
    // SurfaceInteraction. alpha (nullptr: opaque) cuts the shapes out where it is below 1, for
    // closest hits and shadow rays alike (alpha_mask.h); it must outlive the accelerator.
    // windowIndices: empty, or one per shape, reported as SurfaceInteraction::windowIndex.
    // boundaryOnly: the shapes only separate media (an interface material, no light, not
    // hot); their triangles' hits then report what crossing needs and no more
    // (Triangle::BoundaryInteraction).
    void Add(std::span<const Shape> shapes, const Material* material,
             std::span<const int> lightIndices, const ThermalEmission* thermal,
             MediumInterface media = {}, const AlphaMask* alpha = nullptr,
             std::span<const int> windowIndices = {}, bool boundaryOnly = false);
    // Object instancing: a definition's shapes are given in the definition's own space (they
    // can glow, but are no lights).
    int NewInstanceDefinition();
    void AddToInstanceDefinition(int definition, std::span<const Shape> shapes,
                                 const Material* material, const ThermalEmission* thermal,
                                 MediumInterface media = {}, const AlphaMask* alpha = nullptr,
                                 bool boundaryOnly = false);
    // Places a definition.
    void AddInstance(int definition, const Transform& renderFromInstance);
    // Places a definition that moves over the shutter (pbrt-v4's AnimatedPrimitive): each ray
    // is traced in the definition's space through renderFromInstance at the ray's time, and
    // hits are mapped back with the same transform. parent -1 places it at the top level;
    // a definition's index places it inside that definition (a moving shape in an object).
    // Empty definitions are left out.
    void AddAnimatedInstance(int definition, const AnimatedTransform& renderFromInstance,
                             int parent = -1);
    // A curve (curve.h) as Embree curve primitives, at the top level (definition -1) or in an
    // instance definition; it must outlive the accelerator. Curves are not lights.
    void AddCurves(const CurveSet& curves, const Material* material, const ThermalEmission* thermal,
                   MediumInterface media = {}, const AlphaMask* alpha = nullptr,
                   int definition = -1);
    // Builds the BVHs; call once after everything has been added. Returns the instances (by
    // the order of their AddInstance calls) left out because rays cannot be traced in their
    // space: a singular transform, or one that takes them, or the scene's rays in their own
    // space, beyond the range Embree accepts.
    std::vector<int> Commit();

    // Closest hit with t in (0, tMax), t in the parametric units of ray.
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    // Any hit in (0, tMax), for shadow rays.
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    Bounds3f Bounds() const;
    RTCScene EmbreeScene() const;
    // The most memory Embree has held (its own allocations: BVHs, copied buffers), bytes.
    int64_t EmbreePeakBytes() const;
    // Scenes of more than kCompactPrimitives primitives (instances counted once) are built
    // with Embree's compact BVH: about half the BVH memory (583 -> 273 MB for 5 million
    // triangles) for 1-4 % slower rendering (bench/README.md).
    static constexpr size_t kCompactPrimitives = size_t(1) << 21;
    bool Compact() const;

    struct Impl;

  private:
    std::unique_ptr<Impl> impl;
};

}  // namespace kiln
