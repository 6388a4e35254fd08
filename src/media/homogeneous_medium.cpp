#include "media/homogeneous_medium.h"

#include "spectral/cie.h"

namespace kiln {

HomogeneousMedium* HomogeneousMedium::Create(const TextureParameterDictionary& params,
                                             std::optional<EmissionModel> modelOverride,
                                             const FileLoc& loc, ObjectArena& arena,
                                             Diagnostics& diag) {
    MediumCoefficients c = ReadMediumCoefficients(params, loc, diag);
    CheckExtinction(c, 1, params, loc);
    MediumEmission emission;
    std::optional<MediumEmission> thermal = ReadMediumThermalEmission(params, modelOverride, arena);
    std::optional<Spectrum> Le = ReadMediumLe(params);
    Float LeScale = params.GetOneFloat("Lescale", 1);
    if (thermal && Le)
        throw SceneError(params.Loc("temperature"),
                         "a medium glows either by \"Le\" or by its \"temperature\", not both",
                         "temperature");
    if (thermal)
        emission = *thermal;
    else if (Le) {
        Spectrum normalized = NormalizedLe(*Le, LeScale);
        CheckMediumEmissionPeak(normalized.MaxValue(), params);
        emission = MediumEmission::Radiance(std::move(normalized));
    }
    return arena.New<HomogeneousMedium>(c, std::move(emission));
}

}  // namespace kiln
