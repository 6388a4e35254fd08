// Quadric shapes (pbrt-v4): Sphere, Disk and Cylinder, defined in object space and placed by
// renderFromObject. Intersections are computed in object space, in double precision, and the
// hit point is reprojected onto the surface before it is transformed to render space, so hits
// stay accurate for objects far from the origin. Lengths are in scene units, angles in radians
// unless a parameter says degrees.
//
// Sampling and areas are in render space, whatever the transform: points are sampled by
// object-space area and their density per render-space area divides by AreaScale there; a
// sphere samples the cone it subtends only when it is whole and its transform a similarity
// (its image a sphere of radius s r), by area otherwise. pbrt-v4 divides by the object-space
// area and samples the cone of the object-space radius around the centre, so a light on a
// scaled quadric is sampled with the wrong density (a closed cavity of a sphere under
// Scale 2 2 2 rendered 0.966 of B(T) that way, one under Scale 1.5 1 0.8 0.974; Area(), and
// with it a "power" given to an area light on such a shape, was the object-space area).
#pragma once

#include <cmath>
#include <optional>

#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

// Parameters shared by the quadrics.
struct QuadricBase {
    const Transform* renderFromObject;
    const Transform* objectFromRender;
    // Whether the normals point inwards (ReverseOrientation). Normals are computed in object
    // space and transformed as normals, which keeps an outward normal outward under any
    // transform, mirrors included; pbrt-v4 also flips them where the transform swaps
    // handedness (a rule for normals computed from render-space tangents), which turns a
    // mirrored quadric inside out: a one-sided area light on it emits inwards, and a closed
    // cavity holding a mirrored rough glass sphere rendered 1.20 of B(T).
    bool reverseOrientation;

    // s of a similarity renderFromObject (Transform::SimilarityScale), else 0
    Float similarityScale;
    double absDeterminant;  // of renderFromObject's linear part

    QuadricBase(const Transform* renderFromObject, const Transform* objectFromRender,
                bool reverseOrientation)
        : renderFromObject(renderFromObject),
          objectFromRender(objectFromRender),
          reverseOrientation(reverseOrientation),
          similarityScale(renderFromObject->SimilarityScale()),
          absDeterminant(std::abs(renderFromObject->LinearDeterminant())) {}

    // Render-space area per object-space area at a point whose object-space surface normal
    // is the unit vector nObj (Nanson's formula: |det L| |L^-T nObj|, L the linear part of
    // renderFromObject): 1 for rigid motions, s^2 for similarities.
    Float AreaScale(Normal3f nObj) const {
        if (similarityScale > 0) return Sqr(similarityScale);
        return Float(absDeterminant) * Length(Vector3f((*renderFromObject)(nObj)));
    }
};

// Sphere: radius, the slab zmin <= z <= zmax and the sweep 0 <= phi <= phimax (phimax given
// in degrees, stored in radians).
class Sphere : public QuadricBase {
  public:
    Sphere(const Transform* renderFromObject, const Transform* objectFromRender,
           bool reverseOrientation, Float radius, Float zMin, Float zMax, Float phiMaxDegrees);

    Bounds3f Bounds() const;
    // Render-space area (for non-similarities by a 64 x 64 midpoint rule over the object-space
    // area, to about 1e-4)
    Float Area() const { return area; }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Uniform over the object-space surface (z uniform in [zmin, zmax], phi in [0, phimax]);
    // pdf per render-space area.
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction& intr) const;
    // Cone sampling of the subtended directions from outside a whole sphere under a
    // similarity, area sampling otherwise.
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
    Float ObjectArea() const { return phiMax * radius * (zMax - zMin); }
    // The radius of the sphere the cone is sampled around (0: sample by area)
    Float ConeRadius() const;

    Float area = 0;  // render space
};

// Disk at z = height, radius, innerradius (annulus) and sweep phimax (degrees).
class Disk : public QuadricBase {
  public:
    Disk(const Transform* renderFromObject, const Transform* objectFromRender,
         bool reverseOrientation, Float height, Float radius, Float innerRadius,
         Float phiMaxDegrees);

    Bounds3f Bounds() const;
    // Render-space area (exact: the disk's normal, and so AreaScale, is constant)
    Float Area() const { return phiMax * 0.5f * (Sqr(radius) - Sqr(innerRadius)) * areaScale; }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Uniform over the area; pdf per render-space area
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

    Float areaScale;  // AreaScale of the normal (0, 0, 1)
};

// Cylinder about the z axis: radius, zmin <= z <= zmax, sweep phimax (degrees).
class Cylinder : public QuadricBase {
  public:
    Cylinder(const Transform* renderFromObject, const Transform* objectFromRender,
             bool reverseOrientation, Float radius, Float zMin, Float zMax, Float phiMaxDegrees);

    Bounds3f Bounds() const;
    // Render-space area (for non-similarities by a 256-node midpoint rule over phi)
    Float Area() const { return area; }
    std::optional<ShapeIntersection> Intersect(const Ray& ray, Float tMax = Infinity) const;
    bool IntersectP(const Ray& ray, Float tMax = Infinity) const;
    // Uniform over the object-space surface; pdf per render-space area
    std::optional<ShapeSample> Sample(Point2f u) const;
    Float PDF(const Interaction& intr) const;
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
    Float ObjectArea() const { return (zMax - zMin) * radius * phiMax; }
    // Per render-space area at object-space point pObj
    Float AreaDensity(Point3f pObj) const {
        return 1 / (ObjectArea() * AreaScale(Normal3f(pObj.x / radius, pObj.y / radius, 0)));
    }

    Float area = 0;  // render space
};

}  // namespace kiln
