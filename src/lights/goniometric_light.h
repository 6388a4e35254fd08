// Goniometric light (pbrt-v4's "goniometric"): a point light whose intensity towards each
// direction is scale * I(lambda) times the value of a square image in pbrt-v4's equal-area
// octahedral mapping (base/sphere_mappings.h), looked up at its nearest pixel. The map's pole
// (+z of the mapping) is the light's +y axis, as in pbrt-v4 (which swaps y and z).
#pragma once

#include <optional>

#include "base/sampling.h"
#include "base/transform.h"
#include "core/image/image.h"
#include "lights/light_bounds.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class GoniometricLight {
  public:
    // renderFromLight: the light's frame (the CTM at the LightSource); image: one channel
    // ("Y", or the mean of R, G, B: Create's job), square, finite.
    GoniometricLight(const Transform& renderFromLight, Spectrum I, Float scale, Image image);

    static constexpr LightType kType = LightType::DeltaPosition;
    LightType Type() const { return kType; }

    // Intensity towards w, a unit direction in the map's frame, W sr^-1 nm^-1.
    SampledSpectrum I(Vector3f wMap, const SampledWavelengths& lambda) const;

    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext&, Vector3f, bool = false) const { return 0; }
    // A ray leaving the light in proportion to the map's values (u1); pdfPos 1.
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray& ray) const;
    // 4 pi scale I times the map's mean, W nm^-1 (every pixel covers the same solid angle).
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}
    // Bounded as an isotropic point light (as pbrt-v4); phi is Light::Bounds's.
    LightBounds Bounds() const {
        return LightBounds(Bounds3f(position), Vector3f(0, 0, 1), 0, -1, 0, false);
    }

    // The map's pole is the light's +y: the transform from the map's frame to the light's.
    static Transform LightFromMap();

  private:
    Transform renderFromMap;
    Point3f position;
    Spectrum Iemit;
    Float scale;
    Image image;
    Float mean = 0;  // of the image
    PiecewiseConstant2D distribution;
};

}  // namespace kiln
