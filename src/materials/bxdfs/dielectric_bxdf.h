// Interface between two dielectrics: smooth or Trowbridge-Reitz rough, reflection and
// refraction.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "materials/bxdfs/fresnel.h"
#include "materials/bxdfs/microfacet.h"
#include "spectral/polarization.h"

namespace kiln {

// eta: IOR of the inside (-z side) over the outside (+z side), dimensionless. In Radiance mode
// transmitted radiance is scaled by 1/eta'^2 (non-symmetric scattering, Veach 1997 Sec. 5.2).
// eta == 1 is an index-matched interface: pure specular transmission. k > 0: the inside absorbs
// (complex index eta + i k): reflectances are fresnel.h's FrAbsorbingDielectric, what is not
// reflected is transmitted (the body's interior medium absorbs it).
class DielectricBxDF {
  public:
    DielectricBxDF() = default;
    DielectricBxDF(Float eta, const TrowbridgeReitzDistribution& mfDistrib, Float k = 0)
        : eta(eta), k(k), mfDistrib(mfDistrib) {}

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
        BxDFFlags flags =
            Matched() ? BxDFFlags::Transmission : (BxDFFlags::Reflection | BxDFFlags::Transmission);
        return flags | (mfDistrib.EffectivelySmooth() ? BxDFFlags::Specular : BxDFFlags::Glossy);
    }
    void Regularize() { mfDistrib.Regularize(); }

    Float Eta() const { return eta; }
    Float K() const { return k; }
    const TrowbridgeReitzDistribution& Distribution() const { return mfDistrib; }

  private:
    // Rough reflection or refraction from wo to wi: the generalised half vector and f without
    // its Fresnel factor (with the 1/eta'^2 of Radiance mode); nullopt where f is zero.
    std::optional<MicrofacetTerm> Term(Vector3f wo, Vector3f wi, TransportMode mode) const;
    // Unpolarised reflectance at incidence cosTheta (either side)
    Float Fr(Float cosTheta) const { return FrAbsorbingDielectric(cosTheta, eta, k); }
    // Whether the interface is index-matched without absorption: pure transmission
    bool Matched() const { return eta == 1 && k == 0; }

    Float eta = 1, k = 0;
    TrowbridgeReitzDistribution mfDistrib;
};

}  // namespace kiln
