// ThermalEmission: what makes a surface glow because it is hot. A property of the surface
// (its temperature field, emission model and material), evaluated at any point with the BSDF
// the integrator scatters with there:
//   kirchhoff (default): Le = B(lambda, T) (1 - A(wo, lambda)), A the directional albedo of
//                        that BSDF in its shading frame (thermal/material_albedo.h)
//   additive:            Le = B(lambda, T)  (the surface also reflects as usual)
//   diffuse:             Le = B(lambda, T)  (the surface is black: scene creation gives it a
//                        non-reflecting material)
// with B Planck's spectral radiance in W m^-2 sr^-1 nm^-1 (spectral/planck.h) times "scale"
// (1: absolute units). Opaque surfaces emit on both sides, as their BSDFs reflect on both.
// In polarised transport (Radiance = Stokes) kirchhoff emission is polarised as Kirchhoff's
// law per polarisation state requires (emissivity.h); additive and diffuse emission are
// unpolarised, as in the paper.
#pragma once

#include "base/interaction.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/polarization.h"
#include "textures/texture.h"
#include "thermal/emission_model.h"

namespace kiln {

class MaterialAlbedo;

class ThermalEmission {
  public:
    // temperature: kelvin; albedo: the material's (needed for kirchhoff, else may be null).
    ThermalEmission(FloatTexture temperature, EmissionModel model, const MaterialAlbedo* albedo,
                    Float scale = 1)
        : temperature(temperature), model(model), albedo(albedo), scale(scale) {}

    EmissionModel Model() const { return model; }
    // Whether the temperature texture uses the screen-space footprint.
    bool UsesFootprint() const { return temperature.UsesFootprint(); }
    const FloatTexture& TemperatureTexture() const { return temperature; }
    // Temperature at si, K (0 where the texture gives a negative or non-finite value).
    Float Temperature(const SurfaceInteraction& si) const;

    // Radiance leaving si towards w, W m^-2 sr^-1 nm^-1. bsdf: the BSDF at si, which
    // si.material built (SurfaceShader::GetBSDF); none (an interface) emits nothing.
    // Radiance: SampledSpectrum, or Stokes in the implicit frame of w (polarization.h).
    template <typename Radiance = SampledSpectrum>
    Radiance L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
               const SampledWavelengths& lambda) const;
    // Radiant exitance at si over 360-830 nm, both sides, W m^-2: 2 pi integral of
    // B(lambda, T) times the hemispherical emissivity, by an 8-point midpoint rule in
    // wavelength (for the power estimates light selection uses).
    Float VisibleExitance(const SurfaceInteraction& si, const BSDF& bsdf) const;

  private:
    FloatTexture temperature;
    EmissionModel model;
    const MaterialAlbedo* albedo;
    Float scale;
};

}  // namespace kiln
