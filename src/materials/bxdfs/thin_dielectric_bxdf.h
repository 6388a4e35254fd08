// Thin dielectric slab (window pane): specular reflection and straight-through transmission
// summed over all internal inter-reflections.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "spectral/polarization.h"

namespace kiln {

// eta: IOR of the slab relative to the surrounding medium (dimensionless). Non-absorbing.
class ThinDielectricBxDF {
  public:
    ThinDielectricBxDF() = default;
    explicit ThinDielectricBxDF(Float eta) : eta(eta) {}

    SampledSpectrum f(Vector3f, Vector3f, TransportMode) const { return SampledSpectrum(0.f); }
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f, Vector3f, TransportMode,
              BxDFReflTransFlags = BxDFReflTransFlags::All) const {
        return 0;
    }
    // Polarised transport: Mueller matrices in the frames of fresnel_mueller.h, for a pair of
    // directions (zero for specular lobes) and for a sample Sample_f returned.
    MuellerMatrix MuellerF(Vector3f, Vector3f, TransportMode) const { return {}; }
    MuellerMatrix MuellerSample(Vector3f wo, const BSDFSample& bs, TransportMode mode) const;
    BxDFFlags Flags() const {
        return BxDFFlags::Reflection | BxDFFlags::Transmission | BxDFFlags::Specular;
    }
    void Regularize() {}

    // Total reflectance R and transmittance T = 1 - R of the slab at |cosTheta_o|.
    static void ReflectanceTransmittance(Float cosTheta_o, Float eta, Float* R, Float* T);

    Float Eta() const { return eta; }

  private:
    Float eta = 1;
};

}  // namespace kiln
