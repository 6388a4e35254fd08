// Parameters every pbrt-v4 medium shares: sigma_a, sigma_s (or a measured "preset"), "scale"
// and the Henyey-Greenstein "g"; and kiln's heat ("temperature", "emission").
#pragma once

#include <array>
#include <optional>
#include <string>

#include "base/object_arena.h"
#include "media/medium_emission.h"
#include "spectral/spectrum.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/emission_model.h"

namespace kiln {

struct MediumCoefficients {
    // Per unit length of render space; "scale" multiplies both.
    Spectrum sigma_a = ConstantSpectrum(1), sigma_s = ConstantSpectrum(1);
    Float scale = 1;
    Float g = 0;
};

// The measured scattering coefficients of a named material, mm^-1 (sigma_a, sigma_s); nullopt
// if unknown. Sources in medium_parameters.cpp.
std::optional<std::pair<Spectrum, Spectrum>> MediumPreset(const std::string& name);

// "preset" (a warning if unknown, as pbrt-v4), else "spectrum sigma_a" / "sigma_s" (default 1),
// "float scale" (default 1), "float g" in (-1, 1) (default 0).
MediumCoefficients ReadMediumCoefficients(const TextureParameterDictionary& params,
                                          const FileLoc& loc, Diagnostics& diag);

// The largest extinction a medium may have, per unit length of render space: beyond it, or not
// a number, tracking's ratios of majorants overflow single precision. CheckExtinction: a
// SceneError at "scale" (or the density or coefficients, whichever is given) when the largest
// sigma_a + sigma_s times "scale" times densityMax exceeds it.
inline constexpr double kMaxExtinction = 1e30;
void CheckExtinction(double sigmaMax, const TextureParameterDictionary& params, const FileLoc& loc);
void CheckExtinction(const MediumCoefficients& c, double densityMax,
                     const TextureParameterDictionary& params, const FileLoc& loc);

// "float g" in (-1, 1), default 0.
Float ReadHGAsymmetry(const TextureParameterDictionary& params);
// "float scale", finite and >= 0, default 1.
Float ReadCoefficientScale(const TextureParameterDictionary& params, const FileLoc& loc);
// A grid medium's box [p0, p1] (default the unit cube), positive on every axis.
Bounds3f ReadGridBounds(const TextureParameterDictionary& params, const FileLoc& loc);
// "nx", "ny", "nz" (default 1), which n values given for what must fill.
std::array<int, 3> ReadGridResolution(const TextureParameterDictionary& params, size_t n,
                                      const std::string& what, const FileLoc& loc);

// pbrt-v4's "spectrum Le" (an illuminant), nullopt when absent or zero.
std::optional<Spectrum> ReadMediumLe(const TextureParameterDictionary& params);
// Le divided by its luminance (as lights are, lights/light.h), times scale.
Spectrum NormalizedLe(const Spectrum& Le, Float scale);
// A medium's brightest emitted radiance (its Le, normalised and scaled): above kMaxEmission
// (spectral/planck.h), or not a number, a SceneError at "Lescale" (or "Le" without one).
void CheckMediumEmissionPeak(double peak, const TextureParameterDictionary& params);

// kiln's thermal emission of a medium with a constant or textured "temperature"; none when
// the medium has no such parameter. modelOverride: the command line's --emission.
std::optional<MediumEmission> ReadMediumThermalEmission(const TextureParameterDictionary& params,
                                                        std::optional<EmissionModel> modelOverride,
                                                        ObjectArena& arena);

}  // namespace kiln
