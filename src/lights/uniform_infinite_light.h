// Constant environment (pbrt-v4's "infinite" light without an image): radiance scale * L
// (W m^-2 sr^-1 nm^-1) arriving from every direction at infinity.
#pragma once

#include <optional>

#include "base/transform.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class UniformInfiniteLight {
  public:
    UniformInfiniteLight(const Transform& renderFromLight, Spectrum Lemit, Float scale);

    static constexpr LightType kType = LightType::Infinite;
    LightType Type() const { return kType; }

    // Radiance along a ray that escapes the scene: scale L.
    SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const;
    // Uniform over the sphere (pdf 1 / 4 pi sr^-1). With allowIncompletePDF (MIS with BSDF
    // sampling) no sample is drawn and PDF_Li is 0, as in pbrt-v4: BSDF sampling covers it.
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // A ray entering the scene: direction uniform over the sphere (u1), origin uniform on the
    // disk of the scene's bounding sphere perpendicular to it (u2), pdfPos 1 / (pi r^2),
    // pdfDir 1 / 4 pi (pbrt-v4's UniformInfiniteLight::SampleLe).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray&) const;
    // 4 pi^2 r^2 scale L, W nm^-1 (r: the scene's bounding-sphere radius).
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f& sceneBounds) const;

  private:
    Spectrum Lemit;
    Float scale;
    mutable Point3f sceneCenter;
    mutable Float sceneRadius = 0;
};

}  // namespace kiln
