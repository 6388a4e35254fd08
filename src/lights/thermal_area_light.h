// ThermalAreaLight: light sampling of a hot shape (for meshes, one triangle). The radiance it
// returns is the surface's own ThermalEmission (thermal/thermal_emission.h) evaluated with the
// full surface interaction at the sampled point (shading frame, uv, triangle) and the BSDF that
// the receiver's shader builds there exactly as at a ray hit (DeferredL), so a point emits the
// same radiance whether a path reaches it by light or by BSDF sampling. The light holds no
// shader: the integrator hands in its own with each evaluation.
//
// Where the emitted power varies over the shape (a temperature texture on a sphere, a heat map
// on a quad), points are sampled in proportion to it: a piecewise-constant distribution over
// the shape's parameterisation (Shape::SampleParametric), 32 x 32 cells (16 x 16 for a
// triangle) from the exitance at their centres. Otherwise the shape's own solid-angle sampling is
// used (spherical triangles, sphere cones). Triangles of meshes with more than
// kMaxDistributionTriangles triangles rely on per-triangle selection by power alone.
#pragma once

#include <functional>
#include <optional>

#include "base/rng.h"
#include "base/sampling.h"
#include "core/geometry/alpha_mask.h"
#include "lights/area_light_sampling.h"
#include "lights/light_sample.h"
#include "thermal/thermal_emission.h"

namespace kiln {

class Shape;
class Material;

class ThermalAreaLight {
  public:
    static constexpr int kMaxDistributionTriangles = 256;

    // Emission the same over the whole shape (uniform temperature and material): exitance
    // W m^-2 (ThermalEmission::BandExitance) and temperature K.
    struct Uniform {
        Float exitance, temperature;
    };
    // The BSDF at a surface point as the integrator builds it at a ray hit (render/scene.h's
    // SceneShader::GetBSDF): used at creation only, for the power estimate.
    using BSDFAt = std::function<BSDF(SurfaceInteraction&, SampledWavelengths&)>;
    // shape, material (the shape's) and emission must outlive the light. Estimates the light's
    // power from bsdfAt and, where it varies over the shape and powerSampling is set, builds
    // the sampling distribution; with `uniform` given, takes the caller's exitance instead.
    // alpha: the shape's cut-outs (nullptr: none), where sampled points emit nothing.
    ThermalAreaLight(const Shape* shape, const Material* material, const ThermalEmission* emission,
                     const BSDFAt& bsdfAt, std::optional<Uniform> uniform = std::nullopt,
                     bool powerSampling = true, const AlphaMask* alpha = nullptr);

    // Estimates the power and, where it varies over the shape and powerSampling was set,
    // builds the sampling distribution again from the emission as it is now (after its
    // temperature field moved to another frame: Scene::SetAnimation). Not for a light made
    // with `uniform`.
    void EstimatePower(const BSDFAt& bsdfAt);

    static constexpr LightType kType = LightType::Area;
    LightType Type() const { return kType; }
    // Whether SampleLi leaves the radiance to DeferredL (Light::DeferredL)
    static constexpr bool kDefersL = true;
    const ThermalEmission& Emission() const { return *emission; }
    const Shape& GetShape() const { return *shape; }
    Float Area() const { return area; }
    // Emission follows the BSDF on either side of the surface: bounds face both ways
    bool TwoSided() const { return true; }
    bool SamplesByPower() const { return distribution.has_value(); }

    // Radiance leaving si (on this light's shape) towards w; bsdf the BSDF at si.
    // Radiance: SampledSpectrum or Stokes (thermal_emission.h).
    template <typename Radiance = SampledSpectrum>
    Radiance L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
               const SampledWavelengths& lambda) const {
        return emission->L<Radiance>(si, bsdf, w, lambda);
    }
    // A point and its pdf, with the radiance left to DeferredL (ls.deferredL).
    std::optional<LightLiSample> SampleLi(const LightSampleContext& ctx, Point2f u,
                                          const SampledWavelengths& lambda,
                                          bool allowIncompletePDF = false) const;
    // The radiance of a sample of SampleLi towards its receiver, with the BSDF that shader
    // (any type with GetBSDF(SurfaceInteraction&, SampledWavelengths&), the integrator's)
    // builds at the sampled point (on a copy of the wavelengths: the receiving path keeps all
    // of its own). Nothing where the shape is cut out.
    template <typename Radiance = SampledSpectrum, typename Shader>
    Radiance DeferredL(const LightLiSample& ls, const SampledWavelengths& lambda,
                       const Shader& shader) const {
        Vector3f w = -ls.wi;
        SurfaceInteraction si = InteractionAt(ls.pLight.p, 0, w);
        // Cut out of the shape: nothing there to emit (rays never hit such points)
        if (alpha && alpha->Masked(si, HashToUniform(Hash(ls.pLight.p)))) return {};
        SampledWavelengths l = lambda;
        BSDF bsdf = shader.GetBSDF(si, l);
        return emission->L<Radiance>(si, bsdf, w, lambda);
    }
    Float PDF_Li(const LightSampleContext& ctx, Vector3f wi, bool allowIncompletePDF = false) const;
    // A ray leaving the hot body (pbrt-v4's DiffuseAreaLight::SampleLe): a point by power over
    // the parameterisation where SamplesByPower(), else uniform over the area (u1; pdfPos per
    // m^2), a cosine-distributed direction on either side (u2); L the surface's own emission
    // towards it, from the BSDF that shader builds there (as DeferredL). nullopt where the
    // shape is cut out or nothing is emitted.
    template <typename Shader>
    std::optional<LightLeSample> SampleLe(Point2f u1, Point2f u2, const SampledWavelengths& lambda,
                                          const Shader& shader) const {
        std::optional<ShapeSample> ss = SamplePosition(u1);
        if (!ss) return {};
        Float pdfDir = 0;
        Vector3f w = SampleEmissionDirection(ss->intr.n, TwoSided(), u2, &pdfDir);
        if (!(pdfDir > 0)) return {};
        SurfaceInteraction si = InteractionAt(ss->intr.p, 0, w);
        if (alpha && alpha->Masked(si, HashToUniform(Hash(ss->intr.p)))) return {};
        SampledWavelengths l = lambda;
        BSDF bsdf = shader.GetBSDF(si, l);
        SampledSpectrum Le = emission->L<SampledSpectrum>(si, bsdf, w, lambda);
        if (!Le) return {};
        return LightLeSample{Le, ss->intr.SpawnRay(w), ss->intr, ss->pdf, pdfDir};
    }
    // The densities of SampleLe leaving intr (a point of the shape, with its normal) towards w.
    LightLePDF PDF_Le(const Interaction& intr, Vector3f w) const;
    // Emitted power over the scene's wavelengths (ThermalEmission::Band), W (both sides), as
    // estimated at creation (or by the last EstimatePower).
    Float BandPower() const { return bandPower; }
    // Its power-weighted mean temperature, K, as estimated with the power.
    Float MeanTemperature() const { return meanTemperature; }
    // Spectral power, W nm^-1, for light selection: BandPower() distributed over wavelength
    // like a blackbody at the light's power-weighted mean temperature (an estimate: the
    // emissivity's spectral shape is not kept).
    SampledSpectrum Phi(const SampledWavelengths& lambda) const;
    void Preprocess(const Bounds3f&) const {}

  private:
    // The full interaction at a point of the shape, with the shape's material and emission.
    SurfaceInteraction InteractionAt(Point3f p, Float time, Vector3f wo) const;
    std::optional<Float> ParametricPDF(Point3f p) const;
    // A point of the shape with its density per m^2 (by power where SamplesByPower())
    std::optional<ShapeSample> SamplePosition(Point2f u) const;

    const Shape* shape;
    const AlphaMask* alpha = nullptr;
    const Material* material;
    const ThermalEmission* emission;
    Float area = 0;
    bool powerSampling = true;
    Float bandPower = 0, meanTemperature = 0;
    std::optional<PiecewiseConstant2D> distribution;
};

}  // namespace kiln
