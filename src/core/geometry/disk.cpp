#include "base/sampling.h"
#include "core/geometry/quadrics.h"
#include "core/geometry/shape_util.h"

namespace kiln {

Disk::Disk(const Transform* renderFromObject, const Transform* objectFromRender,
           bool reverseOrientation, Float height, Float radius, Float innerRadius,
           Float phiMaxDegrees)
    : QuadricBase(renderFromObject, objectFromRender, reverseOrientation),
      height(height),
      radius(radius),
      innerRadius(innerRadius),
      phiMax(Radians(Clamp(phiMaxDegrees, 0, 360))),
      areaScale(AreaScale(Normal3f(0, 0, 1))) {}

Bounds3f Disk::Bounds() const {
    return (*renderFromObject)(
        Bounds3f(Point3f(-radius, -radius, height), Point3f(radius, radius, height)));
}

// Disk intersection
std::optional<std::pair<Float, Point3f>> Disk::BasicIntersect(const Ray& r, Float tMax) const {
    Point3f o = (*objectFromRender)(r.o);
    Vector3f d = (*objectFromRender)(r.d);
    if (d.z == 0) return std::nullopt;
    double tShapeHit = (double(height) - o.z) / d.z;
    if (tShapeHit <= 0 || tShapeHit >= tMax) return std::nullopt;
    double px = o.x + tShapeHit * d.x, py = o.y + tShapeHit * d.y;
    double dist2 = px * px + py * py;
    if (dist2 > Sqr(double(radius)) || dist2 < Sqr(double(innerRadius))) return std::nullopt;
    double phi = std::atan2(py, px);
    if (phi < 0) phi += 2 * M_PI;
    if (phi > phiMax) return std::nullopt;
    return std::make_pair(Float(tShapeHit), Point3f(Float(px), Float(py), height));
}

SurfaceInteraction Disk::InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const {
    Float phi = std::atan2(pHit.y, pHit.x);
    if (phi < 0) phi += 2 * Pi;
    Float rHit = std::hypot(pHit.x, pHit.y);  // no underflow next to the centre
    Float u = phi / phiMax, v = (radius - rHit) / (radius - innerRadius);
    Vector3f dpdu(-phiMax * pHit.y, phiMax * pHit.x, 0);
    Vector3f dpdv = rHit > 0 ? Vector3f(pHit.x, pHit.y, 0) * (innerRadius - radius) / rHit
                             : Vector3f(innerRadius - radius, 0, 0);
    if (rHit == 0) dpdu = Vector3f(0, phiMax * 1e-6f * radius, 0);
    bool flip = reverseOrientation;  // not the handedness: see QuadricBase
    SurfaceInteraction si(pHit, Point2f(u, v), woObject, dpdu, dpdv, Normal3f(0, 0, 0),
                          Normal3f(0, 0, 0), time, flip);
    return TransformInteraction(*renderFromObject, si);
}

std::optional<ShapeIntersection> Disk::Intersect(const Ray& ray, Float tMax) const {
    auto hit = BasicIntersect(ray, tMax);
    if (!hit) return std::nullopt;
    return ShapeIntersection{InteractionFromHit(hit->second, -(*objectFromRender)(ray.d), ray.time),
                             hit->first};
}

SurfaceInteraction Disk::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    Point3f pObj = (*objectFromRender)(p);
    pObj.z = height;
    return InteractionFromHit(pObj, (*objectFromRender)(wo), time);
}

// Polar parameterisation: r^2 uniform between the radii, phi uniform
std::optional<ShapeSample> Disk::SampleParametric(Point2f u) const {
    Float r = std::sqrt(Lerp(u[0], Sqr(innerRadius), Sqr(radius))), phi = u[1] * phiMax;
    Point3f pObj(r * std::cos(phi), r * std::sin(phi), height);
    Normal3f n = SafeNormalize((*renderFromObject)(Normal3f(0, 0, 1)));
    if (reverseOrientation) n = -n;
    Point2f uv(phi / phiMax, (radius - r) / (radius - innerRadius));
    return ShapeSample{Interaction((*renderFromObject)(pObj), n, uv), 1 / Area()};
}

Point2f Disk::InvertParametric(Point3f p) const {
    Point3f pObj = (*objectFromRender)(p);
    Float r2 = Sqr(pObj.x) + Sqr(pObj.y);
    Float phi = std::atan2(pObj.y, pObj.x);
    if (phi < 0) phi += 2 * Pi;
    Float d = Sqr(radius) - Sqr(innerRadius);
    return Point2f(Clamp(d > 0 ? (r2 - Sqr(innerRadius)) / d : 0, 0, 1),
                   Clamp(phiMax > 0 ? phi / phiMax : 0, 0, 1));
}

bool Disk::IntersectP(const Ray& ray, Float tMax) const {
    return BasicIntersect(ray, tMax).has_value();
}

// Disk sampling
std::optional<ShapeSample> Disk::Sample(Point2f u) const {
    Float r, phi;
    if (innerRadius == 0 && phiMax >= 2 * Pi) {
        // Full disk: the concentric map keeps stratification (pbrt-v4).
        Point2f pd = SampleUniformDiskConcentric(u);
        r = radius * std::sqrt(Sqr(pd.x) + Sqr(pd.y));
        phi = std::atan2(pd.y, pd.x);
        if (phi < 0) phi += 2 * Pi;
    } else {
        r = std::sqrt(Lerp(u[0], Sqr(innerRadius), Sqr(radius)));
        phi = u[1] * phiMax;
    }
    Point3f pObj(r * std::cos(phi), r * std::sin(phi), height);
    Normal3f n = SafeNormalize((*renderFromObject)(Normal3f(0, 0, 1)));
    if (reverseOrientation) n = -n;
    Point2f uv(phi / phiMax, (radius - r) / (radius - innerRadius));
    return ShapeSample{Interaction((*renderFromObject)(pObj), n, uv), 1 / Area()};
}

std::optional<ShapeSample> Disk::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    auto ss = Sample(u);
    if (!ss) return std::nullopt;
    ss->intr.time = ctx.time;
    return AreaSampleToSolidAngle(ctx, *ss);
}

Float Disk::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    auto isect = Intersect(ctx.SpawnRay(wi));
    if (!isect) return 0;
    Float pdf = (1 / Area()) / (AbsDot(isect->intr.n, -wi) / DistanceSquared(ctx.p, isect->intr.p));
    return std::isinf(pdf) ? 0 : pdf;
}

}  // namespace kiln
