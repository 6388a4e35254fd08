#include "media/medium_parameters.h"

#include <cmath>
#include <string_view>

#include "core/parser/diagnostics.h"
#include "spectral/cie.h"
#include "spectral/color.h"
#include "spectral/measured_media.h"
#include "spectral/planck.h"
#include "thermal/thermal_properties.h"

namespace kiln {

std::optional<std::pair<Spectrum, Spectrum>> MediumPreset(const std::string& name) {
    return MeasuredMediumCoefficients(name);
}

MediumCoefficients ReadMediumCoefficients(const TextureParameterDictionary& params,
                                          const FileLoc& loc, Diagnostics& diag) {
    MediumCoefficients c;
    std::optional<std::pair<Spectrum, Spectrum>> preset;
    std::string presetName = params.GetOneString("preset", "");
    if (!presetName.empty()) {
        preset = MediumPreset(presetName);
        if (!preset)
            diag.Warn(params.Loc("preset"), "medium preset \"" + presetName + "\" not found");
    }
    const ParameterDictionary& dict = params.Dict();
    if (preset) {
        c.sigma_a = preset->first;
        c.sigma_s = preset->second;
    } else {
        c.sigma_a = *dict.GetOneSpectrum("sigma_a", ConstantSpectrum(1), SpectrumType::Unbounded);
        c.sigma_s = *dict.GetOneSpectrum("sigma_s", ConstantSpectrum(1), SpectrumType::Unbounded);
    }
    // Tabulated per nanometre (as pbrt-v4): sampled at every tentative collision, an RGB
    // spectrum's sigmoid would cost more than the lookup
    c.sigma_a = DenselySampledSpectrum(c.sigma_a);
    c.sigma_s = DenselySampledSpectrum(c.sigma_s);
    c.scale = ReadCoefficientScale(params, loc);
    c.g = ReadHGAsymmetry(params);
    return c;
}

void CheckExtinction(double sigmaMax, const TextureParameterDictionary& params,
                     const FileLoc& loc) {
    if (sigmaMax <= kMaxExtinction) return;
    std::string name = "scale";
    for (const char* n : {"scale", "density", "sigma_s", "sigma_a", "preset"})
        if (params.Has(n)) {
            name = n;
            break;
        }
    char value[32] = "not a finite number";
    if (std::isfinite(sigmaMax)) std::snprintf(value, sizeof(value), "%g", sigmaMax);
    throw SceneError(params.Loc(name, loc),
                     std::string("this medium's extinction (sigma_a + sigma_s, times \"scale\" "
                                 "and its density) reaches ") +
                         value +
                         " per unit length, beyond the 1e30 that kiln tracks in single "
                         "precision",
                     name);
}

void CheckExtinction(const MediumCoefficients& c, double densityMax,
                     const TextureParameterDictionary& params, const FileLoc& loc) {
    CheckExtinction((double(c.sigma_a.MaxValue()) + double(c.sigma_s.MaxValue())) *
                        double(c.scale) * densityMax,
                    params, loc);
}

Float ReadHGAsymmetry(const TextureParameterDictionary& params) {
    Float g = params.GetOneFloat("g", 0);
    if (!(std::abs(g) < 1))
        throw SceneError(params.Loc("g"), "Henyey-Greenstein \"g\" must be in (-1, 1)",
                         std::to_string(g));
    return g;
}

Float ReadCoefficientScale(const TextureParameterDictionary& params, const FileLoc& loc) {
    Float scale = params.GetOneFloat("scale", 1);
    if (!(scale >= 0) || !std::isfinite(scale))
        throw SceneError(params.Loc("scale", loc), "medium \"scale\" must be a finite number >= 0",
                         std::to_string(scale));
    return scale;
}

Bounds3f ReadGridBounds(const TextureParameterDictionary& params, const FileLoc& loc) {
    Bounds3f bounds(params.GetOnePoint3f("p0", Point3f(0, 0, 0)),
                    params.GetOnePoint3f("p1", Point3f(1, 1, 1)));
    Vector3f d = bounds.Diagonal();
    if (!(d.x > 0 && d.y > 0 && d.z > 0) || !std::isfinite(d.x + d.y + d.z))
        throw SceneError(params.Has("p0") ? params.Loc("p0") : loc,
                         "grid medium bounds p0 - p1 must have a finite, positive extent on "
                         "every axis",
                         "p0");
    return bounds;
}

std::array<int, 3> ReadGridResolution(const TextureParameterDictionary& params, size_t n,
                                      const std::string& what, const FileLoc& loc) {
    std::array<int, 3> res = {params.GetOneInt("nx", 1), params.GetOneInt("ny", 1),
                              params.GetOneInt("nz", 1)};
    // In double: the product of three ints can overflow size_t, not a double's exact range
    // for any n that fits in memory
    bool valid = res[0] >= 1 && res[1] >= 1 && res[2] >= 1 &&
                 double(n) == double(res[0]) * double(res[1]) * double(res[2]);
    if (!valid)
        throw SceneError(params.Loc("nx", loc),
                         "grid medium has " + std::to_string(n) + " " + what +
                             " values; expected nx*ny*nz = " + std::to_string(res[0]) + "*" +
                             std::to_string(res[1]) + "*" + std::to_string(res[2]),
                         what);
    return res;
}

std::optional<Spectrum> ReadMediumLe(const TextureParameterDictionary& params) {
    std::optional<Spectrum> Le =
        params.Dict().GetOneSpectrum("Le", std::nullopt, SpectrumType::Illuminant);
    if (!Le || Le->MaxValue() == 0) return std::nullopt;
    return Le;
}

Spectrum NormalizedLe(const Spectrum& Le, Float scale) {
    DenselySampledSpectrum d(Le);
    d.Scale(scale / (SpectrumToPhotometric(Le) / CIE_Y_integral));
    return d;
}

void CheckMediumEmissionPeak(double peak, const TextureParameterDictionary& params) {
    if (peak <= kMaxEmission) return;
    const char* name = params.Has("Lescale") ? "Lescale" : "Le";
    char value[32] = "not a finite number";
    if (std::isfinite(peak)) std::snprintf(value, sizeof(value), "%g", peak);
    throw SceneError(params.Loc(name),
                     std::string("this medium's emission is too bright: its radiance (\"Le\" "
                                 "or pbrt-v4's blackbody, times \"Lescale\") reaches ") +
                         value +
                         ", beyond the 1e30 W m^-2 sr^-1 nm^-1 that kiln renders in single "
                         "precision",
                     name);
}

std::optional<MediumEmission> ReadMediumThermalEmission(const TextureParameterDictionary& params,
                                                        std::optional<EmissionModel> modelOverride,
                                                        ObjectArena& arena) {
    ThermalProperties t = ReadThermalProperties(params, false, arena);
    if (!t.temperature) return std::nullopt;
    EmissionModel model =
        modelOverride ? *modelOverride : t.model.value_or(EmissionModel::Kirchhoff);
    return MediumEmission::Thermal(*t.temperature, model);
}

}  // namespace kiln
