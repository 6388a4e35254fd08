// Isotropic point light (pbrt-v4's "point"): radiant intensity I (W sr^-1 nm^-1) from one point.
#pragma once

#include <optional>

#include "base/sampling.h"
#include "base/transform.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class PointLight {
  public:
    // I is scaled by `scale` (which already holds pbrt-v4's photometric normalisation);
    // renderFromLight places the light at its origin.
    PointLight(const Transform& renderFromLight, Spectrum I, Float scale);

    static constexpr LightType kType = LightType::DeltaPosition;
    LightType Type() const { return kType; }
    Point3f Position() const { return position; }

    // Li = scale I / r^2 towards the light; pdf 1 (delta).
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext&, Vector3f, bool = false) const { return 0; }
    // A ray leaving the light uniformly over the sphere: L = scale I, pdfPos 1, pdfDir 1 / 4 pi
    // (pbrt-v4's PointLight::SampleLe; u2 unused).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray&) const { return {0, UniformSpherePDF()}; }
    // Radiant power 4 pi scale I, W nm^-1.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}

  private:
    Point3f position;
    Spectrum I;
    Float scale;
};

}  // namespace kiln
