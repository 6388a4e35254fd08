// Scene creation step for participating media (pbrt-v4's BasicScene::CreateMedia): every
// named medium, identified afterwards by its index, with the refractive index of the
// dielectric bodies it fills (for thermal emission inside matter, media/medium_emission.h).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/interaction.h"
#include "materials/material.h"
#include "media/medium.h"
#include "render/scene_description.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

// Medium name -> index into the scene's media.
using MediumIndices = std::map<std::string, int>;

// Creates desc.media into media (SceneError for a missing "string type" or bad parameters).
// A medium inside shapes with a dielectric material (materialOf) gets that material's
// refractive index; media bounded by dielectrics of different indices keep the first and a
// warning says so.
MediumIndices CreateMedia(SceneDescription& desc, const NamedTextures& textures,
                          const std::function<const Material*(const ShapeSceneEntity&)>& materialOf,
                          std::optional<EmissionModel> modelOverride, std::vector<Medium>& media,
                          ObjectArena& arena, Diagnostics& diag);

// The index of the medium called name ("" gives -1); SceneError at loc if undefined.
int MediumIndex(const std::string& name, const MediumIndices& media, const FileLoc& loc);

// The media a shape separates.
inline MediumInterface ShapeMedia(const ShapeSceneEntity& s, const MediumIndices& media) {
    return MediumInterface(MediumIndex(s.insideMedium, media, s.loc),
                           MediumIndex(s.outsideMedium, media, s.loc));
}

}  // namespace kiln
