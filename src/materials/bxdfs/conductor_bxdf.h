// Metals: Fresnel reflection from a smooth or Trowbridge-Reitz rough conductor.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "materials/bxdfs/microfacet.h"
#include "spectral/polarization.h"

namespace kiln {

// eta, k: real and imaginary parts of the conductor's IOR relative to the outside medium, per
// sampled wavelength (dimensionless). Reflection only, on the side of +z (wo and wi with
// negative z are treated by symmetry through |cos|, as pbrt-v4).
class ConductorBxDF {
  public:
    ConductorBxDF() = default;
    ConductorBxDF(const TrowbridgeReitzDistribution& mfDistrib, SampledSpectrum eta,
                  SampledSpectrum k)
        : mfDistrib(mfDistrib), eta(eta), k(k) {}

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    // Polarised transport: Mueller matrices in the frames of fresnel_mueller.h, for a pair of
    // directions (zero for specular lobes) and for a sample Sample_f returned.
    MuellerMatrix MuellerF(Vector3f wo, Vector3f wi, TransportMode mode) const;
    MuellerMatrix MuellerSample(Vector3f wo, const BSDFSample& bs, TransportMode mode) const;
    BxDFFlags Flags() const {
        return mfDistrib.EffectivelySmooth() ? BxDFFlags::SpecularReflection
                                             : BxDFFlags::GlossyReflection;
    }
    void Regularize() { mfDistrib.Regularize(); }

    const TrowbridgeReitzDistribution& Distribution() const { return mfDistrib; }
    const SampledSpectrum& Eta() const { return eta; }
    const SampledSpectrum& K() const { return k; }

  private:
    // Rough reflection from wo to wi: wm and D G / (4 cos_i cos_o); nullopt where f is zero.
    std::optional<MicrofacetTerm> Term(Vector3f wo, Vector3f wi) const;

    TrowbridgeReitzDistribution mfDistrib;
    SampledSpectrum eta, k;
};

}  // namespace kiln
