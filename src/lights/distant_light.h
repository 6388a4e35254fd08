// Directional light (pbrt-v4's "distant"): radiance scale * L (W m^-2 sr^-1 nm^-1) arriving from
// one direction, the light's +z axis in render space; the irradiance it gives a surface facing
// it is scale * L per unit solid angle, i.e. scale * L W m^-2 nm^-1 (delta in direction).
#pragma once

#include <optional>

#include "base/transform.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class DistantLight {
  public:
    // renderFromLight maps the light's +z axis to the direction towards the light.
    DistantLight(const Transform& renderFromLight, Spectrum Lemit, Float scale);

    static constexpr LightType kType = LightType::DeltaDirection;
    LightType Type() const { return kType; }
    // Unit render-space direction from the scene towards the light.
    Vector3f Direction() const { return wLight; }

    // Li = scale L from Direction(); pdf 1 (delta); pLight lies beyond the scene's bounds.
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext&, Vector3f, bool = false) const { return 0; }
    // A ray entering the scene along -Direction() from a point uniform on the disk of the
    // scene's bounding sphere facing the light, pdfPos 1 / (pi r^2), pdfDir 1 (delta;
    // pbrt-v4's DistantLight::SampleLe; u2 unused).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray&) const { return {1 / (Pi * Sqr(sceneRadius)), 0}; }
    // Power through the disk the scene's bounding sphere presents: scale L pi r^2, W nm^-1.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    // Learns the scene's bounding sphere (needed by SampleLi and Phi).
    void Preprocess(const Bounds3f& sceneBounds) const;

  private:
    Vector3f wLight;
    Spectrum Lemit;
    Float scale;
    mutable Point3f sceneCenter;
    mutable Float sceneRadius = 0;
};

}  // namespace kiln
