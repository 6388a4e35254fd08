// Diffuse area light (pbrt-v4's AreaLightSource "diffuse"): a shape emitting radiance
// scale * L (W m^-2 sr^-1 nm^-1) uniformly in direction from the side its surface normal points
// to (both sides if twoSided), or an RGB image over the shape's (u, v) parameterisation.
#pragma once

#include <optional>

#include "base/transform.h"
#include "core/image/image.h"
#include "lights/light_sample.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/spectrum.h"

namespace kiln {

class Shape;
class AlphaMask;
class RGBColorSpace;

class DiffuseAreaLight {
  public:
    // shape must outlive the light (the scene's arena holds both). With a non-empty image
    // (R, G, B channels in imageColorSpace) emission comes from the image at
    // (u, 1 - v), bilinearly filtered, as pbrt-v4; Lemit is then unused.
    // alpha (the shape's cut-outs, nullptr: none) makes light sampling skip points where the
    // shape is cut out; rays never hit such points in the first place. A constant alpha of 0
    // makes an invisible light as in pbrt-v4: never hit, yet emitting over the whole shape,
    // found by light sampling alone (Type() DeltaPosition: no MIS against BSDF sampling).
    DiffuseAreaLight(const Transform& renderFromLight, Spectrum Lemit, Float scale,
                     const Shape* shape, bool twoSided, Image image = {},
                     const RGBColorSpace* imageColorSpace = nullptr,
                     const AlphaMask* alpha = nullptr);

    static constexpr LightType kType = LightType::Area;
    LightType Type() const { return invisible ? LightType::DeltaPosition : kType; }
    // Whether SampleLi leaves the radiance to DeferredL (Light::DeferredL)
    static constexpr bool kDefersL = false;
    const Shape& GetShape() const { return *shape; }
    Float Area() const { return area; }
    bool TwoSided() const { return twoSided; }

    // Radiance leaving point p (surface normal n, surface coordinates uv) in direction w.
    SampledSpectrum L(Point3f p, Normal3f n, Point2f uv, Vector3f w,
                      const SampledWavelengths& lambda) const;
    // The same at a surface interaction (Light::L; the BSDF plays no part), unpolarised.
    template <typename Radiance = SampledSpectrum>
    Radiance L(const SurfaceInteraction& si, const BSDF&, Vector3f w,
               const SampledWavelengths& lambda) const {
        return Radiance(L(si.p, si.n, si.uv, w, lambda));
    }
    // Samples a point on the shape by solid angle from ctx (the shape's sampling strategy).
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // A ray leaving a point uniform over the shape's area (u1; pdfPos per m^2) in a
    // cosine-distributed direction (u2; both sides if two-sided); nullopt where the shape is
    // cut out (pbrt-v4's DiffuseAreaLight::SampleLe).
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    // The densities of SampleLe leaving the point intr (on the shape, with its normal)
    // towards w.
    LightLePDF PDF_Le(const Interaction& intr, Vector3f w) const;
    // pi (2 if two-sided) A scale L (image: its mean), W nm^-1; 0 for a zero-area shape.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}

  private:
    const Shape* shape;
    const AlphaMask* alpha;  // nullptr for invisible lights
    bool invisible;
    Float area;
    bool twoSided;
    Spectrum Lemit;
    Float scale;
    Image image;
    const RGBColorSpace* imageColorSpace;
};

}  // namespace kiln
