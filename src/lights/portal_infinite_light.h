// An environment light seen only through a portal (pbrt-v4's PortalImageInfiniteLight, after
// Bitterli et al. 2015, "Portal-Masked Environment Map Sampling"): a rectangle, typically a
// window, through which all of the environment's light enters the scene. Its radiance is
// stored over the portal's rectified parameterisation, uv = ((atan(x/z) + pi/2) / pi,
// (atan(y/z) + pi/2) / pi) in the portal's frame (x, y along its edges, z its normal), where
// the portal seen from any point is an axis-aligned rectangle: light samples are drawn inside
// that rectangle only. As in pbrt-v4, a ray escaping the scene receives the environment's
// radiance only if it passes through the portal rectangle; all other escaping rays get none.
//
// Units: radiance in W m^-2 sr^-1 nm^-1; pdfs per steradian.
#pragma once

#include <array>
#include <optional>

#include "base/transform.h"
#include "base/windowed_distribution.h"
#include "core/image/image.h"
#include "lights/light_sample.h"

namespace kiln {

class RGBColorSpace;

class PortalInfiniteLight {
  public:
    // equalAreaImage: a square equal-area octahedral map (R, G, B in colorSpace), resampled
    // onto the portal's parameterisation at its own resolution as pbrt-v4 does; portal: the
    // rectangle's four corners in render space, in order around it. Throws
    // std::invalid_argument for a non-square image or a degenerate portal.
    PortalInfiniteLight(const Transform& renderFromLight, const Image& equalAreaImage,
                        const RGBColorSpace* colorSpace, Float scale,
                        const std::array<Point3f, 4>& portal);

    static constexpr LightType kType = LightType::Infinite;
    LightType Type() const { return kType; }

    // Radiance along ray if it leaves through the portal (seen from ray.o), else 0.
    SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const;
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // A ray entering the scene (light tracing, as pbrt-v4): a direction from the whole
    // parameterisation, its origin on the disk of the scene's bounding sphere facing it.
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2,
                                          const SampledWavelengths& lambda) const;
    LightLePDF PDF_Le(const Ray& ray) const;
    // The flux entering through the portal, W nm^-1: its area times the radiance integrated
    // over the projected solid angle of the directions through it (for the "power" light
    // sampler; pbrt-v4 divides by the Jacobian here where it should multiply).
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f& sceneBounds) const;

    // Portal parameterisation: uv of a render-space direction (nullopt behind the portal),
    // and the direction of uv; dw_duv is the Jacobian, steradians per unit uv area (pbrt-v4's
    // "duv_dw": pi^2 (1 - x^2) (1 - y^2) / z for the local unit direction (x, y, z), computed
    // as pi^2 (y^2 + z^2) (x^2 + z^2) / z, which keeps grazing directions' Jacobian positive).
    std::optional<Point2f> ImageFromRender(Vector3f wRender, Float* dw_duv = nullptr) const;
    Vector3f RenderFromImage(Point2f uv, Float* dw_duv = nullptr) const;
    // The portal seen from p, as a rectangle of uv (nullopt when p is behind the portal).
    std::optional<Bounds2f> ImageBounds(Point3f p) const;

  private:
    SampledSpectrum ImageLookup(Point2f uv, const SampledWavelengths& lambda) const;

    std::array<Point3f, 4> portal;
    Frame portalFrame;
    Image image;  // R, G, B over the portal parameterisation
    const RGBColorSpace* colorSpace;
    Float scale;
    WindowedPiecewiseConstant2D distribution;
    mutable Point3f sceneCenter;
    mutable Float sceneRadius = 0;
};

}  // namespace kiln
