#include "render/scene.h"

#include <array>
#include <set>

#include "core/geometry/triangle.h"
#include "render/thermal_emitters.h"
#include "spectral/color.h"
#include "textures/temperature_textures.h"

namespace kiln {

Scene::~Scene() = default;

std::string SceneFeatures::ToString() const {
    std::string s;
    auto add = [&](bool on, const char* name) {
        s += std::string(s.empty() ? "" : ", ") + name + (on ? " on" : " off");
    };
    add(thermalEmission, "thermal emission");
    add(varyingTemperatures, "varying temperatures");
    add(areaLights, "area lights");
    add(environmentLight, "environment light");
    add(imageTextures, "image textures");
    add(dispersion, "dispersion");
    add(aovs, "AOVs");
    s += ", polarisation off (not implemented)";
    return s;
}

namespace {

// Creation of named and anonymous materials; mix materials may refer to named materials
// defined later in the file, so named ones are created in dependency order.
void CreateMaterials(SceneDescription& desc, const NamedTextures& textures, ObjectArena& arena,
                     Diagnostics& diag, std::map<std::string, Material>& named,
                     std::vector<const Material*>& anonymous) {
    std::vector<std::pair<std::string, SceneEntity>*> pending;
    for (auto& nm : desc.namedMaterials) pending.push_back(&nm);
    while (!pending.empty()) {
        std::vector<std::pair<std::string, SceneEntity>*> deferred;
        for (auto* nm : pending) {
            SceneEntity& e = nm->second;
            std::string type = e.parameters.GetOneString("type", "");
            if (type.empty())
                throw SceneError(
                    e.loc,
                    "MakeNamedMaterial \"" + nm->first + "\" needs a \"string type\" parameter",
                    nm->first);
            if (type == "mix") {
                bool ready = true;
                for (const std::string& m : e.parameters.GetStringArray("materials"))
                    if (!named.count(m)) ready = false;
                if (!ready) {
                    deferred.push_back(nm);
                    continue;
                }
            }
            TextureParameterDictionary params(&e.parameters, &textures);
            named.emplace(nm->first, Material::Create(type, params, named, e.loc, arena, diag));
            e.parameters.ReportUnused(diag);
        }
        if (deferred.size() == pending.size()) {
            // Whatever remains refers to undefined (or cyclic) materials: let Create report it.
            for (auto* nm : deferred) {
                SceneEntity& e = nm->second;
                TextureParameterDictionary params(&e.parameters, &textures);
                named.emplace(nm->first,
                              Material::Create("mix", params, named, e.loc, arena, diag));
            }
            break;
        }
        pending = std::move(deferred);
    }
    for (SceneEntity& e : desc.materials) {
        TextureParameterDictionary params(&e.parameters, &textures);
        anonymous.push_back(
            arena.New<Material>(Material::Create(e.name, params, named, e.loc, arena, diag)));
        e.parameters.ReportUnused(diag);
    }
}

// Sets "float <name>" to value unless the texture's parameters already have it.
void SetIfAbsent(ParameterDictionary& params, const std::string& name, Float value) {
    if (params.Has(name)) return;
    ParsedParameter p;
    p.type = "float";
    p.name = name;
    p.floats = {value};
    params.Set(p);
}

void CreateTextures(SceneDescription& desc, const SceneOverrides& overrides,
                    NamedTextures& textures, ObjectArena& arena, Diagnostics& diag) {
    for (auto& [name, tex] : desc.floatTextures) {
        // Animation time for time-dependent temperature textures
        if (overrides.timeSeconds && (tex.texName == "cooling" || tex.texName == "keyframes"))
            SetIfAbsent(tex.parameters, "time", *overrides.timeSeconds);
        if (overrides.frame && tex.texName == "heatmap" &&
            tex.parameters.GetOneString("filename", "").find('#') != std::string::npos)
            SetIfAbsent(tex.parameters, "frame", Float(*overrides.frame));
        TextureParameterDictionary params(&tex.parameters, &textures);
        textures.floatTextures.insert_or_assign(
            name,
            CreateFloatTexture(tex.texName, tex.renderFromObject, params, tex.loc, arena, diag));
        tex.parameters.ReportUnused(diag);
    }
    for (auto& [name, tex] : desc.spectrumTextures) {
        // As pbrt-v4: one texture per way a spectrum can be used.
        TextureParameterDictionary params(&tex.parameters, &textures);
        textures.albedoSpectrumTextures.insert_or_assign(
            name, CreateSpectrumTexture(tex.texName, tex.renderFromObject, params,
                                        SpectrumType::Albedo, tex.loc, arena, diag));
        textures.unboundedSpectrumTextures.insert_or_assign(
            name, CreateSpectrumTexture(tex.texName, tex.renderFromObject, params,
                                        SpectrumType::Unbounded, tex.loc, arena, diag));
        textures.illuminantSpectrumTextures.insert_or_assign(
            name, CreateSpectrumTexture(tex.texName, tex.renderFromObject, params,
                                        SpectrumType::Illuminant, tex.loc, arena, diag));
        tex.parameters.ReportUnused(diag);
    }
}

PathIntegratorSettings CreateIntegratorSettings(SceneEntity& e, bool given, Diagnostics& diag) {
    PathIntegratorSettings s;
    if (e.name == "volpath") {
        if (given)
            diag.Warn(e.loc,
                      "participating media are not supported: integrator \"volpath\" "
                      "renders as \"path\"");
    } else if (e.name != "path") {
        diag.Warn(e.loc, "integrator \"" + e.name + "\" is not supported; using \"path\"");
    }
    s.maxDepth = e.parameters.GetOneInt("maxdepth", 5);
    if (s.maxDepth < 0) throw SceneError(e.parameters.Loc("maxdepth"), "maxdepth must be >= 0");
    s.regularize = e.parameters.GetOneBool("regularize", false);
    int wavelengths = e.parameters.GetOneInt("wavelengths", NSpectrumSamples);
    if (wavelengths != 1 && wavelengths != NSpectrumSamples)
        throw SceneError(e.parameters.Loc("wavelengths"),
                         "\"wavelengths\" must be 1 or " + std::to_string(NSpectrumSamples),
                         std::to_string(wavelengths));
    s.singleWavelength = wavelengths == 1;
    std::string strategy = e.parameters.GetOneString("strategy", "mis");
    if (strategy == "mis")
        s.strategy = LightStrategy::MIS;
    else if (strategy == "light")
        s.strategy = LightStrategy::LightOnly;
    else if (strategy == "bsdf")
        s.strategy = LightStrategy::BSDFOnly;
    else
        throw SceneError(e.parameters.Loc("strategy"),
                         "unknown strategy (expected \"mis\", \"light\" or \"bsdf\")", strategy);
    std::string ls = e.parameters.GetOneString("lightsampler", "bvh");
    if (ls == "uniform")
        s.lightSelection = LightSelection::Uniform;
    else if (ls == "area")
        s.lightSelection = LightSelection::Area;
    else if (ls != "bvh" && ls != "power")
        diag.Warn(e.parameters.Loc("lightsampler"),
                  "light sampler \"" + ls + "\" is not supported; using \"power\"");
    return s;
}

}  // namespace

std::unique_ptr<Scene> Scene::Create(SceneDescription& desc, const SceneOverrides& overrides,
                                     Diagnostics& diag) {
    std::unique_ptr<Scene> scene(new Scene());
    ObjectArena& arena = scene->arena;

    // Camera, film, filter and sampler
    scene->filter =
        Filter::Create(desc.filter.name, desc.filter.parameters, desc.filter.loc, arena, diag);
    Float shutterOpen = desc.camera.parameters.GetOneFloat("shutteropen", 0);
    Float shutterClose = desc.camera.parameters.GetOneFloat("shutterclose", 1);
    if (shutterClose < shutterOpen)
        throw SceneError(desc.camera.loc, "shutterclose is before shutteropen", "shutterclose");
    if (overrides.cropWindow) {
        ParsedParameter crop;
        crop.type = "float";
        crop.name = "cropwindow";
        const Bounds2f& c = *overrides.cropWindow;
        crop.floats = {c.pMin.x, c.pMax.x, c.pMin.y, c.pMax.y};
        desc.film.parameters.Set(crop);
    }
    scene->autoExposure = desc.film.parameters.GetOneBool("autoexposure", false);
    scene->film = RGBFilm::Create(desc.film.name, desc.film.parameters, shutterClose - shutterOpen,
                                  *scene->filter, desc.filmColorSpace, desc.film.loc, arena, diag);
    scene->camera =
        Camera::Create(desc.camera.name, desc.camera.parameters, desc.camera.cameraTransform,
                       scene->film->FullResolution(), desc.camera.loc, arena, diag);
    std::optional<int> seed = overrides.seed ? overrides.seed : desc.seedOption;
    scene->sampler =
        Sampler::Create(desc.sampler.name, desc.sampler.parameters, scene->film->FullResolution(),
                        desc.sampler.loc, diag, overrides.samplesPerPixel, seed);
    scene->integrator =
        CreateIntegratorSettings(desc.integrator, desc.integrator.loc.line > 0, diag);
    scene->disablePixelJitter = desc.disablePixelJitter;
    if (desc.accelerator.name != "bvh" && desc.accelerator.name != "kdtree")
        diag.Warn(desc.accelerator.loc,
                  "unknown accelerator \"" + desc.accelerator.name + "\"; kiln uses Embree");
    for (SceneEntity* e : {&desc.filter, &desc.film, static_cast<SceneEntity*>(&desc.camera),
                           &desc.sampler, &desc.integrator, &desc.accelerator})
        e->parameters.ReportUnused(diag);

    // Textures; the thermal parameters of materials (read before the materials report
    // unused parameters); materials
    NamedTextures* textures = arena.New<NamedTextures>();
    textures->renderFromWorld = desc.camera.cameraTransform.RenderFromWorld();
    CreateTextures(desc, overrides, *textures, arena, diag);
    std::map<std::string, ThermalParameters> namedThermal;
    for (auto& [name, e] : desc.namedMaterials)
        namedThermal[name] = ReadThermalParameters(e.parameters, *textures, false, arena);
    std::vector<ThermalParameters> anonymousThermal;
    for (SceneEntity& e : desc.materials)
        anonymousThermal.push_back(ReadThermalParameters(e.parameters, *textures, false, arena));
    std::map<std::string, Material> namedMaterialValues;
    std::vector<const Material*> materials;
    CreateMaterials(desc, *textures, arena, diag, namedMaterialValues, materials);
    std::map<std::string, const Material*> namedMaterials;
    for (auto& [name, m] : namedMaterialValues) namedMaterials[name] = arena.New<Material>(m);
    auto materialOf = [&](const ShapeSceneEntity& s) -> const Material* {
        if (!s.materialName.empty()) {
            auto it = namedMaterials.find(s.materialName);
            if (it == namedMaterials.end())
                throw SceneError(s.loc, "named material '" + s.materialName + "' not defined",
                                 s.materialName);
            return it->second;
        }
        return materials.at(size_t(s.materialIndex));
    };
    auto materialThermalOf = [&](const ShapeSceneEntity& s) -> const ThermalParameters& {
        if (!s.materialName.empty()) return namedThermal.at(s.materialName);
        return anonymousThermal.at(size_t(s.materialIndex));
    };

    // Shapes (created first so the number of area lights is known), with their heat
    auto createShapes = [&](ShapeSceneEntity& s) {
        const kiln::Transform* renderFromObject = arena.New<kiln::Transform>(s.renderFromObject);
        const kiln::Transform* objectFromRender =
            arena.New<kiln::Transform>(Inverse(s.renderFromObject));
        std::vector<Shape> shapes =
            Shape::Create(s.name, renderFromObject, objectFromRender, s.reverseOrientation,
                          s.parameters, s.loc, arena, diag);
        return shapes;
    };
    struct ShapeHeat {
        std::optional<FloatTexture> temperature;
        EmissionModel model = EmissionModel::None;
    };
    std::vector<std::vector<Shape>> shapes;
    std::vector<ShapeHeat> heat;
    size_t areaLightCount = 0;
    for (ShapeSceneEntity& s : desc.shapes) {
        bool isMesh = s.name == "trianglemesh";
        ThermalParameters own = ReadThermalParameters(s.parameters, *textures, isMesh, arena);
        const ThermalParameters& mat = materialThermalOf(s);
        ShapeHeat h;
        h.temperature = own.temperature ? own.temperature : mat.temperature;
        h.model = overrides.emission
                      ? *overrides.emission
                      : own.model.value_or(mat.model.value_or(EmissionModel::Kirchhoff));
        if (!h.temperature) h.model = EmissionModel::None;
        if (h.model != EmissionModel::None && s.areaLightIndex >= 0) {
            diag.Warn(s.loc,
                      "shape has both an AreaLightSource and a temperature; the area "
                      "light is used");
            h.model = EmissionModel::None;
        }
        shapes.push_back(createShapes(s));
        s.parameters.ReportUnused(diag);
        // Per-vertex temperatures (trianglemesh "float temperature" with one value per vertex,
        // or a PLY "temperature" vertex property) when nothing else gives a temperature
        if (!h.temperature && !shapes.back().empty()) {
            const Triangle* tri = shapes.back().front().Get<Triangle>();
            if (tri && tri->GetMesh()->HasAttribute("temperature")) {
                h.temperature = FloatTexture(arena.New<VertexAttributeTexture>("temperature", 0.f));
                h.model = overrides.emission
                              ? *overrides.emission
                              : own.model.value_or(mat.model.value_or(EmissionModel::Kirchhoff));
                if (s.areaLightIndex >= 0) h.model = EmissionModel::None;
            }
        }
        if (s.areaLightIndex >= 0 || h.model != EmissionModel::None)
            areaLightCount += shapes.back().size();
        heat.push_back(std::move(h));
    }

    // Lights
    scene->lights.reserve(desc.lights.size() + areaLightCount);
    for (TransformedSceneEntity& e : desc.lights) {
        std::optional<Light> light =
            Light::Create(e.name, e.parameters, e.renderFromObject, e.loc, arena, diag);
        if (light) scene->lights.push_back(*light);
    }

    // Accelerator: shapes with their materials and area lights, then instances
    scene->aggregate = std::make_unique<kiln::Accelerator>();
    ThermalMaterialCache thermalCache(arena);
    for (size_t i = 0; i < desc.shapes.size(); ++i) {
        ShapeSceneEntity& s = desc.shapes[i];
        if (shapes[i].empty()) continue;
        const Material* material = materialOf(s);
        std::vector<const Light*> areaLights;
        if (s.areaLightIndex >= 0) {
            TransformedSceneEntity& le = desc.areaLights[size_t(s.areaLightIndex)];
            if (le.name != "diffuse")
                diag.Warn(le.loc, "area light \"" + le.name +
                                      "\" is not supported; using "
                                      "\"diffuse\"");
            for (const Shape& shape : shapes[i]) {
                scene->lights.push_back(Light::CreateArea(
                    "diffuse", le.parameters, le.renderFromObject, shape, le.loc, arena, diag));
                areaLights.push_back(&scene->lights.back());
            }
        } else if (heat[i].model != EmissionModel::None) {
            // Hot shapes glow: one thermal light per shape, bound to its material
            if (heat[i].model == EmissionModel::Diffuse) material = thermalCache.Black(diag);
            const ReflectanceTable* table =
                heat[i].model == EmissionModel::Kirchhoff ? thermalCache.Table(material) : nullptr;
#if KILN_THERMAL_EMISSION
            for (const Shape& shape : shapes[i]) {
                const Shape* stored = arena.New<Shape>(shape);
                scene->lights.push_back(Light(arena.New<ThermalAreaLight>(
                    stored, material, *heat[i].temperature, heat[i].model, 1.f, table)));
                areaLights.push_back(&scene->lights.back());
            }
            scene->thermalEmitterCount += int(shapes[i].size());
#else
            (void)table;
            diag.Warn(s.loc, "kiln was built without thermal emission; the shape does not glow");
#endif
        }
        scene->aggregate->Add(shapes[i], material, areaLights);
        scene->shapeCount += int(shapes[i].size());
    }
    std::map<std::string, int> definitionIds;
    for (const InstanceSceneEntity& inst : desc.instances) {
        auto it = definitionIds.find(inst.name);
        if (it == definitionIds.end()) {
            InstanceDefinitionSceneEntity& def = desc.instanceDefinitions.at(inst.name);
            int id = scene->aggregate->NewInstanceDefinition();
            for (ShapeSceneEntity& s : def.shapes) {
                std::vector<Shape> defShapes = createShapes(s);
                s.parameters.ReportUnused(diag);
                if (!defShapes.empty())
                    scene->aggregate->AddToInstanceDefinition(id, defShapes, materialOf(s));
            }
            it = definitionIds.emplace(inst.name, id).first;
        }
        scene->aggregate->AddInstance(it->second, inst.renderFromInstance);
    }
    scene->aggregate->Commit();

    // Lights learn the scene's extent; the light sampler weighs them by power
    Bounds3f bounds = scene->aggregate->Bounds();
    for (const Light& light : scene->lights) {
        light.Preprocess(bounds);
        if (light.Type() == LightType::Infinite) scene->infiniteLights.push_back(&light);
    }
    switch (scene->integrator.lightSelection) {
        case LightSelection::Power:
            scene->lightSampler = std::make_unique<PowerLightSampler>(scene->lights);
            break;
        case LightSelection::Uniform:
            scene->lightSampler = std::make_unique<PowerLightSampler>(
                scene->lights, std::vector<Float>(scene->lights.size(), 1.f));
            break;
        case LightSelection::Area: {
            std::vector<Float> area;
            for (const Light& light : scene->lights) {
                Float a = 1;
                if (auto d = light.GetIf<DiffuseAreaLight>()) a = d->Area();
#if KILN_THERMAL_EMISSION
                if (auto t = light.GetIf<ThermalAreaLight>()) a = t->Area();
#endif
                area.push_back(a);
            }
            scene->lightSampler = std::make_unique<PowerLightSampler>(scene->lights, area);
            break;
        }
    }
    // Features the scene uses
    SceneFeatures& f = scene->features;
    f.thermalEmission = scene->thermalEmitterCount > 0;
    for (const ShapeHeat& h : heat)
        if (h.model != EmissionModel::None && h.temperature &&
            !h.temperature->Is<FloatConstantTexture>())
            f.varyingTemperatures = true;
    f.areaLights = !desc.areaLights.empty();
    f.environmentLight = !scene->infiniteLights.empty();
    for (const auto& [name, tex] : desc.floatTextures)
        f.imageTextures |= tex.texName == "imagemap" || tex.texName == "heatmap";
    for (const auto& [name, tex] : desc.spectrumTextures)
        f.imageTextures |= tex.texName == "imagemap";
    auto dispersive = [](const ParameterDictionary& p) {
        return p.TypeOf("eta") == "spectrum" && p.GetOneString("type", "") != "conductor";
    };
    for (const SceneEntity& m : desc.materials)
        f.dispersion |= m.name != "conductor" && dispersive(m.parameters);
    for (const auto& [name, m] : desc.namedMaterials) f.dispersion |= dispersive(m.parameters);
    f.aovs = scene->film->UsesVisibleSurface();

    if (scene->lights.empty())
        diag.Warn(FileLoc(), "the scene has no lights; the image will be black");
    return scene;
}

BSDF Scene::GetBSDF(SurfaceInteraction& isect, SampledWavelengths& lambda, const Ray& ray,
                    int samplesPerPixel) const {
    (void)ray;
    if (!isect.material) return {};
    // Screen-space footprint for texture filtering
    camera->Approximate_dp_dxy(isect.p, isect.n, isect.time, samplesPerPixel, &isect.dpdx,
                               &isect.dpdy);
    // Solve for the uv derivatives from dp/dx and dp/dy (pbrt-v4's least squares)
    {
        Float ata00 = Dot(isect.dpdu, isect.dpdu), ata01 = Dot(isect.dpdu, isect.dpdv),
              ata11 = Dot(isect.dpdv, isect.dpdv);
        Float invDet = 1 / (ata00 * ata11 - ata01 * ata01);
        invDet = std::isfinite(invDet) ? invDet : 0.f;
        Float atb0x = Dot(isect.dpdu, isect.dpdx), atb1x = Dot(isect.dpdv, isect.dpdx);
        Float atb0y = Dot(isect.dpdu, isect.dpdy), atb1y = Dot(isect.dpdv, isect.dpdy);
        auto finiteOr0 = [](Float v) { return std::isfinite(v) ? Clamp(v, -1e8f, 1e8f) : 0.f; };
        isect.dudx = finiteOr0((ata11 * atb0x - ata01 * atb1x) * invDet);
        isect.dvdx = finiteOr0((ata00 * atb1x - ata01 * atb0x) * invDet);
        isect.dudy = finiteOr0((ata11 * atb0y - ata01 * atb1y) * invDet);
        isect.dvdy = finiteOr0((ata00 * atb1y - ata01 * atb0y) * invDet);
    }
    MaterialEvalContext ctx(isect);
    const Material* material = isect.material->ChooseMaterial(ctx);
    if (!material || material->IsInterface()) return {};
    return material->GetBSDF(ctx, lambda);
}

VisibleSurface Scene::MakeVisibleSurface(const SurfaceInteraction& isect, const BSDF& bsdf,
                                         const SampledWavelengths& lambda) const {
    (void)lambda;
    VisibleSurface vs;
    vs.set = true;
    vs.p = isect.p;
    vs.n = isect.n;
    vs.ns = isect.shading.n;
    vs.depth = camera->GetCameraTransform().CameraFromRender()(isect.p).z;
    // Albedo from a fixed stratified sample set, as pbrt-v4's VisibleSurface
    constexpr int n = 16;
    std::array<Float, n> uc;
    std::array<Point2f, n> u2;
    for (int i = 0; i < n; ++i) {
        uc[i] = (i + 0.5f) / n;
        u2[i] = Point2f((i % 4 + 0.5f) / 4, (i / 4 + 0.5f) / 4);
    }
    vs.albedo = bsdf.rho(isect.wo, uc, u2);
    return vs;
}

}  // namespace kiln
