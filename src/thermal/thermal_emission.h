// ThermalEmission: what makes a kiln surface glow because it is hot. A property of the surface
// (its temperature field, emission model and material), evaluated at any point with the BSDF
// the integrator scatters with there, through the thermal module's surface interface
// (surface_emission.h: models, Kirchhoff per polarisation state) with the material's albedo
// (material_albedo.h). The temperature is any float texture, in kelvin. Opaque surfaces emit
// on both sides, as their BSDFs reflect on both.
#pragma once

#include "base/interaction.h"
#include "materials/bxdfs/bsdf.h"
#include "spectral/polarization.h"
#include "spectral/spectral_range.h"
#include "textures/texture.h"
#include "thermal/emission_model.h"

namespace kiln {

class MaterialAlbedo;

class ThermalEmission {
  public:
    // temperature: kelvin; albedo: the material's (needed for kirchhoff, else may be null);
    // scale: times B (1: absolute units); band: the scene's wavelengths (BandExitance).
    ThermalEmission(FloatTexture temperature, EmissionModel model, const MaterialAlbedo* albedo,
                    Float scale = 1, SpectralRange band = {})
        : temperature(temperature), model(model), albedo(albedo), scale(scale), band(band) {}

    EmissionModel Model() const { return model; }
    // Whether the temperature texture uses the screen-space footprint.
    bool UsesFootprint() const { return temperature.UsesFootprint(); }
    const FloatTexture& TemperatureTexture() const { return temperature; }
    // Temperature at si, K (0 where the texture gives a negative or non-finite value).
    Float Temperature(const SurfaceInteraction& si) const;

    // Radiance leaving si towards w, W m^-2 sr^-1 nm^-1. bsdf: the BSDF at si, which
    // si.material built (the scene's GetBSDF); none (an interface) emits nothing.
    // Radiance: SampledSpectrum, or Stokes in the implicit frame of w (polarization.h).
    template <typename Radiance = SampledSpectrum>
    Radiance L(const SurfaceInteraction& si, const BSDF& bsdf, Vector3f w,
               const SampledWavelengths& lambda) const;
    // Radiant exitance at si over the band, both sides, W m^-2 (surface_emission.h's
    // BandExitance: for the power estimates light selection uses).
    Float BandExitance(const SurfaceInteraction& si, const BSDF& bsdf) const;
    const SpectralRange& Band() const { return band; }

  private:
    FloatTexture temperature;
    EmissionModel model;
    const MaterialAlbedo* albedo;
    Float scale;
    SpectralRange band;
};

}  // namespace kiln
