#include "render/scene_emitters.h"

#include <tbb/parallel_for.h>

#include <chrono>

#include "core/geometry/triangle.h"
#include "lights/thermal_area_light.h"
#include "materials/materials.h"
#include "render/scene.h"
#include "textures/basic_textures.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/spatial_temperature_fields.h"

namespace kiln {

ThermalEmitters::ThermalEmitters(const SceneShader& shader, EmissivityTables& tables,
                                 ObjectArena& arena, Diagnostics& diag,
                                 std::optional<EmissionModel> overrideModel, bool powerSampling,
                                 std::optional<Float> ambientTemperature,
                                 std::map<std::string, Float> mediumTemperatures)
    : shader(shader),
      tables(tables),
      arena(arena),
      diag(diag),
      overrideModel(overrideModel),
      powerSampling(powerSampling),
      mediumTemperatures(std::move(mediumTemperatures)) {
    if (ambientTemperature)
        ambient = FloatTexture(arena.New<FloatConstantTexture>(*ambientTemperature));
}

ShapeHeat ThermalEmitters::Heat(const ShapeSceneEntity& entity, const ThermalProperties& own,
                                const ThermalProperties& fromMaterial, const Material* material,
                                std::span<const Shape> shapes, bool hasAreaLight) {
    ShapeHeat heat;
    heat.material = material;
    std::optional<FloatTexture> temperature =
        own.temperature ? own.temperature : fromMaterial.temperature;
    // Per-vertex temperatures of a mesh (PLY vertex property or one value per vertex)
    if (!temperature && !shapes.empty())
        if (const Triangle* tri = shapes.front().GetIf<Triangle>();
            tri && tri->GetMesh()->HasAttribute("temperature"))
            temperature = AsFloatTexture(arena.New<VertexAttributeField>("temperature", 0.f));
    EmissionModel model =
        overrideModel ? *overrideModel
                      : own.model.value_or(fromMaterial.model.value_or(EmissionModel::Kirchhoff));
    // A dielectric body's surface that absorbs (rough, or opaque beyond its refraction cone)
    // and emits by Kirchhoff's law: its interior medium's temperature. (Other models would
    // make a clear surface glow.)
    if (!temperature && model == EmissionModel::Kirchhoff && material && material->InteriorEta() &&
        !entity.insideMedium.empty())
        if (auto it = mediumTemperatures.find(entity.insideMedium);
            it != mediumTemperatures.end() && AlbedoOf(material, entity.loc)->SurfaceAbsorbs()) {
            temperature = FloatTexture(arena.New<FloatConstantTexture>(it->second));
            heat.interior = true;
        }
    // The scene's ambient temperature, lowest in precedence; a shape that cannot glow stays
    // cold at it without a warning
    if (!temperature && ambient) {
        temperature = ambient;
        heat.ambient = true;
    }
    const bool borrowed = heat.ambient || heat.interior;
    if (!temperature) return heat;
    if (model == EmissionModel::None) return heat;
    if (hasAreaLight) {
        if (!borrowed)
            diag.Warn(entity.loc,
                      "shape has both an AreaLightSource and a temperature; the area "
                      "light is used");
        return heat;
    }
    // A body bounding a medium glows (or not) from it: its surface's temperature is no mistake
    const bool boundsMedium = !entity.insideMedium.empty();
    if (!material || material->IsInterface()) {
        if (!borrowed && !boundsMedium)
            diag.Warn(entity.loc,
                      "a shape with the interface material has no surface to glow; its "
                      "temperature is ignored");
        return heat;
    }
    if (model == EmissionModel::Kirchhoff && material->InteriorEta() &&
        !AlbedoOf(material, entity.loc)->SurfaceAbsorbs()) {
        // A smooth dielectric surface absorbs nothing: the body glows from its interior
        // medium. So does absorbing glass, from the medium scene creation gave it
        // (render/scene_media.h), but where its real index falls below 1 in the film's range
        // its surface absorbs light arriving outside the cone that refracts in, and a rough
        // surface loses some of what it scatters: those surfaces emit (material_albedo.h)
        if (!borrowed && !boundsMedium && !material->InteriorExtinction())
            diag.Warn(entity.loc,
                      "a hot smooth dielectric surface absorbs nothing and so emits nothing; the "
                      "body glows from a hot interior medium (MediumInterface, medium "
                      "\"temperature\")");
        return heat;
    }
#if KILN_THERMAL_EMISSION
    // Approach A: a black surface that only emits
    if (model == EmissionModel::Diffuse) heat.material = Black();
    const MaterialAlbedo* albedo =
        model == EmissionModel::Kirchhoff ? AlbedoOf(heat.material, entity.loc) : nullptr;
    heat.emission = arena.New<ThermalEmission>(*temperature, model, albedo, 1, tables.Range());
#else
    if (!borrowed)
        diag.Warn(entity.loc, "kiln was built without thermal emission; the shape does not glow");
#endif
    return heat;
}

std::vector<int> ThermalEmitters::CreateLights(std::span<const Shape> shapes, const ShapeHeat& heat,
                                               std::vector<Light>& lights, const AlphaMask* alpha) {
    std::vector<int> indices;
#if KILN_THERMAL_EMISSION
    if (!heat.emission || shapes.empty()) return indices;
    // Uniform temperature and material: one exitance for every shape of the directive
    std::optional<ThermalAreaLight::Uniform> uniform;
    if (heat.emission->TemperatureTexture().Is<FloatConstantTexture>() &&
        HasUniformParameters(*heat.material)) {
        std::optional<ShapeSample> ss = shapes.front().SampleParametric(Point2f(0.5f, 0.5f));
        if (ss) {
            SurfaceInteraction si =
                shapes.front().InteractionAt(ss->intr.p, 0, Vector3f(ss->intr.n));
            si.material = heat.material;
            si.thermal = heat.emission;  // as a ray hit there reports it (the shader reads both)
            SampledWavelengths lambda = SampledWavelengths::FromWavelength(550);
            BSDF bsdf = shader.GetBSDF(si, lambda);
            uniform = ThermalAreaLight::Uniform{heat.emission->BandExitance(si, bsdf),
                                                heat.emission->Temperature(si)};
        }
    }
    // One light per shape, built in parallel (each estimates its power), kept in shape order
    std::vector<ThermalAreaLight*> created(shapes.size());
    ThermalAreaLight::BSDFAt bsdfAt = [this](SurfaceInteraction& si, SampledWavelengths& l) {
        return shader.GetBSDF(si, l);
    };
    tbb::parallel_for(size_t(0), shapes.size(), [&](size_t i) {
        const Shape* stored = arena.New<Shape>(shapes[i]);
        created[i] = arena.New<ThermalAreaLight>(stored, heat.material, heat.emission, bsdfAt,
                                                 uniform, powerSampling, alpha);
    });
    for (ThermalAreaLight* light : created) {
        indices.push_back(int(lights.size()));
        lights.push_back(Light(static_cast<const ThermalAreaLight*>(light)));
        if (!uniform) varyingLights.push_back(light);
    }
#else
    (void)shapes, (void)heat, (void)lights, (void)alpha;
#endif
    return indices;
}

const MaterialAlbedo* ThermalEmitters::AlbedoOf(const Material* material, const FileLoc& loc) {
    auto it = albedos.find(material);
    if (it != albedos.end()) return it->second;
    auto start = std::chrono::steady_clock::now();
    const MaterialAlbedo* albedo = MaterialAlbedo::Create(*material, tables, arena);
    tableSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!albedo->Exact())
        diag.Warn(loc,
                  "the emissivity of this hot material is approximate (a coated material "
                  "with a scattering layer, textured thickness or conductor constants, or "
                  "a dispersive coat over a conductor: a Monte Carlo table, about 1 %; a "
                  "conductor with textured anisotropic roughness: the isotropic albedo at "
                  "the projected roughness; a rough subsurface boundary: the smooth Fresnel "
                  "split; a rough dielectric with textured or anisotropic roughness, or a k "
                  "that varies with wavelength: interpolated or coarse tables): Kirchhoff "
                  "equilibrium does not hold exactly");
    albedos.emplace(material, albedo);
    return albedo;
}

const Material* ThermalEmitters::Black() {
    if (black) return black;
    // A diffuse material of reflectance 0: it absorbs everything and reflects nothing
    const SpectrumConstantTexture* zero =
        arena.New<SpectrumConstantTexture>(Spectrum(ConstantSpectrum(0)));
    black = arena.New<Material>(arena.New<DiffuseMaterial>(SpectrumTexture(zero)));
    return black;
}

}  // namespace kiln
