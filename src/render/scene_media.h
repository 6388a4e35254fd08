// Scene creation step for participating media (pbrt-v4's BasicScene::CreateMedia): every
// named medium, identified afterwards by its index, with the refractive index of the
// dielectric bodies it fills (for thermal emission inside matter, media/medium_emission.h).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/interaction.h"
#include "materials/material.h"
#include "media/medium.h"
#include "render/medium_emission_sampler.h"
#include "render/scene_description.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/thermal_properties.h"

namespace kiln {

// Medium name -> index into the scene's media.
using MediumIndices = std::map<std::string, int>;

// Creates desc.media into media (SceneError for a missing "string type" or bad parameters).
// A medium inside shapes with a dielectric material (materialOf) gets that material's
// refractive index; media bounded by dielectrics of different indices keep the first and a
// warning says so. With desc.ambientTemperature, a medium that gives no emission of its own
// (neither "temperature" nor "Le", nor a temperature grid in its file) is at that temperature
// ("float temperature" as a default below its parameters and attributes); a uniformgrid of one
// voxel is left out (one "temperature" value there is pbrt-v4's grid, not kelvin).
MediumIndices CreateMedia(SceneDescription& desc, const NamedTextures& textures,
                          const std::function<const Material*(const ShapeSceneEntity&)>& materialOf,
                          std::optional<EmissionModel> modelOverride, std::vector<Medium>& media,
                          ObjectArena& arena, Diagnostics& diag);

// Absorbing glass (a "dielectric" with "k", Material::InteriorExtinction) gives the bodies it
// bounds that have no medium of their own (no MediumInterface with two different media) an
// interior "homogeneous" medium: sigma_a = 4 pi k(lambda) / lambda per unit length, scene units
// taken as metres; no scattering; the body's refractive index; glowing at the shape's
// temperature, else its material's, else the scene's ambient one (a float texture evaluated at
// render-space points inside, as a medium's "temperature"; a mesh's per-vertex temperatures
// do not reach it), with the shape's, material's or command line's emission model. The media
// are added to media and indices under names starting with kAbsorbingGlassMediumPrefix, which
// the shapes' insideMedium then names; bodies of one material at one constant temperature (or
// without one) share one.
inline constexpr const char* kAbsorbingGlassMediumPrefix = "kiln:absorbing-glass:";
void CreateAbsorbingGlassMedia(
    SceneDescription& desc, const NamedTextures& textures,
    const std::function<const Material*(const ShapeSceneEntity&)>& materialOf,
    const std::function<const ThermalProperties&(const ShapeSceneEntity&)>& heatOf,
    std::optional<EmissionModel> modelOverride, std::vector<Medium>& media, MediumIndices& indices,
    ObjectArena& arena);

// The index of the medium called name ("" gives -1); SceneError at loc if undefined.
int MediumIndex(const std::string& name, const MediumIndices& media, const FileLoc& loc);

// The media a shape separates.
inline MediumInterface ShapeMedia(const ShapeSceneEntity& s, const MediumIndices& media) {
    return MediumInterface(MediumIndex(s.insideMedium, media, s.loc),
                           MediumIndex(s.outsideMedium, media, s.loc));
}

// One shape directive's part in bounding media: the media it separates, its render-space box
// and its material.
struct MediumBoundary {
    MediumInterface media;
    Bounds3f bounds;
    const Material* material = nullptr;
};

// Per medium: whether it is emissive and every shape touching it has a dielectric material
// (a melt in glass), so that shadow rays from outside cannot reach it.
std::vector<bool> GlowingInsideDielectrics(std::span<const Medium> media,
                                           std::span<const MediumBoundary> boundaries);

// Per medium: 1 where it is emissive and uniform (Medium::IsUniform), so that volpath
// integrates its emission along each ray segment exactly (Scene::exactEmissionMedia).
std::vector<char> ExactEmissionMedia(std::span<const Medium> media);

// The emissive media volpath samples as light sources (nullptr: none): each within its own
// box, or the box of the shapes it fills or surrounds (outside shapes only, a medium may reach
// further: emission there is still found by tracking), or both intersected. Not sampled: media
// no box bounds, and media whose every boundary is a dielectric (hot glass), since shadow rays
// do not pass dielectrics and volpath does not sample a medium from inside itself.
std::unique_ptr<MediumEmissionSampler> CreateMediumEmissionSampler(
    std::span<const Medium> media, std::span<const MediumBoundary> boundaries);

}  // namespace kiln
