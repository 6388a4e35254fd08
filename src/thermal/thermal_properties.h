// What a material or a shape says about its heat (kiln's additions to pbrt-v4's format; see
// docs/guide/glowing-objects.md):
//   "float temperature" T | "texture temperature" "name"   kelvin, any float texture
//   "string emission" "kirchhoff" | "additive" | "diffuse" | "none"
// A material's parameters give it a temperature and model (a hot material; scene creation reads
// them, render/scene_create.cpp, the Material does not keep them); a shape's own values
// override its material's, and an Attribute "shape" temperature applies to the shapes that
// follow.
#pragma once

#include <optional>

#include "base/object_arena.h"
#include "textures/texture.h"
#include "thermal/emission_model.h"

namespace kiln {

class TextureParameterDictionary;

struct ThermalProperties {
    std::optional<FloatTexture> temperature;  // kelvin
    std::optional<EmissionModel> model;
};

// Reads (and marks as used) "temperature" and "emission"; SceneError for malformed values. A
// "float temperature" array with one value per vertex is left to a triangle mesh when
// perVertexAllowed (it returns no temperature).
ThermalProperties ReadThermalProperties(const TextureParameterDictionary& params,
                                        bool perVertexAllowed, ObjectArena& arena);

}  // namespace kiln
