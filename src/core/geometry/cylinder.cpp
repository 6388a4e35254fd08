#include "base/sampling.h"
#include "core/geometry/quadrics.h"
#include "core/geometry/shape_util.h"

namespace kiln {

Cylinder::Cylinder(const Transform* renderFromObject, const Transform* objectFromRender,
                   bool reverseOrientation, Float radius, Float zMin, Float zMax,
                   Float phiMaxDegrees)
    : QuadricBase(renderFromObject, objectFromRender, reverseOrientation),
      radius(radius),
      zMin(std::min(zMin, zMax)),
      zMax(std::max(zMin, zMax)),
      phiMax(Radians(Clamp(phiMaxDegrees, 0, 360))) {
    if (similarityScale > 0) {
        area = ObjectArea() * Sqr(similarityScale);
        return;
    }
    // The mean of AreaScale over phi (the normal does not depend on z)
    constexpr int n = 256;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        Float phi = (i + 0.5f) / n * phiMax;
        sum += AreaScale(Normal3f(std::cos(phi), std::sin(phi), 0));
    }
    area = Float(ObjectArea() * sum / n);
}

Float Cylinder::PDF(const Interaction& intr) const {
    return AreaDensity((*objectFromRender)(intr.p));
}

Bounds3f Cylinder::Bounds() const {
    return (*renderFromObject)(
        Bounds3f(Point3f(-radius, -radius, zMin), Point3f(radius, radius, zMax)));
}

// Cylinder intersection
std::optional<std::pair<Float, Point3f>> Cylinder::BasicIntersect(const Ray& r, Float tMax) const {
    Point3f of = (*objectFromRender)(r.o);
    Vector3f df = (*objectFromRender)(r.d);
    double ox = of.x, oy = of.y, oz = of.z, dx = df.x, dy = df.y, dz = df.z;
    double a = dx * dx + dy * dy;
    if (a == 0) return std::nullopt;
    double b = 2 * (dx * ox + dy * oy);
    double c = ox * ox + oy * oy - double(radius) * radius;
    // Discriminant in the cancellation-free form of pbrt-v4.
    double fx = ox - b / (2 * a) * dx, fy = oy - b / (2 * a) * dy;
    double flen = std::sqrt(fx * fx + fy * fy);
    double discrim = 4 * a * (double(radius) + flen) * (double(radius) - flen);
    if (discrim < 0) return std::nullopt;
    double root = std::sqrt(discrim);
    double q = (b < 0) ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = (q != 0) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= tMax || t1 <= 0) return std::nullopt;

    auto accept = [&](double t) -> std::optional<Point3f> {
        if (t <= 0 || t >= tMax) return std::nullopt;
        double px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
        double scale = radius / std::sqrt(px * px + py * py);
        px *= scale, py *= scale;
        double phi = std::atan2(py, px);
        if (phi < 0) phi += 2 * M_PI;
        if (pz < zMin || pz > zMax || phi > phiMax) return std::nullopt;
        return Point3f(Float(px), Float(py), Float(pz));
    };
    if (auto p = accept(t0)) return std::make_pair(Float(t0), *p);
    if (auto p = accept(t1)) return std::make_pair(Float(t1), *p);
    return std::nullopt;
}

SurfaceInteraction Cylinder::InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const {
    Float phi = std::atan2(pHit.y, pHit.x);
    if (phi < 0) phi += 2 * Pi;
    Float u = phi / phiMax, v = (pHit.z - zMin) / (zMax - zMin);
    Vector3f dpdu(-phiMax * pHit.y, phiMax * pHit.x, 0), dpdv(0, 0, zMax - zMin);
    Vector3f d2Pduu = -phiMax * phiMax * Vector3f(pHit.x, pHit.y, 0);
    Normal3f dndu, dndv;
    WeingartenNormalDerivatives(dpdu, dpdv, d2Pduu, Vector3f(0, 0, 0), Vector3f(0, 0, 0), &dndu,
                                &dndv);
    bool flip = reverseOrientation;  // not the handedness: see QuadricBase
    SurfaceInteraction si(pHit, Point2f(u, v), woObject, dpdu, dpdv, dndu, dndv, time, flip);
    return TransformInteraction(*renderFromObject, si);
}

std::optional<ShapeIntersection> Cylinder::Intersect(const Ray& ray, Float tMax) const {
    auto hit = BasicIntersect(ray, tMax);
    if (!hit) return std::nullopt;
    return ShapeIntersection{InteractionFromHit(hit->second, -(*objectFromRender)(ray.d), ray.time),
                             hit->first};
}

SurfaceInteraction Cylinder::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    Point3f pObj = (*objectFromRender)(p);
    Float r = std::sqrt(Sqr(pObj.x) + Sqr(pObj.y));
    if (r > 0) pObj.x *= radius / r, pObj.y *= radius / r;
    pObj.z = Clamp(pObj.z, zMin, zMax);
    return InteractionFromHit(pObj, (*objectFromRender)(wo), time);
}

// Sample(u) is itself a bijective area-uniform map: u = ((z - zmin) / (zmax - zmin), phi / phimax)
std::optional<ShapeSample> Cylinder::SampleParametric(Point2f u) const { return Sample(u); }

Point2f Cylinder::InvertParametric(Point3f p) const {
    Point3f pObj = (*objectFromRender)(p);
    Float phi = std::atan2(pObj.y, pObj.x);
    if (phi < 0) phi += 2 * Pi;
    Float u0 = zMax > zMin ? (pObj.z - zMin) / (zMax - zMin) : 0;
    return Point2f(Clamp(u0, 0, 1), Clamp(phiMax > 0 ? phi / phiMax : 0, 0, 1));
}

bool Cylinder::IntersectP(const Ray& ray, Float tMax) const {
    return BasicIntersect(ray, tMax).has_value();
}

// Cylinder sampling
std::optional<ShapeSample> Cylinder::Sample(Point2f u) const {
    Float z = Lerp(u[0], zMin, zMax), phi = u[1] * phiMax;
    Point3f pObj(radius * std::cos(phi), radius * std::sin(phi), z);
    Normal3f n = SafeNormalize((*renderFromObject)(Normal3f(pObj.x, pObj.y, 0)));
    if (reverseOrientation) n = -n;
    Point2f uv(phi / phiMax, (z - zMin) / (zMax - zMin));
    return ShapeSample{Interaction((*renderFromObject)(pObj), n, uv), AreaDensity(pObj)};
}

std::optional<ShapeSample> Cylinder::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    auto ss = Sample(u);
    if (!ss) return std::nullopt;
    ss->intr.time = ctx.time;
    return AreaSampleToSolidAngle(ctx, *ss);
}

Float Cylinder::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    auto isect = Intersect(ctx.SpawnRay(wi));
    if (!isect) return 0;
    Float pdf =
        PDF(isect->intr) / (AbsDot(isect->intr.n, -wi) / DistanceSquared(ctx.p, isect->intr.p));
    return std::isinf(pdf) ? 0 : pdf;
}

}  // namespace kiln
