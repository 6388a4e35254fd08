#include "base/sampling.h"
#include "core/geometry/quadrics.h"
#include "core/geometry/shape_util.h"

namespace kiln {

// Sphere construction
Sphere::Sphere(const Transform* renderFromObject, const Transform* objectFromRender,
               bool reverseOrientation, Float radius, Float zMin, Float zMax, Float phiMaxDegrees)
    : QuadricBase(renderFromObject, objectFromRender, reverseOrientation),
      radius(radius),
      zMin(Clamp(std::min(zMin, zMax), -radius, radius)),
      zMax(Clamp(std::max(zMin, zMax), -radius, radius)),
      thetaZMin(std::acos(Clamp(std::min(zMin, zMax) / radius, -1, 1))),
      thetaZMax(std::acos(Clamp(std::max(zMin, zMax) / radius, -1, 1))),
      phiMax(Radians(Clamp(phiMaxDegrees, 0, 360))) {
    if (similarityScale > 0) {
        area = ObjectArea() * Sqr(similarityScale);
        return;
    }
    // The mean of AreaScale over the object-space area (Sample(u) is area-uniform there)
    constexpr int n = 64;
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Float z = Lerp((i + 0.5f) / n, this->zMin, this->zMax), phi = (j + 0.5f) / n * phiMax;
            Float rz = SafeSqrt(Sqr(radius) - Sqr(z));
            sum += AreaScale(
                Normal3f(rz * std::cos(phi) / radius, rz * std::sin(phi) / radius, z / radius));
        }
    area = Float(ObjectArea() * sum / (n * n));
}

Float Sphere::ConeRadius() const {
    bool whole = zMin <= -radius && zMax >= radius && phiMax >= 2 * Pi;
    return whole ? similarityScale * radius : 0;
}

Bounds3f Sphere::Bounds() const {
    return (*renderFromObject)(
        Bounds3f(Point3f(-radius, -radius, zMin), Point3f(radius, radius, zMax)));
}

// Sphere intersection
std::optional<std::pair<Float, Point3f>> Sphere::BasicIntersect(const Ray& r, Float tMax) const {
    Point3f of = (*objectFromRender)(r.o);
    Vector3f df = (*objectFromRender)(r.d);
    double ox = of.x, oy = of.y, oz = of.z, dx = df.x, dy = df.y, dz = df.z;
    // Quadratic a t^2 + b t + c = 0, with the discriminant computed as in pbrt-v4 (Hearn-Baker
    // form) to avoid cancellation.
    double a = dx * dx + dy * dy + dz * dz;
    if (a == 0) return std::nullopt;
    double b = 2 * (dx * ox + dy * oy + dz * oz);
    double c = ox * ox + oy * oy + oz * oz - double(radius) * radius;
    double vx = ox - b / (2 * a) * dx, vy = oy - b / (2 * a) * dy, vz = oz - b / (2 * a) * dz;
    double vlen = std::sqrt(vx * vx + vy * vy + vz * vz);
    double discrim = 4 * a * (double(radius) + vlen) * (double(radius) - vlen);
    if (discrim < 0) return std::nullopt;
    double root = std::sqrt(discrim);
    double q = (b < 0) ? -0.5 * (b - root) : -0.5 * (b + root);
    double t0 = q / a, t1 = (q != 0) ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 >= tMax || t1 <= 0) return std::nullopt;

    auto accept = [&](double t) -> std::optional<Point3f> {
        if (t <= 0 || t >= tMax) return std::nullopt;
        double px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
        double scale = radius / std::sqrt(px * px + py * py + pz * pz);
        px *= scale, py *= scale, pz *= scale;
        if (px == 0 && py == 0) px = 1e-5 * radius;
        double phi = std::atan2(py, px);
        if (phi < 0) phi += 2 * M_PI;
        if ((zMin > -radius && pz < zMin) || (zMax < radius && pz > zMax) || phi > phiMax)
            return std::nullopt;
        return Point3f(Float(px), Float(py), Float(pz));
    };
    if (auto p = accept(t0)) return std::make_pair(Float(t0), *p);
    if (auto p = accept(t1)) return std::make_pair(Float(t1), *p);
    return std::nullopt;
}

SurfaceInteraction Sphere::InteractionFromHit(Point3f pHit, Vector3f woObject, Float time) const {
    Float phi = std::atan2(pHit.y, pHit.x);
    if (phi < 0) phi += 2 * Pi;
    Float u = phi / phiMax;
    Float cosTheta = pHit.z / radius, theta = SafeACos(cosTheta);
    Float v = (theta - thetaZMin) / (thetaZMax - thetaZMin);
    // hypot: the sum of squares underflows within ~1e-19 of the poles (fov 1e-20 hits them)
    Float zRadius = std::hypot(pHit.x, pHit.y);
    Float cosPhi = pHit.x / zRadius, sinPhi = pHit.y / zRadius;
    Vector3f dpdu(-phiMax * pHit.y, phiMax * pHit.x, 0);
    Float sinTheta = SafeSqrt(1 - Sqr(cosTheta));
    Vector3f dpdv =
        (thetaZMax - thetaZMin) * Vector3f(pHit.z * cosPhi, pHit.z * sinPhi, -radius * sinTheta);
    Vector3f d2Pduu = -phiMax * phiMax * Vector3f(pHit.x, pHit.y, 0);
    Vector3f d2Pduv = (thetaZMax - thetaZMin) * pHit.z * phiMax * Vector3f(-sinPhi, cosPhi, 0);
    Vector3f d2Pdvv = -Sqr(thetaZMax - thetaZMin) * Vector3f(pHit);
    Normal3f dndu, dndv;
    WeingartenNormalDerivatives(dpdu, dpdv, d2Pduu, d2Pduv, d2Pdvv, &dndu, &dndv);
    bool flip = reverseOrientation;  // not the handedness: see QuadricBase
    SurfaceInteraction si(pHit, Point2f(u, v), woObject, dpdu, dpdv, dndu, dndv, time, flip);
    return TransformInteraction(*renderFromObject, si);
}

std::optional<ShapeIntersection> Sphere::Intersect(const Ray& ray, Float tMax) const {
    auto hit = BasicIntersect(ray, tMax);
    if (!hit) return std::nullopt;
    Vector3f wo = -(*objectFromRender)(ray.d);
    return ShapeIntersection{InteractionFromHit(hit->second, wo, ray.time), hit->first};
}

bool Sphere::IntersectP(const Ray& ray, Float tMax) const {
    return BasicIntersect(ray, tMax).has_value();
}

SurfaceInteraction Sphere::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    Point3f pObj = (*objectFromRender)(p);
    Float len = Length(Vector3f(pObj));
    if (len > 0) pObj = Point3f(Vector3f(pObj) * (radius / len));
    if (pObj.x == 0 && pObj.y == 0) pObj.x = 1e-5f * radius;
    return InteractionFromHit(pObj, (*objectFromRender)(wo), time);
}

// Sphere sampling
std::optional<ShapeSample> Sphere::Sample(Point2f u) const {
    // Archimedes: z is uniform over the slab for uniform area density.
    Float z = Lerp(u[0], zMin, zMax), phi = u[1] * phiMax;
    Float rz = SafeSqrt(Sqr(radius) - Sqr(z));
    Point3f pObj(rz * std::cos(phi), rz * std::sin(phi), z);
    Normal3f n = SafeNormalize((*renderFromObject)(Normal3f(pObj.x, pObj.y, pObj.z)));
    if (reverseOrientation) n = -n;
    Float theta = SafeACos(pObj.z / radius);
    Point2f uv(phi / phiMax, (theta - thetaZMin) / (thetaZMax - thetaZMin));
    Float pdf =
        1 / (ObjectArea() * AreaScale(Normal3f(pObj.x / radius, pObj.y / radius, pObj.z / radius)));
    return ShapeSample{Interaction((*renderFromObject)(pObj), n, uv), pdf};
}

Float Sphere::PDF(const Interaction& intr) const {
    Vector3f nObj = SafeNormalize(Vector3f((*objectFromRender)(intr.p)));
    return 1 / (ObjectArea() * AreaScale(Normal3f(nObj)));
}

// Sample(u) is itself a bijective area-uniform map: u = ((z - zmin) / (zmax - zmin), phi / phimax)
std::optional<ShapeSample> Sphere::SampleParametric(Point2f u) const { return Sample(u); }

Point2f Sphere::InvertParametric(Point3f p) const {
    Point3f pObj = (*objectFromRender)(p);
    Float len = Length(Vector3f(pObj));
    Float z = len > 0 ? pObj.z * radius / len : 0;
    Float phi = std::atan2(pObj.y, pObj.x);
    if (phi < 0) phi += 2 * Pi;
    Float u0 = zMax > zMin ? (z - zMin) / (zMax - zMin) : 0;
    return Point2f(Clamp(u0, 0, 1), Clamp(phiMax > 0 ? phi / phiMax : 0, 0, 1));
}

std::optional<ShapeSample> Sphere::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    Point3f pCenter = (*renderFromObject)(Point3f(0, 0, 0));
    Point3f pOrigin = ctx.OffsetRayOrigin(pCenter - ctx.p);
    const Float R = ConeRadius();
    if (R == 0 || DistanceSquared(pOrigin, pCenter) <= Sqr(R)) {
        auto ss = Sample(u);
        if (!ss) return std::nullopt;
        ss->intr.time = ctx.time;
        return AreaSampleToSolidAngle(ctx, *ss);
    }
    // Sample a direction uniformly in the cone subtended by the sphere.
    Float sinThetaMax = R / Distance(ctx.p, pCenter);
    Float sin2ThetaMax = Sqr(sinThetaMax);
    Float cosThetaMax = SafeSqrt(1 - sin2ThetaMax), oneMinusCosThetaMax = 1 - cosThetaMax;
    Float cosTheta = (cosThetaMax - 1) * u[0] + 1;
    Float sin2Theta = 1 - Sqr(cosTheta);
    if (sin2ThetaMax < 0.00068523f) {
        // Taylor expansion for small cones (sin^2(1.5 deg)).
        sin2Theta = sin2ThetaMax * u[0];
        cosTheta = std::sqrt(1 - sin2Theta);
        oneMinusCosThetaMax = sin2ThetaMax / 2;
    }
    // The point on the sphere seen in that direction, by its angle alpha from the centre.
    Float cosAlpha =
        sin2Theta / sinThetaMax + cosTheta * SafeSqrt(1 - sin2Theta / Sqr(sinThetaMax));
    Float sinAlpha = SafeSqrt(1 - Sqr(cosAlpha));
    Float phi = u[1] * 2 * Pi;
    Vector3f w = SphericalDirection(sinAlpha, cosAlpha, phi);
    Frame frame = Frame::FromZ(Normalize(pCenter - ctx.p));
    Normal3f n(frame.FromLocal(-w));
    Point3f p = pCenter + R * Vector3f(n);
    if (reverseOrientation) n = -n;
    Point3f pObj = (*objectFromRender)(p);
    Float theta = SafeACos(pObj.z / radius);
    Float sphPhi = std::atan2(pObj.y, pObj.x);
    if (sphPhi < 0) sphPhi += 2 * Pi;
    Point2f uv(sphPhi / phiMax, (theta - thetaZMin) / (thetaZMax - thetaZMin));
    return ShapeSample{Interaction(p, n, uv, {}, ctx.time), 1 / (2 * Pi * oneMinusCosThetaMax)};
}

Float Sphere::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    Point3f pCenter = (*renderFromObject)(Point3f(0, 0, 0));
    Point3f pOrigin = ctx.OffsetRayOrigin(pCenter - ctx.p);
    const Float R = ConeRadius();
    if (R == 0 || DistanceSquared(pOrigin, pCenter) <= Sqr(R)) {
        auto isect = Intersect(ctx.SpawnRay(wi));
        if (!isect) return 0;
        Float pdf =
            PDF(isect->intr) / (AbsDot(isect->intr.n, -wi) / DistanceSquared(ctx.p, isect->intr.p));
        return std::isinf(pdf) ? 0 : pdf;
    }
    Float sin2ThetaMax = Sqr(R) / DistanceSquared(ctx.p, pCenter);
    Float cosThetaMax = SafeSqrt(1 - sin2ThetaMax), oneMinusCosThetaMax = 1 - cosThetaMax;
    if (sin2ThetaMax < 0.00068523f) oneMinusCosThetaMax = sin2ThetaMax / 2;
    // Zero outside the cone (pbrt-v4 leaves this to the caller).
    if (Dot(Normalize(wi), Normalize(pCenter - ctx.p)) < cosThetaMax - 1e-4f) return 0;
    return 1 / (2 * Pi * oneMinusCosThetaMax);
}

}  // namespace kiln
