// Quadric shapes (pbrt-v4): Sphere, Disk and Cylinder, defined in object space and placed by
// renderFromObject. Intersections are computed in object space, in double precision, and the
// hit point is reprojected onto the surface before it is transformed to render space, so hits
// stay accurate for objects far from the origin. Lengths are in scene units, angles in radians
// unless a parameter says degrees.
#pragma once

#include <optional>

#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

// Parameters shared by the quadrics.
struct QuadricBase {
    const Transform* renderFromObject;
    const Transform* objectFromRender;
    bool reverseOrientation, transformSwapsHandedness;

    QuadricBase(const Transform* renderFromObject, const Transform* objectFromRender,
                bool reverseOrientation)
        : renderFromObject(renderFromObject),
          objectFromRender(objectFromRender),
          reverseOrientation(reverseOrientation),
          transformSwapsHandedness(renderFromObject->SwapsHandedness()) {}
};

// Sphere: radius, the slab zmin <= z <= zmax and the sweep 0 <= phi <= phimax (phimax given
// in degrees, stored in radians).
class Sphere : public QuadricBase {
  public:
    Sphere(const Transform* renderFromObject, const Transform* objectFromRender,
           bool reverseOrientation, Float radius, Float zMin, Float zMax, Float phiMaxDegrees);

    Bounds3f Bounds() const;
    Float Area() const { return phiMax * radius * (zMax - zMin); }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Uniform over the surface (z uniform in [zmin, zmax], phi in [0, phimax]); pdf 1/Area.
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction&) const { return 1 / Area(); }
    // Cone sampling of the subtended directions from outside, area sampling from inside.
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;
    // Shape::InteractionAt, SampleParametric, InvertParametric (shape.h)
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const;

    Float radius, zMin, zMax, thetaZMin, thetaZMax, phiMax;

  private:
    // Object-space hit: t and the reprojected point; nullopt on a miss.
    std::optional<std::pair<Float, Point3f>> BasicIntersect(const Ray& r, Float tMax) const;
    SurfaceInteraction InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const;
};

// Disk at z = height, radius, innerradius (annulus) and sweep phimax (degrees).
class Disk : public QuadricBase {
  public:
    Disk(const Transform* renderFromObject, const Transform* objectFromRender,
         bool reverseOrientation, Float height, Float radius, Float innerRadius,
         Float phiMaxDegrees);

    Bounds3f Bounds() const;
    Float Area() const { return phiMax * 0.5f * (Sqr(radius) - Sqr(innerRadius)); }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction&) const { return 1 / Area(); }
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;
    // Shape::InteractionAt, SampleParametric, InvertParametric (shape.h)
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const;

    Float height, radius, innerRadius, phiMax;

  private:
    std::optional<std::pair<Float, Point3f>> BasicIntersect(const Ray& r, Float tMax) const;
    SurfaceInteraction InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const;
};

// Cylinder about the z axis: radius, zmin <= z <= zmax, sweep phimax (degrees).
class Cylinder : public QuadricBase {
  public:
    Cylinder(const Transform* renderFromObject, const Transform* objectFromRender,
             bool reverseOrientation, Float radius, Float zMin, Float zMax, Float phiMaxDegrees);

    Bounds3f Bounds() const;
    Float Area() const { return (zMax - zMin) * radius * phiMax; }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction&) const { return 1 / Area(); }
    std::optional<ShapeSample> Sample(const ShapeSampleContext& ctx, Point2f u) const;
    Float PDF(const ShapeSampleContext& ctx, Vector3f wi) const;
    // Shape::InteractionAt, SampleParametric, InvertParametric (shape.h)
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<ShapeSample> SampleParametric(Point2f u) const;
    Point2f InvertParametric(Point3f p) const;

    Float radius, zMin, zMax, phiMax;

  private:
    std::optional<std::pair<Float, Point3f>> BasicIntersect(const Ray& r, Float tMax) const;
    SurfaceInteraction InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const;
};

}  // namespace kiln
