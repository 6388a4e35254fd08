// Scene creation, thermal part: which shapes are hot, at what temperature and with which
// emission model; their ThermalEmission (thermal/thermal_emission.h) and, for shapes outside
// object instances, their ThermalAreaLights (one per shape; for meshes one per triangle).
//
// A shape is hot when its own parameters, an Attribute "shape", its material (a material
// property; a mix material without one takes its first hot component's) or a per-vertex
// "temperature" of its mesh give it a temperature (thermal/thermal_properties.h). The shape's
// own temperature and model win over its material's; `kiln --emission` overrides every model.
// The surface of a dielectric body without a temperature of its own that absorbs (rough, or
// opaque beyond its refraction cone) and emits by Kirchhoff's law takes its interior medium's
// "float temperature" where that medium is homogeneous: it emits what it loses at it. With
// Option "ambienttemperature", every other shape is hot at that temperature (the material's
// emission model). Shapes that cannot glow (area lights, interfaces, smooth dielectric surfaces)
// stay cold at these borrowed temperatures without the warnings their own would give.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/object_arena.h"
#include "core/geometry/shape.h"
#include "core/parser/diagnostics.h"
#include "lights/light.h"
#include "render/scene_description.h"
#include "thermal/material_albedo.h"
#include "thermal/thermal_emission.h"
#include "thermal/thermal_properties.h"

namespace kiln {

class SceneShader;
class ThermalAreaLight;

// What scene creation needs to know about one Shape directive's heat.
struct ShapeHeat {
    const ThermalEmission* emission = nullptr;  // nullptr: cold
    const Material* material = nullptr;         // the material to render it with
    bool ambient = false;                       // hot at the scene's ambient temperature
    bool interior = false;                      // hot at its interior medium's temperature
};

class ThermalEmitters {
  public:
    // powerSampling: sample points on shapes whose emission varies over them by power.
    // ambient: the temperature of shapes without one (K; Option "ambienttemperature").
    // mediumTemperatures: the constant temperatures of named media (K), which the absorbing
    // surfaces of dielectric bodies holding them take when they have none of their own.
    ThermalEmitters(const SceneShader& shader, EmissivityTables& tables, ObjectArena& arena,
                    Diagnostics& diag, std::optional<EmissionModel> overrideModel,
                    bool powerSampling = true, std::optional<Float> ambient = std::nullopt,
                    std::map<std::string, Float> mediumTemperatures = {});

    // The heat of one shape directive: own = its thermal parameters, fromMaterial = its
    // material's (scene creation resolves a mix's), material = its material, shapes = what it
    // created. A shape with an area light keeps the area light (warning).
    ShapeHeat Heat(const ShapeSceneEntity& entity, const ThermalProperties& own,
                   const ThermalProperties& fromMaterial, const Material* material,
                   std::span<const Shape> shapes, bool hasAreaLight);
    // One light per shape, appended to lights; returns their indices. alpha: the shapes'
    // cut-outs (nullptr: none).
    std::vector<int> CreateLights(std::span<const Shape> shapes, const ShapeHeat& heat,
                                  std::vector<Light>& lights, const AlphaMask* alpha = nullptr);
    // The lights made so far whose emission varies over their shape (their power was estimated
    // from the temperature field and material, which may change with the animation).
    const std::vector<ThermalAreaLight*>& VaryingLights() const { return varyingLights; }
    // Materials whose emissivity was tabulated, and the time that took (s).
    int TabulatedMaterials() const { return int(albedos.size()); }
    double TableSeconds() const { return tableSeconds; }

  private:
    const MaterialAlbedo* AlbedoOf(const Material* material, const FileLoc& loc);
    const Material* Black();

    const SceneShader& shader;
    EmissivityTables& tables;
    ObjectArena& arena;
    Diagnostics& diag;
    std::optional<EmissionModel> overrideModel;
    bool powerSampling;
    std::optional<FloatTexture> ambient;
    std::map<std::string, Float> mediumTemperatures;
    std::map<const Material*, const MaterialAlbedo*> albedos;
    const Material* black = nullptr;
    std::vector<ThermalAreaLight*> varyingLights;
    double tableSeconds = 0;
};

}  // namespace kiln
