// pbrt-v4's NormalizedFresnelBxDF: the directional part Sw of a TabulatedBSSRDF's exit
// (tabulated_bssrdf.h), f(wi) = (1 - F(cos_i, eta)) / (c pi) on the side of wo, with
// c = 1 - 2 FresnelMoment1(1 / eta) (bssrdf_table.h), times eta^2 for radiance transport
// (the radiance scaling that the dielectric entry divided out). Reflection only; sampled
// cosine-weighted.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"

namespace kiln {

class NormalizedFresnelBxDF {
  public:
    // The exit of diffusely scattered light depolarises (bxdf.h).
    static constexpr bool kDepolarizes = true;

    NormalizedFresnelBxDF() = default;
    explicit NormalizedFresnelBxDF(Float eta);

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    BxDFFlags Flags() const { return BxDFFlags::DiffuseReflection; }
    void Regularize() {}

    Float Eta() const { return eta; }
    // integral f(wo, wi) |cos_i| dwi for radiance transport, divided by eta^2: the fraction of
    // what reaches the exit that leaves it ((1 - 2 integral F mu dmu) / c, by quadrature;
    // pbrt-v4's c is a polynomial fit, so this is not exactly 1)
    Float ExitFraction() const;

  private:
    Float eta = 1, c = 1;
};

}  // namespace kiln
