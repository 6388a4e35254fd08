#include "lights/light_bounds.h"

#include <algorithm>
#include <cmath>

#include "base/transform.h"

namespace kiln {

namespace {

// cos(max(0, theta_a - theta_b)) and sin(max(0, theta_a - theta_b)) from sines and cosines
Float CosSubClamped(Float sinA, Float cosA, Float sinB, Float cosB) {
    if (cosA > cosB) return 1;
    return cosA * cosB + sinA * sinB;
}
Float SinSubClamped(Float sinA, Float cosA, Float sinB, Float cosB) {
    if (cosA > cosB) return 0;
    return sinA * cosB - cosA * sinB;
}

}  // namespace

DirectionCone Union(const DirectionCone& a, const DirectionCone& b) {
    if (a.IsEmpty()) return b;
    if (b.IsEmpty()) return a;
    // One cone inside the other
    Float thetaA = SafeACos(a.cosTheta), thetaB = SafeACos(b.cosTheta);
    Float thetaD = AngleBetween(a.w, b.w);
    if (std::min<Float>(thetaD + thetaB, Pi) <= thetaA) return a;
    if (std::min<Float>(thetaD + thetaA, Pi) <= thetaB) return b;
    // The merged cone's spread and axis
    Float thetaO = (thetaA + thetaD + thetaB) / 2;
    if (thetaO >= Pi) return DirectionCone::EntireSphere();
    Float thetaR = thetaO - thetaA;
    Vector3f wr = Cross(a.w, b.w);
    if (LengthSquared(wr) == 0) return DirectionCone::EntireSphere();
    Vector3f w = Rotate(Degrees(thetaR), wr)(a.w);
    return DirectionCone(w, std::cos(thetaO));
}

DirectionCone BoundSubtendedDirections(const Bounds3f& b, Point3f p) {
    Point3f center;
    Float radius;
    b.BoundingSphere(&center, &radius);
    Float d2 = DistanceSquared(p, center);
    if (d2 < Sqr(radius)) return DirectionCone::EntireSphere();
    Float sin2ThetaMax = Sqr(radius) / d2;
    return DirectionCone(center - p, SafeSqrt(1 - sin2ThetaMax));
}

LightBounds Union(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0) return b;
    if (b.phi == 0) return a;
    DirectionCone cone = Union(DirectionCone(a.w, a.cosTheta_o), DirectionCone(b.w, b.cosTheta_o));
    LightBounds u(Union(a.bounds, b.bounds), cone.w, a.phi + b.phi, cone.cosTheta,
                  std::min(a.cosTheta_e, b.cosTheta_e), a.twoSided || b.twoSided);
    Float t = b.phi / (a.phi + b.phi);
    u.center = Point3f((1 - t) * Vector3f(a.center) + t * Vector3f(b.center));
    return u;
}

Float LightBounds::Importance(Point3f p, Normal3f n) const {
    // Squared distance to the power-weighted centre, clamped to the bounds' size
    Point3f pc = center;
    Float d2 = std::max(DistanceSquared(p, pc), minDistance2);
    // The angle to the normal cone, less the cone's spread and the bounds' subtended angle
    Vector3f wi = Normalize(p - pc);
    Float cosThetaW = Dot(w, wi);
    if (twoSided) cosThetaW = std::abs(cosThetaW);
    Float sinThetaW = SafeSqrt(1 - Sqr(cosThetaW));
    // The cone of directions from p to the bounding sphere
    Float ds2 = DistanceSquared(p, sphereCenter), r2 = Sqr(sphereRadius);
    Float cosThetaB = ds2 < r2 ? -1 : SafeSqrt(1 - r2 / ds2);
    Float sinThetaB = SafeSqrt(1 - Sqr(cosThetaB));
    Float sinThetaO = SafeSqrt(1 - Sqr(cosTheta_o));
    Float cosThetaX = CosSubClamped(sinThetaW, cosThetaW, sinThetaO, cosTheta_o);
    Float sinThetaX = SinSubClamped(sinThetaW, cosThetaW, sinThetaO, cosTheta_o);
    Float cosThetaP = CosSubClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
    // Outside the emission cone (strictly: a hard-edged spot has cos theta_e = 1, and a point
    // inside its cone cos theta' = 1; pbrt-v4's <= gives those no importance)
    if (cosThetaP < cosTheta_e) return 0;
    Float importance = phi * cosThetaP / d2;
    // The cosine at a receiving surface
    if (n != Normal3f(0, 0, 0)) {
        Float cosThetaI = AbsDot(wi, n);
        Float sinThetaI = SafeSqrt(1 - Sqr(cosThetaI));
        importance *= CosSubClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
    }
    return std::max<Float>(importance, 0);
}

}  // namespace kiln
