// Points where light interacts with surfaces, and the rays spawned from them.
#pragma once

#include <array>

#include "base/vecmath.h"

namespace kiln {

class Material;
class ThermalEmission;
class TriangleMesh;

// Shadow rays stop this fraction short of their target so they do not hit the target itself.
inline constexpr Float ShadowEpsilon = 0.0001f;

// The participating media on the two sides of a surface, by index into the scene's media (-1:
// none): inside is the side the geometric normal points away from. A surface with the same
// medium on both sides is no boundary; rays crossing it keep the medium they are in.
struct MediumInterface {
    int inside = -1, outside = -1;
    MediumInterface() = default;
    MediumInterface(int inside, int outside) : inside(inside), outside(outside) {}
    bool IsTransition() const { return inside != outside; }
};

struct Interaction {
    Point3f p;       // render-space position
    Normal3f n;      // geometric normal (zero for points not on a surface)
    Point2f uv;      // surface parameterisation
    Vector3f wo;     // outgoing direction (towards where the path came from), unit
    Float time = 0;  // shutter time in [0, 1]
    // How far off the surface spawned rays start, beyond kiln's integer-ULP offset: the
    // half-extent per axis of the box around p the surface may pass through (pbrt-v4's pError;
    // only curves set it, to their hit width, since their ray-facing surface turns with every
    // ray and a ray leaving one would meet the same curve again).
    Float originError = 0;

    Interaction() = default;
    Interaction(Point3f p, Normal3f n, Point2f uv, Vector3f wo = {}, Float time = 0)
        : p(p), n(n), uv(uv), wo(wo), time(time) {}
    bool IsSurfaceInteraction() const { return n != Normal3f(0, 0, 0); }

    Point3f OffsetRayOrigin(Vector3f w) const {
        return IsSurfaceInteraction() ? kiln::OffsetRayOrigin(p, n, w, originError) : p;
    }
    Ray SpawnRay(Vector3f d) const { return Ray(OffsetRayOrigin(d), d, time); }
    // Ray towards p2 whose direction is (p2 - origin), so t in [0, 1 - ShadowEpsilon] covers
    // the segment up to just before p2.
    Ray SpawnRayTo(Point3f p2) const {
        Point3f o = OffsetRayOrigin(p2 - p);
        return Ray(o, p2 - o, time);
    }
    Ray SpawnRayTo(const Interaction& it) const {
        Point3f pTo = it.OffsetRayOrigin(p - it.p);
        return SpawnRayTo(pTo);
    }
};

struct SurfaceInteraction : Interaction {
    Vector3f dpdu, dpdv;
    Normal3f dndu, dndv;
    struct {
        Normal3f n;  // shading normal, same hemisphere as n
        Vector3f dpdu, dpdv;
        Normal3f dndu, dndv;
    } shading;
    int faceIndex = 0;
    const Material* material = nullptr;
    // The scene light this surface point belongs to (its index in the scene's light list), -1
    // if none; and the surface's thermal emission (thermal/thermal_emission.h), also for hot
    // shapes that are not lights (inside object instances)
    int lightIndex = -1;
    const ThermalEmission* thermal = nullptr;
    // The index the scene gave this surface among the glass windows light sampling looks
    // through into a hot medium (render/glass_windows.h), -1 if none
    int windowIndex = -1;
    // Screen-space footprint (for texture filtering); zero when unknown.
    Vector3f dpdx, dpdy;
    Float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
    // Triangle hits (kiln extension, for per-vertex attributes such as "temperature"): the
    // mesh, the triangle's index in it and the barycentrics of p; mesh is nullptr otherwise.
    const TriangleMesh* mesh = nullptr;
    int triIndex = 0;
    std::array<Float, 3> b = {0, 0, 0};
    // The media the surface separates (a transition), or none
    MediumInterface mediumInterface;

    SurfaceInteraction() = default;
    // pbrt-v4 convention: n = normalize(cross(dpdu, dpdv)) (in double), flipped when flipNormal is
    // true (ReverseOrientation xor handedness swap); shading frame initialised to the geometric
    // one.
    SurfaceInteraction(Point3f p, Point2f uv, Vector3f wo, Vector3f dpdu, Vector3f dpdv,
                       Normal3f dndu, Normal3f dndv, Float time, bool flipNormal)
        : Interaction(p, Normal3f(NormalizedCross(dpdu, dpdv)), uv, wo, time),
          dpdu(dpdu),
          dpdv(dpdv),
          dndu(dndu),
          dndv(dndv) {
        if (flipNormal) n = -n;
        shading.n = n;
        shading.dpdu = dpdu, shading.dpdv = dpdv;
        shading.dndu = dndu, shading.dndv = dndv;
    }
    // The medium a ray leaving the surface in direction w travels in, when the ray arriving at
    // it was in medium current.
    int MediumAfter(Vector3f w, int current) const {
        if (!mediumInterface.IsTransition()) return current;
        return Dot(w, n) > 0 ? mediumInterface.outside : mediumInterface.inside;
    }
    // Sets the shading frame; the geometric normal is flipped to the shading normal's side
    // when orientationIsAuthoritative, otherwise the shading normal follows the geometric one.
    void SetShadingGeometry(Normal3f ns, Vector3f dpdus, Vector3f dpdvs, Normal3f dndus,
                            Normal3f dndvs, bool orientationIsAuthoritative) {
        shading.n = ns;
        if (orientationIsAuthoritative)
            n = FaceForward(n, Vector3f(shading.n));
        else
            shading.n = FaceForward(shading.n, Vector3f(n));
        shading.dpdu = dpdus, shading.dpdv = dpdvs;
        shading.dndu = dndus, shading.dndv = dndvs;
        while (LengthSquared(shading.dpdu) > 1e16f || LengthSquared(shading.dpdv) > 1e16f) {
            shading.dpdu *= 1e-8f;
            shading.dpdv *= 1e-8f;
        }
    }
};

}  // namespace kiln
