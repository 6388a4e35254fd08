// Lambertian reflection and transmission (pbrt-v4's DiffuseTransmissionBxDF): a thin diffusing
// sheet such as paper, cloth or a lamp shade.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"

namespace kiln {

// f = R / pi on the side of wo and T / pi on the other (sr^-1); R + T <= 1 is the sheet's
// albedo, the same from either side. Sampling picks reflection or transmission in proportion
// to the largest value of R and of T (as pbrt-v4), cosine-weighted on the chosen side.
class DiffuseTransmissionBxDF {
  public:
    // Diffuse scattering depolarises (bxdf.h).
    static constexpr bool kDepolarizes = true;

    DiffuseTransmissionBxDF() = default;
    DiffuseTransmissionBxDF(SampledSpectrum R, SampledSpectrum T) : R(R), T(T) {}

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    BxDFFlags Flags() const {
        return (R ? BxDFFlags::DiffuseReflection : BxDFFlags::Unset) |
               (T ? BxDFFlags::DiffuseTransmission : BxDFFlags::Unset);
    }
    void Regularize() {}

    const SampledSpectrum& Reflectance() const { return R; }
    const SampledSpectrum& Transmittance() const { return T; }

  private:
    // Probabilities of sampling reflection and transmission, for the sample flags
    void Probabilities(BxDFReflTransFlags sampleFlags, Float* pr, Float* pt) const;

    SampledSpectrum R, T;
};

}  // namespace kiln
