// BSDF: a BxDF placed in the local shading frame of a surface point; converts directions
// between render space and the shading frame (normal on +z).
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
    // ns (Gram-Schmidt); if dpdus is degenerate any tangent is used.
    BSDF(Normal3f ns, Vector3f dpdus, const BxDF& bxdf);

    explicit operator bool() const { return valid; }

    // BSDF value (sr^-1) for render-space directions, both pointing away from the surface.
    SampledSpectrum f(Vector3f woRender, Vector3f wiRender,
                      TransportMode mode = TransportMode::Radiance) const;
    // Samples wi (returned in render space). Returns nothing for wo in the tangent plane, zero
    // f, zero pdf or wi in the tangent plane, as pbrt-v4.
    std::optional<BSDFSample> Sample_f(
        Vector3f woRender, Float u, Point2f u2, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f woRender, Vector3f wiRender, TransportMode mode = TransportMode::Radiance,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;

    BxDFFlags Flags() const { return bxdf.Flags(); }
    void Regularize() { bxdf.Regularize(); }

    Vector3f RenderToLocal(Vector3f v) const { return shadingFrame.ToLocal(v); }
    Vector3f LocalToRender(Vector3f v) const { return shadingFrame.FromLocal(v); }

    SampledSpectrum rho(Vector3f woRender, std::span<const Float> uc,
                        std::span<const Point2f> u2) const {
        return bxdf.rho(RenderToLocal(woRender), uc, u2);
    }
    const BxDF& GetBxDF() const { return bxdf; }

  private:
    BxDF bxdf;
    Frame shadingFrame;
    bool valid = false;
};

}  // namespace kiln
