// Lambertian reflection.
#pragma once

#include <optional>

#include "materials/bxdfs/bxdf_types.h"

namespace kiln {

// f = R / pi (sr^-1) on the side of wo; R is the hemispherical reflectance in [0, 1].
class DiffuseBxDF {
  public:
    // Lambertian reflection depolarises (bxdf.h: the ideal depolariser f diag(1, 0, 0, 0)).
    static constexpr bool kDepolarizes = true;

    DiffuseBxDF() = default;
    explicit DiffuseBxDF(SampledSpectrum R) : R(R) {}

    SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode mode) const;
    std::optional<BSDFSample> Sample_f(
        Vector3f wo, Float uc, Point2f u, TransportMode mode = TransportMode::Radiance,
        BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    Float PDF(Vector3f wo, Vector3f wi, TransportMode mode,
              BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const;
    BxDFFlags Flags() const { return R ? BxDFFlags::DiffuseReflection : BxDFFlags::Unset; }
    void Regularize() {}

    const SampledSpectrum& Reflectance() const { return R; }

  private:
    SampledSpectrum R;
};

}  // namespace kiln
