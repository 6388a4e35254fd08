// Helpers shared by the shape implementations: transforming surface interactions, the
// Weingarten equations for normal derivatives, robust normalisation, and the conversion of
// area-measure samples to solid-angle measure.
#pragma once

#include <optional>

#include "base/interaction.h"
#include "base/transform.h"
#include "base/vecmath.h"
#include "core/geometry/shape_sample.h"

namespace kiln {

// Normalises v without underflow for tiny vectors (sliver triangles); zero stays zero.
template <typename T>
inline T SafeNormalize(const T& v) {
    Float m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (m == 0 || !std::isfinite(m)) return T(0, 0, 0);
    T s = v / m;
    return s / Length(s);
}

// Normal derivatives from the first and second fundamental forms (Weingarten equations).
inline void WeingartenNormalDerivatives(Vector3f dpdu, Vector3f dpdv, Vector3f d2Pduu,
                                        Vector3f d2Pduv, Vector3f d2Pdvv, Normal3f* dndu,
                                        Normal3f* dndv) {
    // In double: E G reaches 1e40 for a sphere of radius 1e10
    auto dot = [](Vector3f a, Vector3f b) {
        return double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
    };
    double E = dot(dpdu, dpdu), F = dot(dpdu, dpdv), G = dot(dpdv, dpdv);
    Vector3f N = SafeNormalize(Cross(dpdu, dpdv));
    double e = dot(N, d2Pduu), f = dot(N, d2Pduv), g = dot(N, d2Pdvv);
    double EGF2 = E * G - F * F;
    double inv = EGF2 == 0 ? 0 : 1 / EGF2;
    *dndu = Normal3f(Float((f * F - e * G) * inv) * dpdu + Float((e * F - f * E) * inv) * dpdv);
    *dndv = Normal3f(Float((g * F - f * G) * inv) * dpdu + Float((f * F - g * E) * inv) * dpdv);
}

// Applies t to every geometric quantity of a surface interaction (pbrt-v4's
// Transform::operator()(SurfaceInteraction)); normals stay unit and the shading normal stays
// in the geometric normal's hemisphere.
inline SurfaceInteraction TransformInteraction(const Transform& t, const SurfaceInteraction& si) {
    SurfaceInteraction r = si;
    r.p = t(si.p);
    r.n = SafeNormalize(t(si.n));
    if (si.wo != Vector3f(0, 0, 0)) r.wo = SafeNormalize(t(si.wo));
    r.dpdu = t(si.dpdu), r.dpdv = t(si.dpdv);
    r.dndu = t(si.dndu), r.dndv = t(si.dndv);
    r.shading.n = FaceForward(SafeNormalize(t(si.shading.n)), Vector3f(r.n));
    r.shading.dpdu = t(si.shading.dpdu), r.shading.dpdv = t(si.shading.dpdv);
    r.shading.dndu = t(si.shading.dndu), r.shading.dndv = t(si.shading.dndv);
    r.dpdx = t(si.dpdx), r.dpdy = t(si.dpdy);
    if (si.originError > 0) {
        // Scaled as a length: by the cube root of the volume scale
        Vector3f ax = t(Vector3f(1, 0, 0)), ay = t(Vector3f(0, 1, 0)), az = t(Vector3f(0, 0, 1));
        r.originError = si.originError * std::cbrt(std::abs(Dot(ax, Cross(ay, az))));
    }
    return r;
}

// Converts an area-measure sample seen from ctx to solid-angle measure (pdf in sr^-1);
// nullopt when the point coincides with ctx.p or the density is infinite.
inline std::optional<ShapeSample> AreaSampleToSolidAngle(const ShapeSampleContext& ctx,
                                                         ShapeSample ss) {
    Vector3f wi = ss.intr.p - ctx.p;
    if (LengthSquared(wi) == 0) return std::nullopt;
    Float dist2 = LengthSquared(wi);
    wi = Normalize(wi);
    ss.pdf /= AbsDot(ss.intr.n, -wi) / dist2;
    if (!std::isfinite(ss.pdf)) return std::nullopt;
    return ss;
}

}  // namespace kiln
