#include "render/thermal_emitters.h"

#include "materials/bxdfs/bxdf.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"

namespace kiln {

ThermalParameters ReadThermalParameters(const ParameterDictionary& params,
                                        const NamedTextures& textures, bool isTriangleMesh,
                                        ObjectArena& arena) {
    ThermalParameters t;
    std::string type = params.TypeOf("temperature");
    if (type == "float") {
        std::vector<Float> values = params.GetFloatArray("temperature");
        if (values.size() > 1 && isTriangleMesh) {
            // One value per vertex: the mesh keeps them (see geometry/triangle.h).
        } else if (values.size() == 1) {
            if (values[0] < 0 || !std::isfinite(values[0]))
                throw SceneError(params.Loc("temperature"),
                                 "temperature must be a finite, non-negative number of kelvin",
                                 std::to_string(values[0]));
            t.temperature = FloatTexture(arena.New<FloatConstantTexture>(values[0]));
        } else {
            throw SceneError(params.Loc("temperature"),
                             "\"float temperature\" takes one value (kelvin)", "temperature");
        }
    } else if (type == "texture") {
        TextureParameterDictionary tp(&params, &textures);
        t.temperature = tp.GetFloatTextureOrNull("temperature", arena);
    } else if (!type.empty()) {
        throw SceneError(params.Loc("temperature"),
                         "temperature must be a \"float\" or a \"texture\"", type);
    }
    if (params.Has("emission")) {
        std::string name = params.GetOneString("emission", "kirchhoff");
        t.model = ParseEmissionModel(name);
        if (!t.model)
            throw SceneError(params.Loc("emission"),
                             "unknown emission model (expected kirchhoff, additive, diffuse or "
                             "none)",
                             name);
    }
    return t;
}

const ReflectanceTable* ThermalMaterialCache::Table(const Material* material) {
    auto it = tables.find(material);
    if (it != tables.end()) return it->second;
    const ReflectanceTable* table = nullptr;
    if (material && IsSpatiallyUniform(*material)) {
        // Closed forms need no table: diffuse, smooth conductors, transmissive materials.
        SampledWavelengths lambda = SampledWavelengths::FromWavelength(550);
        BSDF bsdf = EmissionBSDF(*material, Point3f(0, 0, 0), Normal3f(0, 0, 1),
                                 Point2f(0.5f, 0.5f), Vector3f(0, 0, 1), lambda);
        bool closedForm = !bsdf || IsTransmissive(bsdf.Flags()) ||
                          bsdf.GetBxDF().Is<DiffuseBxDF>() ||
                          (bsdf.GetBxDF().Is<ConductorBxDF>() && IsSpecular(bsdf.Flags()));
        if (!closedForm) {
            std::optional<ReflectanceTable> t = ReflectanceTable::Build(*material);
            if (t) table = arena.New<ReflectanceTable>(std::move(*t));
        }
    }
    tables[material] = table;
    return table;
}

const Material* ThermalMaterialCache::Black(Diagnostics& diag) {
    if (black) return black;
    ParsedParameter p;
    p.type = "rgb";
    p.name = "reflectance";
    p.floats = {0, 0, 0};
    ParameterDictionary dict({p}, nullptr);
    NamedTextures none;
    TextureParameterDictionary tp(&dict, &none);
    black = arena.New<Material>(Material::Create("diffuse", tp, {}, FileLoc(), arena, diag));
    return black;
}

}  // namespace kiln
