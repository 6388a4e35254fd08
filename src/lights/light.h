// Light: the closed set of light sources behind one small value type (pbrt-v4's Light, with
// std::variant of pointers in place of its TaggedPointer). Light objects live in the scene's
// ObjectArena; a Light is a pointer-sized handle that may be copied freely.
//
// Units: radiance L, Le and LightLiSample::L in W m^-2 sr^-1 nm^-1, intensity in
// W sr^-1 nm^-1, power Phi in W nm^-1, all at each of the sampled wavelengths.
//
// Photometric normalisation (as pbrt-v4): every emission spectrum given in a scene is divided
// by its luminance so that "scale" sets the luminance. kiln's film reports
// Y = integral(L ybar) / integral(ybar) (docs/architecture.md), so luminance here is
// SpectrumToPhotometric(s) / CIE_Y_integral: an "rgb L [1 1 1]" light keeps the colour
// space's illuminant unchanged and renders with Y = scale, exactly as pbrt-v4 renders it.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <variant>

#include "base/closed_set.h"
#include "base/object_arena.h"
#include "base/transform.h"
#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/image_infinite_light.h"
#include "lights/light_bounds.h"
#include "lights/light_sample.h"
#include "lights/point_light.h"
#include "lights/portal_infinite_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"
#include "lights/thermal_area_light.h"
#include "lights/uniform_infinite_light.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/spectral_range.h"

// ThermalAreaLight is in the closed set unless thermal emission is compiled out (CMake option
// KILN_THERMAL_EMISSION, only for overhead measurements).
#if KILN_THERMAL_EMISSION
#define KILN_THERMAL_LIGHT_KIND const ThermalAreaLight*,
#else
#define KILN_THERMAL_LIGHT_KIND
#endif

namespace kiln {

class AlphaMask;

class ParameterDictionary;
class Shape;
class Diagnostics;
struct FileLoc;

// The closed set: add a kind here (and its header above) to add a light type.
class Light : public ClosedSet<const PointLight*, const SpotLight*, const GoniometricLight*,
                               const ProjectionLight*, const DistantLight*, const DiffuseAreaLight*,
                               KILN_THERMAL_LIGHT_KIND const UniformInfiniteLight*,
                               const ImageInfiniteLight*, const PortalInfiniteLight*> {
  public:
    using ClosedSet::ClosedSet;

    LightType Type() const {
        return Dispatch([](auto l) { return l->Type(); });
    }
    // Whether light sampling with an incomplete PDF (allowIncompletePDF, as path and volpath
    // sample lights for MIS with BSDF sampling) draws nothing from this light: a uniform
    // environment, whose light BSDF sampling finds as well as any light sample would.
    bool CoveredByBSDFSampling() const {
        return Dispatch([](auto l) {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            return std::is_same_v<T, UniformInfiniteLight>;
        });
    }
    // Whether SampleLi may return samples with wiLength != 1 (pbrt-v4 compatibility for image
    // infinite lights under transforms that change lengths: LightLiSample::wiLength).
    bool HasUnnormalizedSamples() const {
        return Dispatch([](auto l) {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (std::is_same_v<T, ImageInfiniteLight>)
                return !l->PreservesLengths();
            else
                return false;
        });
    }
    // Emitted power, W nm^-1 at each wavelength. Infinite and distant lights need Preprocess.
    SampledSpectrum Phi(const SampledWavelengths& lambda) const {
        return Dispatch([&](auto l) { return l->Phi(lambda); });
    }
    // Incident radiance at ctx.p from a direction sampled by solid angle (pdf per sr; 1 for
    // delta lights); nullopt if no light arrives or the sample is invalid. A light whose
    // radiance at the sampled point costs a surface evaluation (thermal emission: interaction,
    // BSDF, emissivity) leaves L to DeferredL (ls.deferredL), so that the receiver evaluates
    // it only for samples it can use (non-zero BSDF, unoccluded).
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const {
        return Dispatch([&](auto l) { return l->SampleLi(ctx, u, lambda, allowIncompletePDF); });
    }
    // The radiance of a sample of SampleLi: its L unless deferred, else evaluated with the BSDF
    // that shader (the integrator's: GetBSDF(SurfaceInteraction&, SampledWavelengths&)) builds
    // at the sampled point. Radiance: SampledSpectrum, or Stokes in the implicit frame of
    // -ls.wi (polarization.h; only thermal emission is polarised).
    template <typename Radiance = SampledSpectrum, typename Shader>
    Radiance DeferredL(const LightLiSample& ls, const SampledWavelengths& lambda,
                       const Shader& shader) const {
        if (!ls.deferredL) return Radiance(ls.L);
        return Dispatch([&](auto l) -> Radiance {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (T::kType == LightType::Area) {
                if constexpr (T::kDefersL)
                    return l->template DeferredL<Radiance>(ls, lambda, shader);
            }
            return Radiance(ls.L);  // a light that does not defer never sets ls.deferredL
        });
    }
    // Density per sr with which SampleLi would pick wi (0 for delta lights).
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi,
                 bool allowIncompletePDF = false) const {
        return Dispatch([&](auto l) { return l->PDF_Li(ctx, wi, allowIncompletePDF); });
    }
    // Area lights: radiance leaving si, a point of the light's shape, towards w; bsdf is the
    // BSDF at si (thermal emission derives from it). 0 for the other kinds. What each light
    // class provides follows from its kType (and kDefersL for area lights): an area light
    // without L, GetShape, Area and TwoSided, or an infinite one without Le, does not compile.
    // Radiance as for DeferredL, in the implicit frame of w.
    template <typename Radiance = SampledSpectrum>
    Radiance L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
               const SampledWavelengths& lambda) const {
        return Dispatch([&](auto l) -> Radiance {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (T::kType == LightType::Area)
                return l->template L<Radiance>(si, bsdf, w, lambda);
            else
                return {};
        });
    }
    // Infinite lights: radiance arriving along a ray that leaves the scene. 0 for the others.
    SampledSpectrum Le(const Ray& ray, const SampledWavelengths& lambda) const {
        return Dispatch([&](auto l) -> SampledSpectrum {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (T::kType == LightType::Infinite)
                return l->Le(ray, lambda);
            else
                return SampledSpectrum(0.f);
        });
    }
    // A ray leaving the light (pbrt-v4's Light::SampleLe, for light tracing), from u1 and u2;
    // lights whose radiance costs a surface evaluation (thermal emission) evaluate it with
    // the BSDF that shader builds at the sampled point, as DeferredL.
    template <typename Shader>
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2, const SampledWavelengths& lambda,
                                          const Shader& shader) const {
        return Dispatch([&](auto l) -> std::optional<LightLeSample> {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            constexpr bool withShader = [] {
                if constexpr (T::kType == LightType::Area)
                    return T::kDefersL;
                else
                    return false;
            }();
            if constexpr (withShader)
                return l->SampleLe(u1, u2, lambda, shader);
            else
                return l->SampleLe(u1, u2, lambda);
        });
    }
    // Densities of SampleLe producing `ray`, for lights without a surface (point, spot,
    // distant, infinite); {0, 0} for area lights.
    LightLePDF PDF_Le(const Ray& ray) const {
        return Dispatch([&](auto l) -> LightLePDF {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (T::kType == LightType::Area)
                return {};
            else
                return l->PDF_Le(ray);
        });
    }
    // Densities of SampleLe leaving intr (a point of an area light's shape, with its surface
    // normal) towards w; {0, 0} for the other kinds.
    LightLePDF PDF_Le(const Interaction& intr, Vector3f w) const {
        return Dispatch([&](auto l) -> LightLePDF {
            using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
            if constexpr (T::kType == LightType::Area)
                return l->PDF_Le(intr, w);
            else
                return {};
        });
    }
    // The light's weight for light selection: its power over the scene's wavelengths, W (pbrt-v4:
    // Phi / pdf averaged over the four wavelengths SampleVisible(0.5) gives; beyond the visible,
    // SpectralRange::Spread(0.5)); 0 if not finite.
    Float Power(const SpectralRange& range = {}) const;
    // What a hot surface radiates, for the film's choice of wavelengths
    // (spectral/wavelength_distribution.h): nullopt for lights other than thermal ones.
    struct ThermalOutput {
        Float temperature;  // K, the power-weighted mean over the surface
        Float bandPower;    // W over the scene's wavelengths (SpectralRange)
    };
    std::optional<ThermalOutput> Thermal() const;
    // Spatial and directional bounds of the emission (lights at infinity: none), with phi =
    // Power().
    std::optional<LightBounds> Bounds(const SpectralRange& range = {}) const;
    // Tells distant and infinite lights the scene's extent (call before Phi and SampleLi).
    void Preprocess(const Bounds3f& sceneBounds) const {
        Dispatch([&](auto l) { l->Preprocess(sceneBounds); });
    }

    // Light "name" (pbrt-v4): "point" (I, scale, power, from), "spot" (I, scale, power, from,
    // to, coneangle, conedeltaangle), "goniometric" (I, scale, power, filename), "projection"
    // (scale, power, fov, filename), "distant" (L, scale, from, to, illuminance), "infinite"
    // (L or filename, scale, illuminance, portal: four corners in world space, which
    // renderFromWorld takes to render space). A goniometric light without "filename" is warned
    // about and gives nullopt (it emits nothing); other names throw SceneError.
    static std::optional<Light> Create(const std::string& name, const ParameterDictionary& params,
                                       const Transform& renderFromLight, const FileLoc& loc,
                                       ObjectArena& arena, Diagnostics& diag,
                                       const Transform& renderFromWorld = Transform());
    // AreaLightSource "diffuse" (L, scale, power, twosided, filename) on `shape`; other names
    // throw SceneError. (Thermal lights are made by scene creation: render/scene_lights.h.)
    // alpha: the shape's cut-outs (nullptr: none), skipped by light sampling.
    static Light CreateArea(const std::string& name, const ParameterDictionary& params,
                            const Transform& renderFromLight, const Shape& shape,
                            const FileLoc& loc, ObjectArena& arena, Diagnostics& diag,
                            const AlphaMask* alpha = nullptr);
};

// Luminance Y of an emission spectrum in kiln's convention (SpectrumToPhotometric /
// CIE_Y_integral; for RGBIlluminantSpectrum that of its illuminant, as pbrt-v4), the value
// pbrt-v4's light creation divides by.
Float EmissionLuminance(const Spectrum& s);

}  // namespace kiln
