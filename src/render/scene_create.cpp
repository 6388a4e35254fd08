// Scene creation in named steps (pbrt-v4's scene.cpp: CreateMaterials, CreateLights,
// CreateAggregate): camera and film, textures, materials, shapes with their heat, lights (with
// a shape-to-lights map, lights identified by index), aggregate, light sampler, features.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <new>
#include <set>
#include <type_traits>

#include <tbb/parallel_for.h>

#include "base/system_memory.h"
#include "core/geometry/curve.h"
#include "core/geometry/mesh_displacement.h"
#include "core/geometry/triangle.h"
#include "core/parser/suggestions.h"
#include "lights/thermal_area_light.h"
#include "materials/subsurface_material.h"
#include "render/integrator_settings.h"
#include "render/scene.h"
#include "render/scene_emitters.h"
#include "render/scene_media.h"
#include "render/scene_wavelengths.h"
#include "spectral/color.h"
#include "textures/basic_textures.h"
#include "textures/texture_alpha_mask.h"
#include "textures/texture_parameter_dictionary.h"
#include "thermal/temperature_field.h"

namespace kiln {

namespace {

// The render job's film (from the recipe and the options' crop window and pixel bounds), its
// charge to the scene's budget recorded
void CreateJobFilm(Scene& scene, RenderJob& job, const RenderOptions& options, Diagnostics& diag) {
    const Scene::JobRecipe& r = scene.jobRecipe;
    RGBFilm::Request request{options.cropWindow, options.pixelBounds, r.stokes};
    if (options.spreadSamples)
        request.reconstruction = *options.spreadSamples ? PixelReconstruction::Spread
                                                        : PixelReconstruction::FilterImportance;
    request.pixelJitter = !scene.disablePixelJitter;
    request.cameraFromRender = r.cameraTransform.CameraFromRender();
    request.worldFromRender = r.cameraTransform.WorldFromRender();
    double before = job.arena.Budget().Committed();
    job.film = RGBFilm::Create(r.film.name, r.film.parameters, r.exposureTime, *scene.filter,
                               r.colorSpace, r.film.loc, job.arena, diag, request);
    job.chargedBytes = job.arena.Budget().Committed() - before;
    job.film->SetWavelengths(scene.wavelengths);
}

// The render job's sampler (the options' samples per pixel and seed) and shader
void CreateJobSamplerAndShader(Scene& scene, RenderJob& job, const RenderOptions& options,
                               Diagnostics& diag) {
    const Scene::JobRecipe& r = scene.jobRecipe;
    std::optional<int> seed = options.seed ? options.seed : r.seed;
    // Spread reconstruction samples pixels beyond the bounds too (RGBFilm::SamplerResolution)
    job.sampler =
        Sampler::Create(r.sampler.name, r.sampler.parameters, job.film->SamplerResolution(),
                        r.sampler.loc, diag, options.samplesPerPixel, seed);
    job.shader = std::make_unique<SceneShader>(&*scene.camera, job.sampler->SamplesPerPixel(),
                                               r.genericFootprints);
}

void CreateCameraAndFilm(Scene& scene, SceneDescription& desc, const RenderOptions& options,
                         Diagnostics& diag) {
    ObjectArena& arena = scene.arena;
    scene.filter =
        Filter::Create(desc.filter.name, desc.filter.parameters, desc.filter.loc, arena, diag);
    Float shutterOpen = desc.camera.parameters.GetOneFloat("shutteropen", 0);
    Float shutterClose = desc.camera.parameters.GetOneFloat("shutterclose", 1);
    if (shutterClose < shutterOpen)
        throw SceneError(desc.camera.loc, "shutterclose is before shutteropen", "shutterclose");
    scene.autoExposure = desc.film.parameters.GetOneBool("autoexposure", false);
    // The first render job; later ones (Scene::SetJob) are built from the same recipe
    scene.jobRecipe = Scene::JobRecipe{desc.film,
                                       desc.sampler,
                                       desc.seedOption,
                                       shutterClose - shutterOpen,
                                       desc.filmColorSpace,
                                       options.stokes,
                                       options.genericFootprints,
                                       desc.camera.cameraTransform};
    scene.disablePixelJitter = desc.disablePixelJitter;  // the film's reconstruction needs it
    scene.job = std::make_unique<RenderJob>(arena.Budget());
    CreateJobFilm(scene, *scene.job, options, diag);
    scene.camera = Camera::Create(desc.camera.name, desc.camera.parameters,
                                  desc.camera.cameraTransform, scene.job->film->FullResolution(),
                                  scene.job->film->Diagonal(), desc.camera.loc, arena, diag);
    if (desc.camera.parameters.Has("polarizer")) {
        Float degrees = desc.camera.parameters.GetOneFloat("polarizer", 0);
        if (!std::isfinite(degrees))
            throw SceneError(desc.camera.parameters.Loc("polarizer"),
                             "camera \"polarizer\" must be a finite angle in degrees", "polarizer");
        scene.cameraPolarizer = Radians(degrees);
    }
    CreateJobSamplerAndShader(scene, *scene.job, options, diag);
    scene.integrator = CreateIntegratorSettings(desc.integrator, options, diag);
    if (desc.accelerator.name != "bvh" && desc.accelerator.name != "kdtree")
        diag.Warn(desc.accelerator.loc,
                  "unknown accelerator \"" + desc.accelerator.name + "\"; kiln uses Embree");
    // (The film's and the sampler's parameters were read from the recipe's copies)
    for (SceneEntity* e :
         {&desc.filter, &scene.jobRecipe.film, static_cast<SceneEntity*>(&desc.camera),
          &scene.jobRecipe.sampler, &desc.integrator, &desc.accelerator})
        e->parameters.ReportUnused(diag);
}

// Textures
NamedTextures& CreateTextures(SceneDescription& desc, const RenderOptions& options, Scene& scene,
                              Diagnostics& diag) {
    ObjectArena& arena = scene.arena;
    NamedTextures& textures = *arena.New<NamedTextures>();
    textures.renderFromWorld = desc.camera.cameraTransform.RenderFromWorld();
    // The thermal module's temperature fields first (at the frame and time of the options;
    // the animated ones are kept to move them to another frame), then kiln's float textures
    TemperatureAnimation animation{options.frame, options.timeSeconds};
    for (auto& [name, tex] : desc.floatTextures) {
        TextureParameterDictionary params(&tex.parameters, &textures);
        textures.floatTextures.insert_or_assign(
            name, IsTemperatureFieldClass(tex.texName)
                      ? CreateTemperatureField(tex.texName, tex.renderFromObject, params, tex.loc,
                                               arena, diag, animation, &scene.animatedFields)
                      : CreateFloatTexture(tex.texName, tex.renderFromObject, params, tex.loc,
                                           arena, diag));
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
    return textures;
}

// Materials: named (in dependency order: mix materials may refer to named materials defined
// later in the file) and anonymous, each with its heat (kiln's "temperature" and "emission",
// thermal/thermal_properties.h; a mix without its own takes its first hot component's)
struct SceneMaterials {
    std::map<std::string, const Material*> named;
    std::vector<const Material*> anonymous;
    std::map<std::string, ThermalProperties> namedHeat;
    std::vector<ThermalProperties> anonymousHeat;
    const BSSRDFTableCache* bssrdfTables = nullptr;  // the subsurface materials' tables

    const Material* Of(const ShapeSceneEntity& s) const {
        if (!s.materialName.empty()) return named.at(CheckedName(s));
        return anonymous.at(size_t(s.materialIndex));
    }
    const ThermalProperties& HeatOf(const ShapeSceneEntity& s) const {
        if (!s.materialName.empty()) return namedHeat.at(CheckedName(s));
        return anonymousHeat.at(size_t(s.materialIndex));
    }

  private:
    const std::string& CheckedName(const ShapeSceneEntity& s) const {
        if (!named.count(s.materialName))
            throw SceneError(s.loc, "named material '" + s.materialName + "' not defined",
                             s.materialName);
        return s.materialName;
    }
};

// A material's heat: its own, or for a mix without one its first hot component's (with the
// mix's own emission model, if it has one)
ThermalProperties ReadMaterialHeat(const std::string& type,
                                   const TextureParameterDictionary& params,
                                   const std::map<std::string, ThermalProperties>& namedHeat,
                                   ObjectArena& arena) {
    ThermalProperties own = ReadThermalProperties(params, false, arena);
    if (own.temperature || type != "mix") return own;
    for (const std::string& name : params.GetStringArray("materials")) {
        auto it = namedHeat.find(name);
        if (it == namedHeat.end() || !it->second.temperature) continue;
        ThermalProperties c = it->second;
        if (own.model) c.model = own.model;
        return c;
    }
    return own;
}

SceneMaterials CreateMaterials(SceneDescription& desc, const NamedTextures& textures,
                               ObjectArena& arena, Diagnostics& diag, LayeredMIS layeredMIS) {
    SceneMaterials materials;
    BSSRDFTableCache* bssrdfTables = arena.New<BSSRDFTableCache>();
    materials.bssrdfTables = bssrdfTables;
    std::map<std::string, Material> named;
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
            materials.namedHeat[nm->first] =
                ReadMaterialHeat(type, params, materials.namedHeat, arena);
            named.emplace(nm->first, Material::Create(type, params, named, e.loc, arena, diag,
                                                      layeredMIS, bssrdfTables));
            e.parameters.ReportUnused(diag);
        }
        if (deferred.size() == pending.size()) {
            // Whatever remains refers to undefined (or cyclic) materials: let Create report it.
            for (auto* nm : deferred) {
                SceneEntity& e = nm->second;
                TextureParameterDictionary params(&e.parameters, &textures);
                materials.namedHeat[nm->first] =
                    ReadMaterialHeat("mix", params, materials.namedHeat, arena);
                named.emplace(nm->first,
                              Material::Create("mix", params, named, e.loc, arena, diag));
            }
            break;
        }
        pending = std::move(deferred);
    }
    for (auto& [name, m] : named) materials.named[name] = arena.New<Material>(m);
    for (SceneEntity& e : desc.materials) {
        TextureParameterDictionary params(&e.parameters, &textures);
        materials.anonymousHeat.push_back(
            ReadMaterialHeat(e.name, params, materials.namedHeat, arena));
        materials.anonymous.push_back(arena.New<Material>(
            Material::Create(e.name, params, named, e.loc, arena, diag, layeredMIS, bssrdfTables)));
        e.parameters.ReportUnused(diag);
    }
    return materials;
}

// The directive a light comes from
struct LightOrigin {
    FileLoc loc;
    std::string name;
    bool hotShape = false;  // a thermal light (the shape's temperature makes it glow)
};

// Shapes of one directive with their material, heat and media
struct SceneShapes {
    std::vector<Shape> shapes;
    ShapeHeat heat;
    MediumInterface media;
    const AlphaMask* alpha = nullptr;  // cut-outs ("alpha"), nullptr: opaque
    const CurveSet* curves = nullptr;  // a "curve" directive (not a Shape)
    bool interfaceMaterial = false;    // an interface marks a boundary: no area light on it
};

// The homogeneous named media with a "float temperature" (K), for the surfaces of the
// dielectric bodies holding them (scene_emitters.h)
std::map<std::string, Float> MediumTemperatures(const SceneDescription& desc) {
    std::map<std::string, Float> temperatures;
    for (const auto& [name, e] : desc.media)
        if (e.parameters.GetOneString("type", "") == "homogeneous" &&
            e.parameters.TypeOf("temperature") == "float")
            if (std::vector<Float> t = e.parameters.GetFloatArray("temperature");
                t.size() == 1 && t[0] > 0 && std::isfinite(t[0]))
                temperatures[name] = t[0];
    return temperatures;
}

SceneShapes CreateShapes(ShapeSceneEntity& s, const NamedTextures& textures,
                         const SceneMaterials& materials, const MediumIndices& media,
                         ThermalEmitters& emitters, ObjectArena& arena, Diagnostics& diag) {
    SceneShapes result;
    result.media = ShapeMedia(s, media);
    TextureParameterDictionary params(&s.parameters, &textures);
    ThermalProperties own = ReadThermalProperties(params, s.name == "trianglemesh", arena);
    result.alpha = TextureAlphaMask::Read(params, arena);
    result.interfaceMaterial = materials.Of(s)->IsInterface();
    const kiln::Transform* renderFromObject = arena.New<kiln::Transform>(s.renderFromObject);
    const kiln::Transform* objectFromRender =
        arena.New<kiln::Transform>(Inverse(s.renderFromObject));
    if (s.name == "curve") {
        result.curves = CurveSet::Create(s.renderFromObject, s.reverseOrientation, s.parameters,
                                         s.loc, arena, diag);
        s.parameters.ReportUnused(diag);
        if (!result.curves) return result;
        if (s.areaLightIndex >= 0)
            diag.Warn(s.loc,
                      "curves cannot be area lights (as in pbrt-v4); the AreaLightSource "
                      "is ignored");
        result.heat = emitters.Heat(s, own, materials.HeatOf(s), materials.Of(s), {}, false);
        if (result.heat.emission && !result.heat.ambient)
            diag.Warn(s.loc, "hot curves glow where rays hit them but are not sampled as lights");
        return result;
    }
    // A plymesh's displacement texture (named textures live here, not in Shape::Create)
    std::optional<MeshDisplacement> displacement;
    if (s.name == "plymesh" && s.parameters.Has("displacement")) {
        std::optional<FloatTexture> d = params.GetFloatTextureOrNull("displacement", arena);
        Float edgeLength = params.GetOneFloat("edgelength", 1);
        if (!(edgeLength > 0) || !std::isfinite(edgeLength))
            throw SceneError(params.Loc("edgelength", s.loc),
                             "\"edgelength\" must be positive and finite", "edgelength");
        if (d)
            displacement = MeshDisplacement{[d](Point3f p, Normal3f n, Point2f uv) {
                                                TextureEvalContext ctx;
                                                ctx.p = p;
                                                ctx.n = n;
                                                ctx.uv = uv;
                                                return d->Evaluate(ctx);
                                            },
                                            edgeLength};
    }
    result.shapes =
        Shape::Create(s.name, renderFromObject, objectFromRender, s.reverseOrientation,
                      s.parameters, s.loc, arena, diag, displacement ? &*displacement : nullptr);
    s.parameters.ReportUnused(diag);
    if (!result.shapes.empty())
        result.heat = emitters.Heat(s, own, materials.HeatOf(s), materials.Of(s), result.shapes,
                                    s.areaLightIndex >= 0);
    return result;
}

// Lights: the scene's lights, then one area or thermal light per shape of each hot or
// emitting shape directive. Returns, per shape directive, the indices of its shapes' lights;
// origins gets each light's directive (LightSource, AreaLightSource or the hot shape): where
// it is and its name.
std::vector<std::vector<int>> CreateLights(Scene& scene, SceneDescription& desc,
                                           const std::vector<SceneShapes>& shapes,
                                           ThermalEmitters& emitters,
                                           std::vector<LightOrigin>& origins, Diagnostics& diag) {
    ObjectArena& arena = scene.arena;
    for (TransformedSceneEntity& e : desc.lights) {
        std::optional<Light> light =
            Light::Create(e.name, e.parameters, e.renderFromObject, e.loc, arena, diag,
                          desc.camera.cameraTransform.RenderFromWorld());
        if (light) scene.lights.push_back(*light);
        if (light) origins.push_back({e.loc, e.name});
    }
    std::vector<std::vector<int>> shapeLights(desc.shapes.size());
    for (size_t i = 0; i < desc.shapes.size(); ++i) {
        const ShapeSceneEntity& s = desc.shapes[i];
        if (s.areaLightIndex >= 0 && shapes[i].interfaceMaterial) {
            diag.Warn(s.loc,
                      "an area light on a shape with an \"interface\" material is ignored (as in "
                      "pbrt-v4): the surface only marks a boundary between media");
        } else if (s.areaLightIndex >= 0) {
            TransformedSceneEntity& le = desc.areaLights[size_t(s.areaLightIndex)];
            if (le.name != "diffuse")
                diag.Warn(le.loc,
                          "area light \"" + le.name + "\" is not supported; using \"diffuse\"");
            for (const Shape& shape : shapes[i].shapes) {
                shapeLights[i].push_back(int(scene.lights.size()));
                scene.lights.push_back(Light::CreateArea("diffuse", le.parameters,
                                                         le.renderFromObject, shape, le.loc, arena,
                                                         diag, shapes[i].alpha));
                origins.push_back({le.loc, le.name});
            }
        } else if (shapes[i].heat.emission && s.motion) {
            diag.Warn(s.loc,
                      "a hot moving shape glows where rays hit it but is not sampled as a light");
        } else if (shapes[i].heat.emission) {
            shapeLights[i] = emitters.CreateLights(shapes[i].shapes, shapes[i].heat, scene.lights,
                                                   shapes[i].alpha);
            scene.thermalEmitterCount += int(shapeLights[i].size());
            origins.resize(scene.lights.size(), {s.loc, s.name, true});
        }
    }
    return shapeLights;
}

// Lights learn the scene's extent (infinite and distant lights need it). The power of each
// light but those at infinity (whose power grows with the scene's extent and is not what
// selects them) must be finite: light selection weighs lights by it. Light creation limits
// the emission itself (lights/light_create.cpp); this catches emission times a huge area.
void PreprocessLights(Scene& scene, const std::vector<LightOrigin>& origins) {
    Bounds3f bounds = scene.aggregate->Bounds();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        scene.lights[i].Preprocess(bounds);
        if (scene.lights[i].Type() == LightType::Infinite) {
            scene.infiniteLights.push_back(int(i));
            continue;
        }
        SampledSpectrum phi = scene.lights[i].Phi(scene.spectralRange.Spread(0.5f));
        for (int c = 0; c < NSpectrumSamples; ++c)
            if (!std::isfinite(phi[c]))
                throw SceneError(origins[i].loc,
                                 origins[i].hotShape
                                     ? "this hot shape radiates more power than single precision "
                                       "holds: its temperature (textured ones too) times its area "
                                       "is too large; at most 1e27 K, and less on large shapes"
                                     : "this light emits more power than single precision holds "
                                       "(its emission times its area, or the scene's cross-"
                                       "section for a distant light); make it dimmer",
                                 origins[i].name);
    }
}

// The glass windows of hot melts (glass_windows.h): the shapes of every directive touching a
// medium that glows inside dielectrics, when their dielectric is non-dispersive and they
// neither move nor have cut-outs; per directive, each shape's window index (or none).
std::vector<std::vector<int>> CreateGlassWindows(Scene& scene, const SceneDescription& desc,
                                                 const std::vector<SceneShapes>& shapes) {
    std::vector<std::vector<int>> windowIndices(shapes.size());
    if (!scene.integrator.volumetric || !scene.integrator.mediumEmissionSampling ||
        !scene.integrator.glassWindows)
        return windowIndices;
    std::vector<MediumBoundary> boundaries;
    for (const SceneShapes& s : shapes)
        boundaries.push_back({s.media, Bounds3f(), s.heat.material});
    std::vector<bool> inGlass = GlowingInsideDielectrics(scene.media, boundaries);
    std::vector<GlassWindows::Window> windows;
    for (size_t i = 0; i < shapes.size(); ++i) {
        const SceneShapes& s = shapes[i];
        int hot = s.media.inside >= 0 && inGlass[size_t(s.media.inside)]     ? s.media.inside
                  : s.media.outside >= 0 && inGlass[size_t(s.media.outside)] ? s.media.outside
                                                                             : -1;
        if (hot < 0 || desc.shapes[i].motion || s.alpha || !s.heat.material) continue;
        std::optional<Spectrum> eta = s.heat.material->InteriorEta();
        if (!eta || (*eta)(400) != (*eta)(550) || (*eta)(700) != (*eta)(550)) continue;
        for (const Shape& shape : s.shapes) {
            windowIndices[i].push_back(int(windows.size()));
            windows.push_back({shape, s.heat.material, s.media, hot});
        }
    }
    if (!windows.empty()) {
        scene.glassWindows = std::make_unique<GlassWindows>(std::move(windows));
        if (scene.glassWindows->Count() == 0) {
            scene.glassWindows.reset();
            windowIndices.assign(shapes.size(), {});
        }
    }
    return windowIndices;
}

// The aggregate: shapes with their materials, lights, thermal emission and glass windows, then
// instances
void CreateAggregate(Scene& scene, SceneDescription& desc, const std::vector<SceneShapes>& shapes,
                     const std::vector<std::vector<int>>& shapeLights,
                     const std::vector<std::vector<int>>& shapeWindows,
                     const NamedTextures& textures, const SceneMaterials& materials,
                     const MediumIndices& media, ThermalEmitters& emitters, Diagnostics& diag) {
    scene.aggregate = std::make_unique<kiln::Accelerator>();
    kiln::Accelerator& aggregate = *scene.aggregate;
    // One directive's shapes into `definition` (-1: the top level, with their lights); a
    // moving directive gets a definition of its own, placed at each ray's time
    auto add = [&](const ShapeSceneEntity& s, const SceneShapes& made, std::span<const int> lights,
                   std::span<const int> windows, int definition) {
        int target = definition;
        if (s.motion) target = aggregate.NewInstanceDefinition();
        if (made.curves)
            aggregate.AddCurves(*made.curves, made.heat.material, made.heat.emission, made.media,
                                made.alpha, target);
        if (!made.shapes.empty()) {
            if (target < 0)
                aggregate.Add(made.shapes, made.heat.material, lights, made.heat.emission,
                              made.media, made.alpha, windows, made.interfaceMaterial);
            else
                aggregate.AddToInstanceDefinition(target, made.shapes, made.heat.material,
                                                  made.heat.emission, made.media, made.alpha,
                                                  made.interfaceMaterial);
        }
        if (s.motion) aggregate.AddAnimatedInstance(target, *s.motion, definition);
    };
    for (size_t i = 0; i < desc.shapes.size(); ++i) {
        add(desc.shapes[i], shapes[i], shapeLights[i], shapeWindows[i], -1);
        scene.shapeCount += int(shapes[i].shapes.size());
    }
    std::map<std::string, int> definitionIds;
    std::vector<size_t> placed;  // the description's index of each AddInstance call
    for (size_t k = 0; k < desc.instances.size(); ++k) {
        const InstanceSceneEntity& inst = desc.instances[k];
        auto it = definitionIds.find(inst.name);
        if (it == definitionIds.end()) {
            InstanceDefinitionSceneEntity& def = desc.instanceDefinitions.at(inst.name);
            int id = aggregate.NewInstanceDefinition();
            for (ShapeSceneEntity& s : def.shapes)
                add(s, CreateShapes(s, textures, materials, media, emitters, scene.arena, diag), {},
                    {}, id);
            it = definitionIds.emplace(inst.name, id).first;
        }
        if (inst.motion) {
            aggregate.AddAnimatedInstance(it->second, *inst.motion);
        } else {
            aggregate.AddInstance(it->second, inst.renderFromInstance);
            placed.push_back(k);
        }
    }
    for (int i : aggregate.Commit()) {
        const InstanceSceneEntity& inst = desc.instances[placed[size_t(i)]];
        diag.Warn(inst.loc, "instance of \"" + inst.name +
                                "\" under a singular transform, or one that takes it or the "
                                "scene's rays beyond the range kiln traces rays in; skipped");
    }
}

// Light selection for next-event estimation (after PreprocessLights: the power of distant and
// infinite lights depends on the scene's size)
void CreateLightSampler(Scene& scene) {
    // Only path and volpath use it, sampling with an incomplete PDF
    const bool skip = scene.integrator.skipUniformEnvironment;
    switch (scene.integrator.lightSelection) {
        case LightSelection::BVH:
            scene.lightSampler = std::make_unique<LightSampler>(
                BVHLightSampler(scene.lights, scene.spectralRange, skip));
            break;
        case LightSelection::Power:
            scene.lightSampler = std::make_unique<LightSampler>(
                PowerLightSampler(scene.lights, scene.spectralRange, skip));
            break;
        case LightSelection::Uniform:
            scene.lightSampler =
                std::make_unique<LightSampler>(UniformLightSampler(scene.lights.size()));
            break;
        case LightSelection::Area: {
            std::vector<Float> area;
            for (const Light& light : scene.lights)
                area.push_back(light.Dispatch([](auto l) -> Float {
                    using T = std::remove_cv_t<std::remove_pointer_t<decltype(l)>>;
                    if constexpr (T::kType == LightType::Area)
                        return l->Area();
                    else
                        return 1;
                }));
            scene.lightSampler = std::make_unique<LightSampler>(PowerLightSampler(std::move(area)));
            break;
        }
    }
}

// The emissive media volpath samples as light sources (scene_media.h), from the shapes that
// bound them
void CreateMediumEmitters(Scene& scene, const std::vector<SceneShapes>& shapes) {
    if (!scene.integrator.mediumEmissionSampling) return;
    std::vector<MediumBoundary> boundaries;
    for (const SceneShapes& s : shapes) {
        if (s.media.inside < 0 && s.media.outside < 0) continue;
        Bounds3f box;
        for (const Shape& shape : s.shapes) box = Union(box, shape.Bounds());
        boundaries.push_back({s.media, box, s.heat.material});
    }
    auto start = std::chrono::steady_clock::now();
    scene.mediumEmission = CreateMediumEmissionSampler(scene.media, boundaries);
    scene.features.mediumSamplerSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What the scene uses and what was chosen for it
SceneFeatures DecideFeatures(const Scene& scene, const SceneDescription& desc,
                             const std::vector<SceneShapes>& shapes,
                             const SceneMaterials& materials, const ThermalEmitters& emitters,
                             const RenderOptions& options) {
    SceneFeatures f;
    for (const SceneShapes& s : shapes)
        if (s.heat.emission) {
            f.thermalEmission = true;
            if (!s.heat.emission->TemperatureTexture().Is<FloatConstantTexture>())
                f.varyingTemperatures = true;
        }
    f.thermalLights = scene.thermalEmitterCount;
    f.emissivityTables = emitters.TabulatedMaterials();
    f.emissivitySeconds = emitters.TableSeconds();
    auto count = [&](const Material* m) {
        ++f.materials;
        if (m->UsesFootprint()) ++f.footprintMaterials;
        if (m->MayPassLightStraightThrough()) ++f.sheets;
        if (m->Is<SubsurfaceMaterial>()) ++f.subsurface;
    };
    for (const auto& [name, m] : materials.named) count(m);
    for (const Material* m : materials.anonymous) count(m);
    f.bssrdfTables = materials.bssrdfTables->Size();
    f.bssrdfSeconds = materials.bssrdfTables->BuildSeconds();
    f.genericFootprints = options.genericFootprints;
    f.genericAOVs = options.genericAOVs;
    f.aovs = scene.job->film->UsesVisibleSurface() || options.genericAOVs;
    f.singleWavelength = scene.integrator.singleWavelength;
    f.fixedPixelCenter = scene.disablePixelJitter;
    f.spreadSamples = scene.job->film->Reconstruction() == PixelReconstruction::Spread;
    f.polarized = scene.emissivityTables->polarized;  // decided in Scene::Create
    f.lightSelection = scene.integrator.lightSelection;
    f.media = int(scene.media.size());
    for (const Medium& m : scene.media) {
        f.emissiveMedia += m.IsEmissive();
        f.thermalMedia += m.IsThermal();
    }
    f.genericVolumes = options.genericVolumes;
    // An environment map whose transform changes lengths makes pbrt-v4's light samples biased
    // (LightLiSample::wiLength): their mean then depends on the MIS heuristic, so "volpath"
    // keeps pbrt-v4's volpath heuristic even without media
    for (const Light& light : scene.lights)
        f.unnormalizedLightSamples |= light.HasUnnormalizedSamples();
    // Subsurface scattering is volpath's (as in pbrt-v4, whose path integrator ignores it)
    f.volumetric =
        options.genericVolumes || (scene.integrator.volumetric &&
                                   (f.media > 0 || f.unnormalizedLightSamples || f.subsurface > 0));
    f.ambientOcclusion = scene.integrator.ambientOcclusion.has_value();
    f.areaLights = !desc.areaLights.empty();
    f.environmentLight = !scene.infiniteLights.empty();
    auto dispersive = [](const ParameterDictionary& p) {
        return p.TypeOf("eta") == "spectrum" && p.GetOneString("type", "") != "conductor";
    };
    for (const SceneEntity& m : desc.materials)
        f.dispersion |= m.name != "conductor" && dispersive(m.parameters);
    for (const auto& [name, m] : desc.namedMaterials) f.dispersion |= dispersive(m.parameters);
    return f;
}

// Bidirectional path tracing (bdpt, and mlt and sppm which render with it) covers surfaces,
// unpolarised light and the perspective camera; otherwise volpath, with a warning. The film
// takes splats under bdpt.
void DecideBidirectional(Scene& scene, const SceneDescription& desc, Diagnostics& diag) {
    SceneFeatures& f = scene.features;
    if (!scene.integrator.bidirectional) return;
    const char* why = f.genericVolumes   ? "--generic volpath"
                      : f.media > 0      ? "participating media"
                      : f.subsurface > 0 ? "subsurface scattering (\"subsurface\" materials)"
                      : f.polarized ? "polarised light (Stokes layers, a camera polariser or a "
                                      "polarising filter)"
                      : !scene.camera->Is<PerspectiveCamera>()
                          ? "cameras other than \"perspective\""
                          : nullptr;
    if (why)
        diag.Warn(desc.integrator.loc, "integrator \"" + desc.integrator.name +
                                           "\": kiln's bdpt does not support " + why +
                                           "; using \"volpath\"");
    f.bidirectional = !why;
    if (f.bidirectional) scene.job->film->EnableSplats();
}

// Polarised transport (render/radiance.h) when the film records Stokes layers, the camera
// carries a polariser or a material is a polarising filter.
bool NeedsPolarization(const Scene& scene, const SceneMaterials& materials) {
    if (scene.job->film->WritesStokes() || scene.cameraPolarizer) return true;
    auto filter = [](const Material* m) { return m->Is<PolarizingFilterMaterial>(); };
    for (const auto& [name, m] : materials.named)
        if (filter(m)) return true;
    return std::any_of(materials.anonymous.begin(), materials.anonymous.end(), filter);
}

}  // namespace

// Every object of the scene, in pbrt-v4's order of creation
static void CreateScene(Scene& scene, SceneDescription& desc, const RenderOptions& options,
                        Diagnostics& diag) {
    CreateCameraAndFilm(scene, desc, options, diag);
    NamedTextures& textures = CreateTextures(desc, options, scene, diag);
    SceneMaterials materials =
        CreateMaterials(desc, textures, scene.arena, diag, options.layeredMIS);
    auto materialOf = [&](const ShapeSceneEntity& s) { return materials.Of(s); };
    MediumIndices media =
        CreateMedia(desc, textures, materialOf, options.emission, scene.media, scene.arena, diag);
    CreateAbsorbingGlassMedia(
        desc, textures, materialOf,
        [&](const ShapeSceneEntity& s) -> const ThermalProperties& { return materials.HeatOf(s); },
        options.emission, scene.media, media, scene.arena);
    scene.cameraMedium = MediumIndex(desc.camera.medium, media, desc.camera.loc);
    scene.spectralRange = scene.job->film->Range();
    WarnOfColoursBeyondTheVisible(desc, scene.spectralRange, diag);
    scene.emissivityTables = std::make_unique<EmissivityTables>(scene.spectralRange);
    scene.emissivityTables->polarized = NeedsPolarization(scene, materials);
    // The shader thermal lights estimate their power with: the job's but for the texture
    // footprint, taken at one sample per pixel, so that what is built at load does not depend on
    // the render job
    SceneShader loadShader(&*scene.camera, 1, options.genericFootprints);
    ThermalEmitters emitters(loadShader, *scene.emissivityTables, scene.arena, diag,
                             options.emission, scene.integrator.emitterPowerSampling,
                             desc.ambientTemperature, MediumTemperatures(desc));
    std::vector<SceneShapes> shapes;
    for (ShapeSceneEntity& s : desc.shapes)
        shapes.push_back(CreateShapes(s, textures, materials, media, emitters, scene.arena, diag));
    std::vector<LightOrigin> lightOrigins;
    std::vector<std::vector<int>> shapeLights =
        CreateLights(scene, desc, shapes, emitters, lightOrigins, diag);
    std::vector<std::vector<int>> shapeWindows = CreateGlassWindows(scene, desc, shapes);
    CreateAggregate(scene, desc, shapes, shapeLights, shapeWindows, textures, materials, media,
                    emitters, diag);
    PreprocessLights(scene, lightOrigins);
    CreateLightSampler(scene);
    if (scene.glassWindows)
        scene.glassWindows->WeighAgainstEnvironment(
            scene.media, GlassWindows::EnvironmentRadiance(scene.lights, scene.infiniteLights));
    scene.varyingThermalLights = emitters.VaryingLights();
    scene.features = DecideFeatures(scene, desc, shapes, materials, emitters, options);
    if (scene.features.volumetric) CreateMediumEmitters(scene, shapes);
    scene.features.sampledMedia = scene.mediumEmission ? scene.mediumEmission->Emitters() : 0;
    scene.features.glassWindows = scene.glassWindows ? scene.glassWindows->Count() : 0;
    scene.features.glassWindowsAgainstEnvironment =
        scene.glassWindows && scene.glassWindows->WeighedAgainstEnvironment();
    if (scene.features.volumetric && scene.integrator.exactMediumEmission)
        scene.exactEmissionMedia = ExactEmissionMedia(scene.media);
    scene.features.exactEmissionMedia =
        int(std::count(scene.exactEmissionMedia.begin(), scene.exactEmissionMedia.end(), 1));
    scene.wavelengths = CreateWavelengthDistribution(scene, &scene.features.wavelengthVisibleShare);
    scene.features.sensorResponseWavelengths = scene.job->film->Thermal() != nullptr;
    scene.job->film->SetWavelengths(scene.wavelengths);
    DecideBidirectional(scene, desc, diag);
    // What volpath does in media, and path and volpath at smooth dielectrics; bdpt and ambient
    // occlusion do neither
    const bool unidirectional = !scene.features.bidirectional && !scene.features.ambientOcclusion;
    scene.features.weightAbsorption =
        unidirectional && scene.features.volumetric && scene.integrator.weightAbsorption;
    scene.features.collisionLightSampling =
        unidirectional && scene.features.volumetric && scene.integrator.collisionLightSampling;
    scene.features.splitDielectrics = unidirectional && scene.integrator.splitDielectrics;
    if (unidirectional && scene.integrator.skipUniformEnvironment &&
        (scene.integrator.lightSelection == LightSelection::BVH ||
         scene.integrator.lightSelection == LightSelection::Power))
        scene.features.skipsUniformEnvironment =
            std::any_of(scene.lights.begin(), scene.lights.end(),
                        [](const Light& l) { return l.CoveredByBSDFSampling(); });
    if (!scene.integrator.volumetric && !scene.media.empty())
        diag.Warn(desc.integrator.loc,
                  "integrator \"path\" ignores participating media (as pbrt-v4); use "
                  "\"volpath\"");
    if (!scene.integrator.volumetric && scene.features.subsurface > 0 &&
        !scene.features.bidirectional)
        diag.Warn(desc.integrator.loc,
                  "integrator \"path\" renders \"subsurface\" materials as their dielectric "
                  "boundary alone (as pbrt-v4); use \"volpath\"");
    if (scene.lights.empty() && !scene.features.thermalEmission &&
        !(scene.features.volumetric && scene.features.emissiveMedia > 0) &&
        !scene.features.ambientOcclusion)
        diag.Warn(FileLoc(), "the scene has no lights; the image will be black");
}

void Scene::SetJob(const RenderOptions& options, Diagnostics& diag) {
    // Built beside the current job, which stays if this one fails
    auto next = std::make_unique<RenderJob>(arena.Budget());
    CreateJobFilm(*this, *next, options, diag);
    CreateJobSamplerAndShader(*this, *next, options, diag);
    if (features.bidirectional) next->film->EnableSplats();
    // The job's film decides the reconstruction (a job may ask for another, kiln's Python API)
    features.spreadSamples = next->film->Reconstruction() == PixelReconstruction::Spread;
    job = std::move(next);
}

void Scene::SetAnimation(const TemperatureAnimation& next) {
    if (next.frame == animation.frame && next.timeSeconds == animation.timeSeconds) return;
    animation = next;
    if (animatedFields.empty()) return;
    for (TemperatureField* field : animatedFields) field->SetAnimation(animation);
    // The thermal lights' power and sampling distributions follow their temperatures, with the
    // shader they were estimated with at load (one sample per pixel), then light selection
    SceneShader loadShader(&*camera, 1, jobRecipe.genericFootprints);
    ThermalAreaLight::BSDFAt bsdfAt = [&](SurfaceInteraction& si, SampledWavelengths& l) {
        return loadShader.GetBSDF(si, l);
    };
    tbb::parallel_for(size_t(0), varyingThermalLights.size(),
                      [&](size_t i) { varyingThermalLights[i]->EstimatePower(bsdfAt); });
    CreateLightSampler(*this);
    // Media whose temperatures follow the animation: their emission estimated again
    if (mediumEmission)
        mediumEmission = std::make_unique<MediumEmissionSampler>(media, mediumEmission->Regions());
    // The film's wavelengths follow what now glows, as a fresh load of this frame would draw them
    wavelengths = CreateWavelengthDistribution(*this, &features.wavelengthVisibleShare);
    if (job) job->film->SetWavelengths(wavelengths);
}

std::unique_ptr<Scene> Scene::Create(SceneDescription& desc, const RenderOptions& options,
                                     Diagnostics& diag) {
    std::unique_ptr<Scene> scene(new Scene());
    if (options.memoryLimitBytes) scene->arena.Budget().SetLimit(*options.memoryLimitBytes);
    try {
        // The description is alive while the scene is created from it (its owner frees it
        // after)
        scene->arena.Budget().Charge(desc.estimatedBytes, "the scene's parsed directives");
        CreateScene(*scene, desc, options, diag);
        scene->animation = TemperatureAnimation{options.frame, options.timeSeconds};
        scene->arena.Budget().Release(desc.estimatedBytes);
    } catch (const MemoryLimitError& e) {
        // Charges are reported at their directive where creation code can; the rest here
        throw SceneError(FileLoc(), e.what());
    } catch (const std::bad_alloc&) {
        // An allocation nothing charged (or the machine short of what the budget assumed)
        throw SceneError(FileLoc(),
                         "out of memory creating the scene, after " +
                             FormatBytes(scene->arena.Budget().Committed()) +
                             " were committed; --memory-limit below the machine's memory "
                             "names the object that does not fit");
    }
    return scene;
}

}  // namespace kiln
