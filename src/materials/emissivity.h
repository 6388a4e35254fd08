// Thermal emission models and emissivity (Wilkie & Weidlich 2011, "A Physically Plausible
// Model for Light Emission from Glowing Solid Objects").
//
// By Kirchhoff's law an opaque body in thermal equilibrium emits, in each direction and at each
// wavelength, exactly what it absorbs: emissivity(w, lambda) = 1 - R(w, lambda), where R is the
// directional-hemispherical reflectance of the body's own surface model. kiln computes R from
// the same BSDF it renders reflection with, so a closed isothermal cavity renders B(T)
// everywhere whatever its materials (the equilibrium test in test/lights).
//
// Transmissive materials (dielectric, thindielectric) are treated as non-absorbing: they emit
// nothing (kiln has no volumetric absorption). A glowing glass-like opaque body is written as
// coateddiffuse with a black base (the paper's black quartz).
//
// Rough conductors use pbrt-v4's single-scattering microfacet model. Its directional albedo
// misses the energy of multiply scattered light (for a perfect mirror metal about 12 % at
// alpha 0.3 and 69 % at alpha 1, normal incidence), so 1 - R over-estimates the physical
// emissivity by at most that loss; reflection and emission stay consistent, so equilibrium
// holds exactly. EmissivityTest.RoughConductorSingleScatteringLossIsAsDocumented guards this.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "materials/bxdfs/bsdf.h"
#include "materials/material.h"
#include "spectral/sampled_spectrum.h"

namespace kiln {

// How a hot surface emits (the paper's approaches A, B and C, plus none).
enum class EmissionModel {
    None,       // no thermal emission
    Diffuse,    // A: a diffuse blackbody B(lambda, T); the surface does not reflect
    Additive,   // B: B(lambda, T) added to the material's ordinary reflection
    Kirchhoff,  // C: B(lambda, T) (1 - R(w, lambda)) plus ordinary reflection (default)
};
std::optional<EmissionModel> ParseEmissionModel(std::string_view name);
std::string_view EmissionModelName(EmissionModel model);

// Directional-hemispherical reflectance R(wo) of a BSDF at the path's wavelengths
// (dimensionless, in [0, 1]); woRender in render space. Closed forms for diffuse and smooth
// conductors and coatings, a deterministic stratified estimate otherwise. For transmissive
// BSDFs returns 1 (they emit nothing).
SampledSpectrum HemisphericalReflectance(const BSDF& bsdf, Vector3f woRender, int sqrtSamples = 24);

// R(cos theta, lambda) tabulated once for a material whose parameters do not vary over the
// surface: 46 polar angles (2 degree steps) x 95 wavelengths (5 nm, 360-830 nm), bilinear
// interpolation.
class ReflectanceTable {
  public:
    // nullopt if the material varies over the surface (textured parameters) or is a mix.
    static std::optional<ReflectanceTable> Build(const Material& material);

    SampledSpectrum Reflectance(Float absCosTheta, const SampledWavelengths& lambda) const;
    // Hemispherical average 2 int R(mu) mu dmu at one wavelength (nm).
    Float HemisphericalAverage(Float lambda_nm) const;

    static constexpr int kThetaCount = 46, kLambdaCount = 95;
    static constexpr Float kLambdaMin = 360, kLambdaStep = 5;

  private:
    std::vector<float> values;  // [theta][lambda]
};

// Whether every texture of the material is a constant (so one BSDF serves the whole surface).
bool IsSpatiallyUniform(const Material& material);

// A BSDF of the material at a surface point for emission purposes (shading frame from n).
BSDF EmissionBSDF(const Material& material, Point3f p, Normal3f n, Point2f uv, Vector3f wo,
                  SampledWavelengths& lambda);

}  // namespace kiln
