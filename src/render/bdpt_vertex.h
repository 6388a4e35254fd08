// A vertex of a bidirectional path (pbrt-v4's BDPT Vertex, surfaces only): the camera or a
// light at the ends of the subpaths, or a scattering surface, with the path throughput beta up
// to it and the area densities (pdfFwd, pdfRev) with which the two subpaths would generate it.
#pragma once

#include "base/interaction.h"
#include "lights/light.h"
#include "materials/bxdfs/bsdf.h"

namespace kiln {

enum class BDPTVertexType { Camera, Light, Surface };

struct BDPTVertex {
    BDPTVertexType type = BDPTVertexType::Camera;
    SampledSpectrum beta;
    // The point: a surface hit (Surface), or for the end points only p and n (n zero where
    // there is no surface: the pinhole, point lights, lights at infinity's sampled points; a
    // ray escaping the scene becomes a light vertex one unit along it with n = -d, as pbrt-v4)
    SurfaceInteraction si;
    BSDF bsdf;
    // Light vertices: the light's index in the scene's list, -1 for a ray that escaped (all
    // infinite lights together)
    int light = -1;
    // Light vertices: the light's kind (LightType::Infinite for escaped rays)
    LightType lightType = LightType::Infinite;
    bool delta = false;  // sampled by a specular BSDF
    Float pdfFwd = 0, pdfRev = 0;

    Point3f p() const { return si.p; }
    Normal3f ng() const { return si.n; }
    Normal3f ns() const { return type == BDPTVertexType::Surface ? si.shading.n : si.n; }
    bool IsOnSurface() const { return si.n != Normal3f(0, 0, 0); }

    // A light end point: a surface-light vertex is a Surface whose si.lightIndex >= 0
    bool IsLight() const {
        return type == BDPTVertexType::Light ||
               (type == BDPTVertexType::Surface && si.lightIndex >= 0);
    }
    bool IsDeltaLight() const {
        return type == BDPTVertexType::Light && light >= 0 && kiln::IsDeltaLight(lightType);
    }
    bool IsInfiniteLight() const {
        return type == BDPTVertexType::Light && (light < 0 || lightType == LightType::Infinite ||
                                                 lightType == LightType::DeltaDirection);
    }
    // Whether a connection may end here: not at a distant light, not at a specular surface
    bool IsConnectible() const {
        switch (type) {
            case BDPTVertexType::Light:
                return lightType != LightType::DeltaDirection;
            case BDPTVertexType::Camera:
                return true;
            case BDPTVertexType::Surface:
                return IsNonSpecular(bsdf.Flags());
        }
        return false;
    }

    // The BSDF from this surface vertex towards next (0 if they coincide); in Importance mode
    // the adjoint (AdjointF).
    SampledSpectrum f(const BDPTVertex& next, TransportMode mode) const {
        Vector3f wi = next.p() - p();
        if (LengthSquared(wi) == 0) return SampledSpectrum(0);
        wi = Normalize(wi);
        if (mode == TransportMode::Importance) return AdjointF(bsdf, si, si.wo, wi);
        return bsdf.f(si.wo, wi, mode);
    }
    // What a surface scatters towards wi of the light arriving along -wo from a light: the
    // adjoint of the BSDF the camera's paths see, f(wi, wo) in Radiance mode, times
    // ShadingNormalAdjoint. Where the BSDF does not fold, Importance mode's f(wo, wi) is that
    // value (pbrt-v4's convention); a folding BSDF (bsdf.h) mirrors its second direction, so
    // it is evaluated with the two swapped. (The layered BxDFs keep Importance mode: their f
    // is a stochastic estimate, and f over PDF would not weigh their samples exactly.)
    static SampledSpectrum AdjointF(const BSDF& bsdf, const SurfaceInteraction& si, Vector3f wo,
                                    Vector3f wi) {
        SampledSpectrum value = AdjointSwaps(bsdf) ? bsdf.f(wi, wo, TransportMode::Radiance)
                                                   : bsdf.f(wo, wi, TransportMode::Importance);
        return value ? value * ShadingNormalAdjoint(si, wo, wi) : value;
    }
    // Whether AdjointF evaluates bsdf with its directions swapped
    static bool AdjointSwaps(const BSDF& bsdf) {
        return bsdf.Folds() && !bsdf.GetBxDF().EstimatesStochastically();
    }
    // Light carried from a light along -wo and scattered towards wi at a surface with shading
    // normals (Veach 1997, Sec. 5.3): the adjoint BSDF is f(wi, wo) |wo.ns| |wi.ng| /
    // (|wo.ng| |wi.ns|), the cosines at the surface of the radiance equation being the shading
    // normal's on the side of the light and the geometric normal's (the area measure's) on the
    // other. Light subpaths carry this factor at each surface; 1 where ns = ng.
    static Float ShadingNormalAdjoint(const SurfaceInteraction& si, Vector3f wo, Vector3f wi) {
        Float num = AbsDot(wo, si.shading.n) * AbsDot(wi, si.n);
        Float denom = AbsDot(wo, si.n) * AbsDot(wi, si.shading.n);
        return denom == 0 ? 0 : num / denom;
    }

    // A solid-angle density at this vertex turned into an area density at next (unchanged
    // when next is at infinity).
    Float ConvertDensity(Float pdf, const BDPTVertex& next) const {
        if (next.IsInfiniteLight()) return pdf;
        Vector3f w = next.p() - p();
        Float d2 = LengthSquared(w);
        if (d2 == 0) return 0;
        Float invDist2 = 1 / d2;
        if (next.IsOnSurface()) pdf *= AbsDot(next.ng(), w * std::sqrt(invDist2));
        return pdf * invDist2;
    }
};

}  // namespace kiln
