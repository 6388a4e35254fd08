// How a medium glows.
//
// pbrt-v4's emission: "spectrum Le" times "Lescale" (per voxel in a "uniformgrid"), normalised
// by its luminance as lights are; or, for grid media, a "temperature" grid giving pbrt-v4's
// peak-normalised blackbody times "Lescale". Either is emitted per unit absorption: sigma_a Le.
//
// kiln's thermal emission (Kirchhoff inside matter): a medium at temperature T (kelvin: "float
// temperature", any float texture evaluated at render-space points, or a temperature grid with
// "string emission" given) emits per unit length as the thermal module's VolumeEmission says
// (thermal/volume_emission.h: sigma_a n^2 B(lambda, T) by default), n the refractive index of
// the dielectric bounding the medium (set by the scene), 1 otherwise.
#pragma once

#include <optional>

#include "media/medium_properties.h"
#include "media/sampled_grid.h"
#include "spectral/spectrum.h"
#include "textures/texture.h"
#include "thermal/emission_model.h"

namespace kiln {

class MediumEmission {
  public:
    MediumEmission() = default;  // emits nothing
    // pbrt-v4: Le (already divided by its luminance and times a constant Lescale), scaled per
    // point by LeScale when given.
    static MediumEmission Radiance(Spectrum Le, SampledGrid<Float> LeScale = {});
    // pbrt-v4's temperature grid: LeScale(p) (1 if empty) times LeFactor times the
    // peak-normalised blackbody at (T(p) - offset) * scale, nothing below 100 K, times
    // CIE_Y_integral: pbrt-v4's film weighs radiance by the colour matching functions without
    // dividing by the integral of y-bar (kiln's film divides, as SampledSpectrum::ToXYZ
    // does); its lights and "Le" are divided by their luminance, so they look alike in both,
    // but this blackbody is not, and looks CIE_Y_integral (106.9) times brighter in pbrt-v4.
    static MediumEmission NormalizedBlackbody(SampledGrid<Float> temperature, Float offset,
                                              Float scale, SampledGrid<Float> LeScale,
                                              Float LeFactor = 1);
    // kiln: thermal emission at a temperature from a texture (render-space points) or a grid
    // ((T - offset) * scale at points of the unit cube).
    static MediumEmission Thermal(FloatTexture temperature, EmissionModel model);
    static MediumEmission Thermal(SampledGrid<Float> temperature, Float offset, Float scale,
                                  EmissionModel model);

    bool IsEmissive() const { return kind != Kind::None; }
    bool IsThermal() const { return kind == Kind::Thermal; }
    // Whether Apply sets the same emission (and moves the same scattering to absorption) at
    // every point: no emission, Le without a per-voxel scale, or a constant temperature.
    bool IsUniform() const;
    // A temperature for the spectrum of thermal emission (K): a constant one, or the mean of a
    // grid's voxels weighted by their visible blackbody radiance; nullopt for other emission
    // and temperature textures that vary.
    std::optional<Float> RepresentativeTemperature() const;
    // The refractive index of the body the medium fills (thermal emission only).
    void SetRefractiveIndex(Spectrum eta) { this->eta = eta; }
    // Sets mp.emission (and for the "diffuse" model moves scattering to absorption) at the
    // render-space point pRender, pUnit in the unit cube of the medium's grid.
    void Apply(MediumProperties& mp, Point3f pRender, Point3f pUnit,
               const SampledWavelengths& lambda) const;

  private:
    enum class Kind { None, Radiance, NormalizedBlackbody, Thermal };
    Kind kind = Kind::None;
    std::optional<Spectrum> Le;
    std::optional<FloatTexture> temperatureTexture;
    SampledGrid<Float> temperatureGrid, LeScale;
    Float temperatureOffset = 0, temperatureScale = 1, LeFactor = 1;
    EmissionModel model = EmissionModel::Kirchhoff;
    std::optional<Spectrum> eta;
};

}  // namespace kiln
