// Spotlight (pbrt-v4's "spot"): a point light whose intensity scale * I (W sr^-1 nm^-1) is
// full inside the cone of half-angle `falloffStart` around the light's +z axis and falls off
// smoothly (smoothstep in cos theta) to zero at half-angle `totalWidth`.
#pragma once

#include <optional>

#include "base/transform.h"
#include "lights/light_bounds.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class SpotLight {
  public:
    // Angles in degrees; renderFromLight maps the light's +z axis to the spot direction.
    SpotLight(const Transform& renderFromLight, Spectrum I, Float scale, Float totalWidthDeg,
              Float falloffStartDeg);

    static constexpr LightType kType = LightType::DeltaPosition;
    LightType Type() const { return kType; }

    // Intensity towards light-space direction w (unit), W sr^-1 nm^-1.
    SampledSpectrum I(Vector3f wLight, const SampledWavelengths& lambda) const;

    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext&, Vector3f, bool = false) const { return 0; }
    // A ray leaving the light: the full cone or the falloff ring chosen in proportion to their
    // share of ConeSolidAngle (u2[0]), then uniform in the cone or smoothstep-distributed in cos
    // theta in the ring (u1); pdfPos 1 (pbrt-v4's SpotLight::SampleLe).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    // pdfPos 0 (delta), pdfDir the density of SampleLe's direction ray.d.
    LightLePDF PDF_Le(const Ray& ray) const;
    // scale I 2 pi ((1 - cos start) + (cos start - cos end) / 2), W nm^-1.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}
    // Its position, spot axis and cone (phi left 0: Light::Bounds fills it in).
    LightBounds Bounds() const {
        Vector3f w = Normalize(renderFromLight(Vector3f(0, 0, 1)));
        Float cosThetaE = std::cos(SafeACos(cosFalloffEnd) - SafeACos(cosFalloffStart));
        return LightBounds(Bounds3f(position), w, 0, cosFalloffStart, cosThetaE, false);
    }

    // The solid-angle factor of Phi: 2 pi ((1 - cos start) + (cos start - cos end) / 2), sr.
    static Float ConeSolidAngle(Float cosFalloffStart, Float cosFalloffEnd);

  private:
    Transform renderFromLight;
    Point3f position;
    Spectrum Iemit;
    Float scale, cosFalloffStart, cosFalloffEnd;
};

}  // namespace kiln
