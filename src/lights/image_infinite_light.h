// Environment map (pbrt-v4's "infinite" light with "filename"): radiance from an RGB image
// wrapped around the scene at infinity, RGBIlluminantSpectrum(rgb) * scale in
// W m^-2 sr^-1 nm^-1, looked up at the nearest pixel (as pbrt-v4).
//
// Two parameterisations of the sphere of light-space directions, chosen by the image's shape:
// - square images: pbrt-v4's equal-area octahedral map (EqualAreaSquareToSphere), wrap mode
//   OctahedralSphere; every pixel covers 4 pi / (w h) sr;
// - 2:1 images (kiln extension): equirectangular latitude-longitude maps as pbrt-v3 read them,
//   +z up in light space: column u = phi / 2 pi (phi from +x towards +y), row v = theta / pi
//   (theta from +z; the top row is the +z pole). A pixel covers 2 pi^2 sin(theta) / (w h) sr.
//
// Directions are importance sampled with PiecewiseConstant2D over the pixels in proportion to
// radiance per unit (u, v) (channel average times the solid angle per unit (u, v)); the pdfs
// SampleLi returns and PDF_Li reports are exact densities per steradian. With
// allowIncompletePDF pbrt-v4's compensated distribution max(L - mean L, 0) is used instead.
#pragma once

#include <optional>
#include <string>

#include "base/sampling.h"
#include "base/transform.h"
#include "core/image/image.h"
#include "lights/light_sample.h"
#include "spectral/spectrum.h"

namespace kiln {

class RGBColorSpace;

enum class EnvironmentMapping { EqualAreaOctahedral, Equirectangular };

class ImageInfiniteLight {
  public:
    // image must have "R", "G" and "B" channels and be square or 2:1 (else
    // std::invalid_argument naming `filename`); its RGB is in colorSpace (which outlives the
    // light).
    ImageInfiniteLight(const Transform& renderFromLight, const Image& image,
                       const RGBColorSpace* colorSpace, Float scale,
                       const std::string& filename = "");

    static constexpr LightType kType = LightType::Infinite;
    LightType Type() const { return kType; }
    EnvironmentMapping Mapping() const { return mapping; }
    // Whether renderFromLight maps unit directions to unit directions (its upper 3x3 a
    // rotation, within 1e-4). Otherwise SampleLi reports the length pbrt-v4's unnormalised
    // direction would have (LightLiSample::wiLength) and PDF_Li looks the map up as pbrt-v4.
    bool PreservesLengths() const { return preservesLengths; }

    SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const;
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // A ray entering the scene: direction from the image distribution (u1; the ray travels
    // along -DirectionFromST), origin uniform on the disk of the scene's bounding sphere
    // perpendicular to it (u2); pdfPos 1 / (pi r^2), pdfDir per sr (pbrt-v4's
    // ImageInfiniteLight::SampleLe).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray& ray) const;
    // pi r^2 times the integral of radiance over the sphere, W nm^-1.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f& sceneBounds) const;

    // Light-space direction <-> image st in [0,1]^2 for this light's mapping.
    Vector3f DirectionFromST(Point2f st) const;
    Point2f STFromDirection(Vector3f wLight) const;
    // Solid angle per unit st area at direction wLight (4 pi or 2 pi^2 sin theta), sr.
    Float SolidAnglePerUnitST(Vector3f wLight) const;

  private:
    SampledSpectrum ImageLe(Point2f st, const SampledWavelengths& lambda) const;

    Transform renderFromLight;
    Image image;  // R, G, B only
    const RGBColorSpace* colorSpace;
    Float scale;
    EnvironmentMapping mapping;
    WrapMode wrapMode;
    bool preservesLengths;
    PiecewiseConstant2D distribution, compensatedDistribution;
    mutable Point3f sceneCenter;
    mutable Float sceneRadius = 0;
};

}  // namespace kiln
