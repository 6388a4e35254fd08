// BSDF: a BxDF placed in the local shading frame of a surface point; converts directions
// between render space and the shading frame (normal on +z).
//
// Surfaces with shading normals (interpolated or bumped normals that differ from the
// geometric normal ng): a BxDF's reflection lobe in the shading frame can send light to the
// other side of the geometric surface (where pbrt-v4 lets it leak through an opaque surface),
// and its transmission lobe can send light back to wo's side (so a refracted ray would not
// enter the body, nor its medium). kiln folds such directions back: a direction w on the wrong
// side of the surface for its lobe is mirrored about the geometric tangent plane,
// m(w) = w - 2 (w . ng) ng, so the BSDF becomes
//   f_fold(wo, wi) |wi . ns| = f(wo, wi) |wi . ns| + f(wo, m(wi)) |m(wi) . ns|,
// each term counted only when its lobe matches wi's geometric side (reflection on wo's side,
// transmission on the other). The directional albedo is unchanged (so Kirchhoff emission
// 1 - albedo stays exact and a closed cavity stays in equilibrium), no light passes through an
// opaque surface, reflected light stays in its medium and refracted light enters the other
// (n^2 B inside glass meets the 1 / eta^2 of refraction), and the same estimate holds for
// light and BSDF sampling (MIS). A deliberate difference from pbrt-v4, visible only where
// shading and geometric normals differ strongly.
//
// Folding puts wi on the right side for wo, but wo itself can lie on one side of the geometric
// surface and the other of the shading one (near silhouettes of smooth-shaded meshes). For a
// dielectric the BxDF then takes wo's medium for the other one: in Radiance mode it scales a
// transmission by 1 / eta'^2 for light crossing the wrong way (eta' = eta seen from inside,
// 1 / eta seen from outside). kiln scales it for the crossing the light makes, from wi's side
// of the geometric surface to wo's: the BxDF's value times eta'^4, eta' the shading frame's. A
// surface in equilibrium with n^2 B in its body then still sends n^2 B on wo's geometric side
// (with PointsInside deciding which side its emission is on). Scaling by the shading frame's
// side (pbrt-v4's way), a closed cavity holding a smooth-shaded rough glass mesh rendered
// 0.996 (eta 1.5, 100 triangles) to 1.032 (eta 2.4, 36 triangles) of B(T). Importance mode has
// no 1 / eta'^2 and is unchanged.
//
// Polarised transport (Value = MuellerMatrix): f and Sample_f return Mueller matrices between
// the implicit frames of render-space directions (spectral/polarization.h): light arriving
// along -wi with reference axis StokesBasis(-wi), leaving along wo with StokesBasis(wo). A
// folded direction is a reflection in a perfect mirror lying in the geometric tangent plane,
// and its Mueller matrix is that mirror's (rs = -1, rp = 1).
#pragma once

#include <optional>
#include <span>

#include "materials/bxdfs/bxdf.h"

namespace kiln {

class BSDF {
  public:
    // Invalid BSDF (operator bool false): the surface is only an interface between media.
    BSDF() = default;
    // ns: shading normal; dpdus: shading dp/du. The frame's x axis is dpdus made orthogonal to
    // ns (Gram-Schmidt); if dpdus is degenerate any tangent is used. ng: the geometric normal
    // (zero when unknown), for folding (see above).
    BSDF(Normal3f ns, Vector3f dpdus, const BxDF& bxdf, Normal3f ng = Normal3f(0, 0, 0));

    explicit operator bool() const { return valid; }

    // BSDF value (sr^-1) for render-space directions, both pointing away from the surface.
    // Value: SampledSpectrum or MuellerMatrix.
    template <typename Value = SampledSpectrum>
    Value f(Vector3f woRender, Vector3f wiRender,
            TransportMode mode = TransportMode::Radiance) const;
    // Samples wi (returned in render space). Returns nothing for wo in the tangent plane, zero
    // f, zero pdf or wi in the tangent plane, as pbrt-v4.
    template <typename Value = SampledSpectrum>
    std::optional<BSDFSampleOf<Value>> Sample_f(
        Vector3f woRender, Float u, Point2f u2, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f woRender, Vector3f wiRender, TransportMode mode = TransportMode::Radiance,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;

    BxDFFlags Flags() const { return bxdf.Flags(); }
    void Regularize() { bxdf.Regularize(); }

    const Frame& ShadingFrame() const { return shadingFrame; }
    Vector3f RenderToLocal(Vector3f v) const { return shadingFrame.ToLocal(v); }
    Vector3f LocalToRender(Vector3f v) const { return shadingFrame.FromLocal(v); }

    SampledSpectrum rho(Vector3f woRender, std::span<const Float> uc,
                        std::span<const Point2f> u2) const {
        return bxdf.rho(RenderToLocal(woRender), uc, u2);
    }
    const BxDF& GetBxDF() const { return bxdf; }

    // Whether the BSDF folds (its shading normal differs from the geometric one)
    bool Folds() const { return fold; }
    // Whether wLocal (shading frame) points into the body: below the geometric surface where
    // the BSDF folds, else below the shading one.
    bool PointsInside(Vector3f wLocal) const {
        return fold ? Dot(LocalToRender(wLocal), ng) < 0 : wLocal.z < 0;
    }

  private:
    // Mirror image of w about the geometric tangent plane.
    Vector3f Mirror(Vector3f w) const { return w - 2 * Dot(w, ng) * ng; }
    // Whether w leaves on wo's side of the geometric surface.
    bool SameSide(Vector3f wo, Vector3f w) const { return Dot(wo, ng) * Dot(w, ng) > 0; }
    // The factor (above) for a transmission from local wo, which lies on woRender's geometric
    // side: 1 unless the shading frame puts wo on the other side of a refracting BxDF.
    Float CrossingScale(Vector3f wo, Vector3f woRender, TransportMode mode) const;
    // A BxDF's Mueller matrix for local wo, wi re-expressed in the implicit frames of woRender
    // and wiRender.
    MuellerMatrix ToRenderFrames(const MuellerMatrix& M, Vector3f woRender, Vector3f wiRender,
                                 Vector3f wo, Vector3f wi) const;
    // The folding mirror's Mueller matrix taking light travelling along -wiRender to light
    // travelling along -Mirror(wiRender), implicit frames.
    MuellerMatrix FoldMueller(Vector3f wiRender) const;

    BxDF bxdf;
    Frame shadingFrame;
    Vector3f ng;        // geometric normal when folding (on the shading normal's side), else zero
    bool fold = false;  // the shading normal differs from the geometric one
    bool valid = false;
};

}  // namespace kiln
