// Thin dielectric slab (window pane, lamp bulb): specular reflection and straight-through
// transmission summed over all internal inter-reflections. When its IOR does not vary with
// wavelength, its transmission is flagged StraightThrough: the integrators' shadow rays cross
// it, attenuated by T, so light sampling finds a lamp inside a bulb (a dispersive slab stays
// an ordinary specular surface, since a shadow ray cannot terminate the path's secondary
// wavelengths).
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"
#include "spectral/polarization.h"

namespace kiln {

// eta: IOR of the slab relative to the surrounding medium (dimensionless). Non-absorbing.
// straightThrough: light sampling may look through it (eta is the same at every wavelength).
class ThinDielectricBxDF {
  public:
    ThinDielectricBxDF() = default;
    explicit ThinDielectricBxDF(Float eta, bool straightThrough = true)
        : eta(eta), straightThrough(straightThrough) {}

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
        BxDFFlags f = BxDFFlags::Reflection | BxDFFlags::Transmission | BxDFFlags::Specular;
        return straightThrough ? f | BxDFFlags::StraightThrough : f;
    }
    void Regularize() {}

    // Total reflectance R and transmittance T = 1 - R of the slab at |cosTheta_o|.
    static void ReflectanceTransmittance(Float cosTheta_o, Float eta, Float* R, Float* T);

    Float Eta() const { return eta; }

  private:
    Float eta = 1;
    bool straightThrough = true;
};

}  // namespace kiln
