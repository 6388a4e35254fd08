// RenderOptions: what a render asks of a scene besides its file, typed (the command line, the
// tests and any host set them; nothing is turned back into scene-file parameters). Each option
// that is set takes precedence over the scene file.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "base/vecmath.h"
#include "materials/bxdfs/layered_bxdf.h"
#include "thermal/emission_model.h"

namespace kiln {

// How direct light is found: pbrt-v4's MIS of light and BSDF sampling (default), or one of the
// two alone (kiln's Integrator "path" "string strategy" "mis" | "light" | "bsdf", for
// comparisons and tests; all three converge to the same image).
enum class LightStrategy { MIS, LightOnly, BSDFOnly };
// How next-event estimation picks a light (Integrator "string lightsampler"): pbrt-v4's "bvh"
// (default: a light BVH, by importance at the receiving point), "power" (by emitted power) and
// "uniform", and kiln's "area" (area lights by area, others weigh 1).
enum class LightSelection { BVH, Power, Uniform, Area };

// The names above; nullopt for any other.
std::optional<LightStrategy> ParseLightStrategy(std::string_view name);
std::optional<LightSelection> ParseLightSelection(std::string_view name);
// "power" (true: points on hot shapes by power) or "shape" (false: the shape's own sampling).
std::optional<bool> ParseEmitterPowerSampling(std::string_view name);
// "sampled" (true: emissive media are light sources sampled by power) or "tracked" (false).
std::optional<bool> ParseMediumEmissionSampling(std::string_view name);

struct RenderOptions {
    std::optional<int> samplesPerPixel;
    std::optional<int> seed;
    std::optional<Bounds2f> cropWindow;  // NDC [x0, x1] x [y0, y1], as Film "cropwindow"
    // Pixels [x0, x1) x [y0, y1) of the full image, as Film "pixelbounds" (pbrt-v4's
    // --pixelbounds; replaces the scene's crop window and pixel bounds)
    std::optional<Bounds2i> pixelBounds;
    std::optional<EmissionModel> emission;  // thermal emission model for every hot surface
    // kiln --layered-mis: the coated materials' MIS weights (materials/bxdfs/layered_bxdf.h)
    LayeredMIS layeredMIS = LayeredMIS::Kiln;
    // Animation: the frame being rendered and its time in seconds. Textures that change over
    // time ("cooling" and "keyframes": "float time"; "heatmap" sequences: "float frame") get
    // these unless the scene sets them explicitly.
    std::optional<int> frame;
    std::optional<Float> timeSeconds;
    // Run generic code paths instead of the ones chosen for the scene (SceneFeatures), to
    // measure what the choices save: texture footprints at every hit, AOV work for every
    // camera ray.
    bool genericFootprints = false, genericAOVs = false;
    // Volumetric path tracing even when the scene has no media or asks for "path" (kiln
    // --generic volpath)
    bool genericVolumes = false;
    // Whether the film records Stokes layers (kiln --stokes: true; Film "bool stokes"
    // otherwise).
    std::optional<bool> stokes;
    // Pixel reconstruction (kiln --reconstruction; Film "string reconstruction" otherwise):
    // true spreads samples over the pixels within the filter's radius, false importance-samples
    // the filter (pbrt-v4)
    std::optional<bool> spreadSamples;
    // kiln --memory-limit: what the scene's objects may take (base/memory_budget.h);
    // default the machine's memory.
    std::optional<double> memoryLimitBytes;
    // The integrator's choices (Integrator "lightsampler", "strategy", "emittersampling",
    // "mediumemission", "glasswindows", "exactmediumemission", "weightabsorption",
    // "collisionlightsampling", "splitdielectrics", "skipuniformenvironment",
    // "wavelengthsampling", "wavelengths"), for comparisons
    std::optional<LightSelection> lightSelection;
    std::optional<LightStrategy> strategy;
    std::optional<bool> emitterPowerSampling;
    std::optional<bool> mediumEmissionSampling;
    std::optional<bool> glassWindows;            // Integrator "glasswindows"
    std::optional<bool> exactMediumEmission;     // Integrator "exactmediumemission"
    std::optional<bool> weightAbsorption;        // Integrator "weightabsorption"
    std::optional<bool> collisionLightSampling;  // Integrator "collisionlightsampling"
    std::optional<bool> splitDielectrics;        // Integrator "splitdielectrics"
    std::optional<bool> skipUniformEnvironment;  // Integrator "skipuniformenvironment"
    std::optional<bool> emissionWavelengths;     // Integrator "wavelengthsampling" "emission"
    std::optional<bool> singleWavelength;        // one wavelength per path rather than four
};

// The options that change what a render's pixels are, as canonical text (unset ones empty: the
// scene file decides, and it is identified apart): emission model, coated MIS weights, generic
// volumetric integrator, Stokes layers, light selection, strategy, emitter sampling, medium
// emission sampling, glass windows, wavelengths per path. Two renders with different keys must not
// be merged or resumed from one another (app/merge.h, app/checkpoint.h).
std::string RenderOptionsKey(const RenderOptions& options);

}  // namespace kiln
