// Scene-level set-up of thermal emission: which shapes are hot, at what temperature, with
// which emission model, and the ThermalAreaLights that make them glow.
//
// Scene syntax (kiln's additions to pbrt-v4's format; see README "Glowing objects"):
//   Material ... "float temperature" 1300 | "texture temperature" "heat"
//                "string emission" "kirchhoff" | "additive" | "diffuse" | "none"
//   Shape ...    "float temperature" 1450 | "texture temperature" "heat"  (the shape's wins)
//   Attribute "shape" "float temperature" 900   (applies to the shapes that follow)
// Temperatures are in kelvin. `kiln --emission MODEL` overrides every material's model.
#pragma once

#include <map>
#include <optional>

#include "core/base/object_arena.h"
#include "core/parser/diagnostics.h"
#include "core/parser/parameter_dictionary.h"
#include "materials/emissivity.h"
#include "materials/material.h"
#include "textures/texture.h"

namespace kiln {

// What a material or shape says about its heat.
struct ThermalParameters {
    std::optional<FloatTexture> temperature;  // kelvin
    std::optional<EmissionModel> model;
};

// Reads (and marks as used) "temperature" and "emission" from params. A per-vertex
// "float temperature" array on a triangle mesh is left to the mesh (returns no temperature).
ThermalParameters ReadThermalParameters(const ParameterDictionary& params,
                                        const NamedTextures& textures, bool isTriangleMesh,
                                        ObjectArena& arena);

// Per-material data shared by all the thermal lights of that material.
class ThermalMaterialCache {
  public:
    explicit ThermalMaterialCache(ObjectArena& arena) : arena(arena) {}
    // The reflectance table of a material when it is uniform and has no closed form
    // (rough conductors, coatings); nullptr otherwise.
    const ReflectanceTable* Table(const Material* material);
    // A black, non-reflecting material for the diffuse emission model (approach A).
    const Material* Black(Diagnostics& diag);

  private:
    ObjectArena& arena;
    std::map<const Material*, const ReflectanceTable*> tables;
    const Material* black = nullptr;
};

}  // namespace kiln
