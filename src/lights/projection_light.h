// Projection light (pbrt-v4's "projection"): a point light that projects an RGB image like a
// slide projector along its +z axis. The image fills the field of view `fov` (degrees) across
// its shorter side; the intensity towards a direction through the image plane is scale times
// the nearest pixel's RGB as an illuminant spectrum (RGBIlluminantSpectrum, the image's colour
// space), zero outside the image. The image's top row lies towards the light's +y, as in
// pbrt-v4 (which flips y).
#pragma once

#include <optional>

#include "base/sampling.h"
#include "base/transform.h"
#include "core/image/image.h"
#include "lights/light_bounds.h"
#include "lights/light_sample.h"
#include "spectral/color.h"
#include "spectral/spectrum.h"

namespace kiln {

class ProjectionLight {
  public:
    // image: R, G, B, finite (Create's job); imageColorSpace outlives the light.
    ProjectionLight(const Transform& renderFromLight, Image image,
                    const RGBColorSpace* imageColorSpace, Float scale, Float fovDegrees);

    static constexpr LightType kType = LightType::DeltaPosition;
    LightType Type() const { return kType; }

    // Intensity towards w, a unit direction in the projector's frame (+y down the image),
    // W sr^-1 nm^-1.
    SampledSpectrum I(Vector3f wProjector, const SampledWavelengths& lambda) const;

    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext&, Vector3f, bool = false) const { return 0; }
    // A ray leaving the light in proportion to each pixel's value (the mean of R, G, B) times
    // its solid angle (u1); pdfPos 1.
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray& ray) const;
    // The integral of I over the image's solid angle (each pixel's exact solid angle; pbrt-v4
    // takes cos^3 theta at its centre, which differs only for images of few pixels), W nm^-1.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}
    // The cone around +z through the image's corners; phi is Light::Bounds's.
    LightBounds Bounds() const;

    // The image plane z = 1 of the projector's frame holds screen points (x, y) tan(fov / 2);
    // the screen spans [-a, a] x [-1, 1] for an image of aspect ratio a >= 1, else
    // [-1, 1] x [-1 / a, 1 / a] (pbrt-v4's screen window). Solid angle per unit screen area at
    // a screen point: tan^2(fov / 2) cos^3 theta.
    static Bounds2f ScreenBounds(Point2i resolution);
    // The integral of the image's luminance (the Y row of its colour space) over its solid
    // angle: the luminous power at unit scale after the photometric normalisation, which
    // "power" divides by (pbrt-v4's, with exact pixel solid angles as in Phi).
    static double LuminousIntegral(const Image& image, const RGBColorSpace& cs, Float fovDegrees);

  private:
    // The screen point of a direction in the projector's frame; nullopt behind the light or
    // outside the image
    std::optional<Point2f> ScreenPoint(Vector3f w) const;
    // Solid angle per unit screen area at screen point s
    Float SolidAnglePerScreenArea(Point2f s) const;

    Transform renderFromProjector;
    Point3f position;
    Image image;
    const RGBColorSpace* colorSpace;
    Float scale, tanHalfFov;
    Bounds2f screen;
    PiecewiseConstant2D distribution;  // over the screen mapped to [0, 1]^2
};

}  // namespace kiln
