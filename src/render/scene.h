// Scene: the renderable objects created from a SceneDescription (pbrt-v4's BasicScene
// creation step) and RenderOptions: what is loaded once (camera, textures, materials, lights,
// media, shapes in an Embree accelerator, emissivity tables, the integrator's settings) and the
// current render job (film, sampler, shader: RenderJob), which SetJob replaces to render the
// loaded scene again with other samples per pixel, seed, crop window or pixel bounds.
// Creation runs in named steps (scene_create.cpp: camera and film, textures, materials, shapes
// and their heat (scene_emitters.h), lights, aggregate, light sampler, features).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/object_arena.h"
#include "core/camera/camera.h"
#include "core/camera/sampler.h"
#include "core/film/film.h"
#include "core/film/filter.h"
#include "core/film/visible_surface.h"
#include "core/geometry/accelerator.h"
#include "core/parser/diagnostics.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "materials/bxdfs/bsdf.h"
#include "materials/material.h"
#include "media/medium.h"
#include "render/glass_windows.h"
#include "render/medium_emission_sampler.h"
#include "render/render_options.h"
#include "render/scene_description.h"
#include "thermal/emission_model.h"
#include "thermal/emissivity_tables.h"
#include "thermal/temperature_field.h"
#include "thermal/thermal_emission.h"

namespace kiln {

class ThermalAreaLight;

struct PathIntegratorSettings {
    // pbrt-v4's "volpath" (default; participating media) rather than "path" (media ignored)
    bool volumetric = true;
    // pbrt-v4's "bdpt" (also what "mlt" and "sppm" render with): BDPTIntegrator, unless scene
    // creation falls back to volpath (SceneFeatures::bidirectional)
    bool bidirectional = false;
    int maxDepth = 5;         // pbrt-v4 "maxdepth"
    bool regularize = false;  // pbrt-v4 "regularize"
    LightStrategy strategy = LightStrategy::MIS;
    LightSelection lightSelection = LightSelection::BVH;
    // kiln "integer wavelengths": 4 (hero wavelength sampling, default) or 1.
    bool singleWavelength = false;
    // kiln "string emittersampling": points on hot shapes whose emission varies over them are
    // sampled in proportion to power ("power", default) or by the shape's own sampling
    // ("shape", for comparisons).
    bool emitterPowerSampling = true;
    // kiln "string mediumemission": emissive media are sampled as light sources by emitted
    // power in volpath ("sampled", default) or found by tracking alone ("tracked", pbrt-v4's
    // way, for comparisons)
    bool mediumEmissionSampling = true;
    // kiln "bool glasswindows": media glowing inside glass are sampled through their glass
    // (render/glass_windows.h; true, default, with "mediumemission" "sampled") or found by
    // chance refractions alone (false, for comparisons)
    bool glassWindows = true;
    // kiln "bool exactmediumemission": the emission of a uniform medium (homogeneous, constant
    // emission) along a ray segment no light sampling strategy could have found is integrated
    // exactly (true, default) rather than met at tentative collisions (false, pbrt-v4's way)
    bool exactMediumEmission = true;
    // kiln "bool weightabsorption": at a tentative collision volpath chooses between scattering
    // and passing on, absorption weighting the path that passes on by sigma_n / (sigma_n +
    // sigma_a), and in a uniform medium it samples only scattering, the path carrying
    // exp(-sigma_a t) (true, default, while the path's Russian-roulette weight is at least
    // 1/4), rather than ending it with probability sigma_a / sigma_maj (false, pbrt-v4's way):
    // what lies behind a thin absorbing medium is seen through it without the noise of paths
    // ended there or not
    bool weightAbsorption = true;
    // kiln "bool collisionlightsampling": on camera rays and after specular bounces, volpath
    // samples lights at tentative collisions in media (the k-th of a segment with probability
    // 1 / k, weighted by the probability of scattering there) rather than at real scatterings
    // (true, default; false: pbrt-v4's way)
    bool collisionLightSampling = true;
    // kiln "bool splitdielectrics": where a camera ray first meets a smooth dielectric, path
    // and volpath trace both its reflection and its transmission, each weighted by its Fresnel
    // factor (true, default), rather than one of them chosen by chance (false, pbrt-v4's way)
    bool splitDielectrics = true;
    // kiln "bool skipuniformenvironment": path and volpath sample lights with an incomplete
    // PDF (pbrt-v4's allowIncompletePDF), which draws nothing from a uniform environment (BSDF
    // sampling covers it); the bvh and power light samplers then leave it out, so its share of
    // the light samples goes to the other lights (true, default) rather than being spent on
    // it (false, pbrt-v4's way)
    bool skipUniformEnvironment = true;
    // kiln "string wavelengthsampling": in scenes with hot matter, the film draws wavelengths
    // partly by the spectrum it radiates ("emission", default; render/scene_wavelengths.h)
    // or by pbrt-v4's visible density alone ("visible", for comparisons)
    bool emissionWavelengths = true;
    // pbrt-v4's "ambientocclusion" (AmbientOcclusionIntegrator): "cossample" and
    // "maxdistance", the film's white (its colour space's illuminant at unit luminance) times
    // the unoccluded fraction of the hemisphere above each camera ray's first hit
    struct AmbientOcclusion {
        bool cosSample = true;
        Float maxDistance = Infinity;
    };
    std::optional<AmbientOcclusion> ambientOcclusion;
};

// What a scene uses and what kiln chose for it at load; every choice selects code (kiln
// --verbose prints them, bench/specialisation.sh measures what they save).
struct SceneFeatures {
    // Thermal emission exists only for hot shapes: without them no emissivity table is built,
    // no thermal light made and no Planck function evaluated
    bool thermalEmission = false;
    int thermalLights = 0;
    int emissivityTables = 0;          // materials whose emissivity was tabulated
    double emissivitySeconds = 0;      // building those tables
    bool varyingTemperatures = false;  // temperature textures other than constants
    // Texture footprints (pbrt-v4's ray differentials) are computed only at surfaces whose
    // material or temperature texture filters with them
    int materials = 0, footprintMaterials = 0;
    // The pixel loop's instantiation (renderer.cpp): first-hit AOVs only when the film writes
    // them, one or four wavelengths per path, jittered or fixed pixel positions, samples spread
    // over the pixels within the filter's radius or importance-sampled from the filter
    // (PixelReconstruction)
    bool aovs = false, singleWavelength = false, fixedPixelCenter = false, spreadSamples = false;
    // kiln --generic: footprints at every hit, AOV work for every camera ray (to measure what
    // the choices save)
    bool genericFootprints = false, genericAOVs = false;
    LightSelection lightSelection = LightSelection::BVH;
    bool areaLights = false, environmentLight = false;
    bool dispersion = false;  // wavelength-dependent IOR (terminates secondaries)
    // Materials that pass light straight through (thin sheets, Material::
    // MayPassLightStraightThrough): with any, shadow rays cross them (an Intersect loop),
    // else one IntersectP
    int sheets = 0;
    // "subsurface" materials (pbrt-v4's TabulatedBSSRDF): volpath runs VolPathIntegrator for
    // them; their BSSRDF tables (one per g and eta) and the time building them took
    int subsurface = 0, bssrdfTables = 0;
    double bssrdfSeconds = 0;
    // Participating media: the integrator "volpath" runs VolPathIntegrator when the scene has
    // media (or an environment map with unnormalised light samples), PathIntegrator otherwise
    // (media cost nothing when absent); --generic volpath runs VolPathIntegrator whatever the scene
    // says
    int media = 0, emissiveMedia = 0, thermalMedia = 0;
    // Emissive media volpath samples as light sources (MediumEmissionSampler), and the time
    // estimating their emission took
    int sampledMedia = 0, glassWindows = 0;
    bool glassWindowsAgainstEnvironment = false;  // GlassWindows::WeighAgainstEnvironment
    // Emissive media whose emission volpath integrates exactly along ray segments
    // (Scene::exactEmissionMedia)
    int exactEmissionMedia = 0;
    // Whether volpath weighs paths by absorption rather than ending them
    // (PathIntegratorSettings::weightAbsorption)
    bool weightAbsorption = false;
    // Whether volpath samples lights at tentative collisions on camera rays
    // (PathIntegratorSettings::collisionLightSampling)
    bool collisionLightSampling = false;
    // Whether camera rays split at their first smooth dielectric
    // (PathIntegratorSettings::splitDielectrics)
    bool splitDielectrics = false;
    // Whether the light sampler leaves out a uniform environment light the scene has
    // (PathIntegratorSettings::skipUniformEnvironment)
    bool skipsUniformEnvironment = false;
    // The share of the visible density (a thermal film: of its sensor's response) in the film's
    // wavelength distribution (1: it alone; less where hot matter's spectrum makes the rest:
    // scene_wavelengths.h)
    Float wavelengthVisibleShare = 1;
    bool sensorResponseWavelengths = false;  // a thermal film: the base density is its response
    double mediumSamplerSeconds = 0;
    bool volumetric = false, genericVolumes = false;
    bool unnormalizedLightSamples = false;  // Light::HasUnnormalizedSamples (pbrt-v4 compatibility)
    // Bidirectional path tracing (BDPTIntegrator) for "bdpt", "mlt" and "sppm": unless the
    // scene has media, renders polarised light or has a camera other than perspective (then
    // volpath, with a warning); the film then takes splats
    bool bidirectional = false;
    // Ambient occlusion (AmbientOcclusionIntegrator) for "ambientocclusion"
    bool ambientOcclusion = false;
    // Polarised transport (radiance.h): when the film records Stokes layers, the camera
    // carries a polariser or a material is a polarising filter; otherwise the unpolarised
    // variant runs
    bool polarized = false;
    std::string ToString() const;
};

// The scene's shader: the BSDF at a surface point exactly as the integrator builds it at a ray
// hit (texture footprint, mix-material choice, bump or normal map), with the footprint of a
// camera ray there (pbrt-v4's Camera::Approximate_dp_dxy, a function of the point alone, so
// hits and light samples agree). Thermal light samples are evaluated with it
// (ThermalAreaLight::DeferredL), so a point emits the same radiance however a path finds it.
class SceneShader final {
  public:
    // footprintsAlways: compute footprints at every surface, not only where a texture uses
    // them (the generic path).
    SceneShader(const Camera* camera, int samplesPerPixel, bool footprintsAlways)
        : camera(camera), samplesPerPixel(samplesPerPixel), footprintsAlways(footprintsAlways) {}
    // The BSDF at si (invalid for interface materials or si.material == nullptr). Sets si's
    // texture footprint; si.material becomes the material that built the BSDF (a mix
    // material's component chosen at si). May terminate lambda's secondary wavelengths
    // (dispersion).
    BSDF GetBSDF(SurfaceInteraction& si, SampledWavelengths& lambda) const;

  private:
    const Camera* camera;
    int samplesPerPixel;
    bool footprintsAlways;
};

// A render of a loaded scene: what may change from one render of it to the next (samples per
// pixel, seed, crop window, pixel bounds) without re-parsing or rebuilding anything else:
// the film, the sampler, and the shader (whose texture footprints depend on the samples per
// pixel). Its film lives in its own arena, charged to the scene's memory budget while the job
// lasts.
struct RenderJob {
    explicit RenderJob(MemoryBudget& budget) : arena(budget) {}
    ~RenderJob() { arena.Budget().Release(chargedBytes); }
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    ObjectArena arena;
    RGBFilm* film = nullptr;
    std::optional<kiln::Sampler> sampler;  // prototype: each thread renders with a Clone()
    std::unique_ptr<SceneShader> shader;
    double chargedBytes = 0;  // what the film charged to the scene's budget
};

class Scene {
  public:
    // Creates every object; throws SceneError for invalid input and reports warnings
    // (including unused parameters) to diag.
    static std::unique_ptr<Scene> Create(SceneDescription& description,
                                         const RenderOptions& overrides, Diagnostics& diag);
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    ~Scene();

    // Replaces the render job (the film, with what it accumulated, included): samples per
    // pixel, seed, crop window and pixel bounds from options (unset: the scene file's); every
    // other option stays as the scene was created with, since it chose what was built at
    // load (emission models and tables, lights, media, the textures of a frame, Stokes
    // layers, the integrator). Throws SceneError for an invalid film or sampler, as Create,
    // and then keeps the current job (the two films are charged to the memory budget
    // together while the new one is made).
    void SetJob(const RenderOptions& options, Diagnostics& diag);

    // Moves the scene to another frame of its animation (RenderOptions::frame, timeSeconds)
    // without re-parsing or re-creating it: the temperature fields that follow the animation
    // (thermal/temperature_field.h: heat-map sequences, cooling, keyframes) take the new frame
    // and time, the thermal lights whose emission varies over their shape estimate their
    // power again, and light selection is rebuilt. The result is the scene Create makes with
    // those options. Throws SceneError if a frame's heat map cannot be read (the fields that
    // moved keep the new frame). Not while a render runs.
    void SetAnimation(const TemperatureAnimation& animation);
    const TemperatureAnimation& Animation() const { return animation; }

    // The BSDF at a surface hit (SceneShader::GetBSDF): invalid for interface materials;
    // isect.material becomes the material that built it (a mix's component).
    BSDF GetBSDF(SurfaceInteraction& isect, SampledWavelengths& lambda) const {
        return job->shader->GetBSDF(isect, lambda);
    }
    // Radiance the surface at isect emits towards wo: its thermal emission, or its area
    // light's. bsdf: the BSDF GetBSDF returned there. Radiance: SampledSpectrum or Stokes
    // (in the implicit frame of wo).
    template <typename Radiance = SampledSpectrum>
    Radiance SurfaceLe(const SurfaceInteraction& isect, const BSDF& bsdf, Vector3f wo,
                       const SampledWavelengths& lambda) const {
        if (isect.thermal) return isect.thermal->L<Radiance>(isect, bsdf, wo, lambda);
        if (isect.lightIndex >= 0)
            return lights[size_t(isect.lightIndex)].L<Radiance>(isect, bsdf, wo, lambda);
        return {};
    }
    VisibleSurface MakeVisibleSurface(const SurfaceInteraction& isect, const BSDF& bsdf,
                                      const SampledWavelengths& lambda) const;

    ObjectArena arena;               // owns everything below that is held by pointer
    std::unique_ptr<RenderJob> job;  // the film, sampler and shader of the next render
    // What SetJob builds a job from: the scene file's film and sampler, and what the scene was
    // created with
    struct JobRecipe {
        SceneEntity film, sampler;
        std::optional<int> seed;  // the file's (or pbrt-v4's --seed in the description)
        Float exposureTime = 1;   // the camera's shutter interval
        const RGBColorSpace* colorSpace = nullptr;
        std::optional<bool> stokes;
        bool genericFootprints = false;
        CameraTransform cameraTransform;  // the camera's placement (gbuffer layers' spaces)
    };
    JobRecipe jobRecipe;
    std::optional<Filter> filter;
    std::optional<Camera> camera;
    std::unique_ptr<EmissivityTables> emissivityTables;
    std::unique_ptr<kiln::Accelerator> aggregate;
    std::vector<Light> lights;        // identified by index (SurfaceInteraction::lightIndex)
    std::vector<int> infiniteLights;  // indices into lights
    std::unique_ptr<LightSampler> lightSampler;
    // Participating media, identified by index (MediumInterface); the camera's (-1: none)
    std::vector<Medium> media;
    int cameraMedium = -1;
    // Points of emissive media by emitted power for volpath's next-event estimation (nullptr:
    // none, or Integrator "mediumemission" "tracked")
    std::unique_ptr<MediumEmissionSampler> mediumEmission;
    // The glass windows of media glowing inside dielectrics (SurfaceInteraction::windowIndex;
    // nullptr: none, or "mediumemission" "tracked")
    std::unique_ptr<GlassWindows> glassWindows;
    // Per medium: whether it is emissive and uniform, its emission then integrated exactly along
    // ray segments (Medium::UniformSegmentEmission; empty: none, or "exactmediumemission" false)
    std::vector<char> exactEmissionMedia;
    // The wavelengths the scene renders (the film's sensor: visible unless Film "thermal"),
    // decided at load; every job's film must cover the same
    SpectralRange spectralRange;
    // The wavelengths every job's film draws (render/scene_wavelengths.h)
    WavelengthDistribution wavelengths;
    PathIntegratorSettings integrator;
    bool disablePixelJitter = false;
    // Camera "float polarizer" (kiln): a linear polariser in front of the film, its
    // transmission axis at this angle (radians) from the image's horizontal towards its up.
    std::optional<Float> cameraPolarizer;
    bool autoExposure = false;  // film "bool autoexposure" (kiln): see auto_exposure.h
    // The temperature fields that follow the animation, and the thermal lights whose power
    // depends on the point of their shape (SetAnimation moves them)
    std::vector<TemperatureField*> animatedFields;
    std::vector<ThermalAreaLight*> varyingThermalLights;
    int shapeCount = 0;
    int thermalEmitterCount = 0;  // lights of shapes glowing because of their temperature
    SceneFeatures features;

  private:
    Scene() = default;
    TemperatureAnimation animation;  // the frame and time the scene is at
};

}  // namespace kiln
