#include "render/integrator_settings.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include "core/parser/suggestions.h"
#include "render/scene_description.h"

namespace kiln {

namespace {

// The value of the string parameter `name` (default def) as parse maps it, or a SceneError
// naming what it expects
template <typename Parse>
auto Choice(SceneEntity& e, const char* name, const char* def, Parse parse, const char* expected) {
    std::string value = e.parameters.GetOneString(name, def);
    auto parsed = parse(value);
    if (!parsed)
        throw SceneError(e.parameters.Loc(name),
                         std::string("unknown ") + name + " (expected " + expected + ")", value);
    return *parsed;
}

}  // namespace

PathIntegratorSettings CreateIntegratorSettings(SceneEntity& e, const RenderOptions& options,
                                                Diagnostics& diag) {
    PathIntegratorSettings s;
    // pbrt-v4's other integrators render with volpath (a warning); a name pbrt-v4 does not know
    // either is an error, as in pbrt-v4
    static constexpr std::string_view kIntegrators[] = {
        "path",       "volpath",    "ambientocclusion", "bdpt", "lightpath", "mlt",
        "randomwalk", "simplepath", "simplevolpath",    "sppm", "function"};
    if (std::find(std::begin(kIntegrators), std::end(kIntegrators), e.name) ==
        std::end(kIntegrators))
        throw SceneError(e.loc,
                         "unknown integrator \"" + e.name + "\"" + DidYouMean(e.name, kIntegrators),
                         e.name);
    // mlt and sppm converge to the image bdpt renders: rendered with bdpt (which may still
    // fall back to volpath: DecideFeatures)
    s.bidirectional = e.name == "bdpt" || e.name == "mlt" || e.name == "sppm";
    if (e.name == "mlt" || e.name == "sppm")
        diag.Warn(e.loc, "integrator \"" + e.name + "\" is not supported; rendered with \"bdpt\"");
    else if (e.name != "path" && e.name != "volpath" && e.name != "bdpt" &&
             e.name != "ambientocclusion")
        diag.Warn(e.loc, "integrator \"" + e.name + "\" is not supported; using \"volpath\"");
    if (e.name == "ambientocclusion") {
        PathIntegratorSettings::AmbientOcclusion ao;
        ao.cosSample = e.parameters.GetOneBool("cossample", true);
        ao.maxDistance = e.parameters.GetOneFloat("maxdistance", Infinity);
        if (!(ao.maxDistance > 0))
            throw SceneError(e.parameters.Loc("maxdistance"), "\"maxdistance\" must be > 0",
                             std::to_string(ao.maxDistance));
        s.ambientOcclusion = ao;
    }
    s.volumetric = e.name != "path";
    s.maxDepth = e.parameters.GetOneInt("maxdepth", 5);
    if (s.maxDepth < 0) throw SceneError(e.parameters.Loc("maxdepth"), "maxdepth must be >= 0");
    s.regularize = e.parameters.GetOneBool("regularize", false);
    int wavelengths = e.parameters.GetOneInt("wavelengths", NSpectrumSamples);
    if (wavelengths != 1 && wavelengths != NSpectrumSamples)
        throw SceneError(e.parameters.Loc("wavelengths"),
                         "\"wavelengths\" must be 1 or " + std::to_string(NSpectrumSamples),
                         std::to_string(wavelengths));
    s.singleWavelength = options.singleWavelength.value_or(wavelengths == 1);
    s.strategy = options.strategy.value_or(
        Choice(e, "strategy", "mis", ParseLightStrategy, "\"mis\", \"light\" or \"bsdf\""));
    s.emitterPowerSampling = options.emitterPowerSampling.value_or(
        Choice(e, "emittersampling", "power", ParseEmitterPowerSampling, "\"power\" or \"shape\""));
    s.mediumEmissionSampling = options.mediumEmissionSampling.value_or(Choice(
        e, "mediumemission", "sampled", ParseMediumEmissionSampling, "\"sampled\" or \"tracked\""));
    s.glassWindows = options.glassWindows.value_or(e.parameters.GetOneBool("glasswindows", true));
    s.exactMediumEmission =
        options.exactMediumEmission.value_or(e.parameters.GetOneBool("exactmediumemission", true));
    s.weightAbsorption =
        options.weightAbsorption.value_or(e.parameters.GetOneBool("weightabsorption", true));
    s.collisionLightSampling = options.collisionLightSampling.value_or(
        e.parameters.GetOneBool("collisionlightsampling", true));
    s.splitDielectrics =
        options.splitDielectrics.value_or(e.parameters.GetOneBool("splitdielectrics", true));
    s.skipUniformEnvironment = options.skipUniformEnvironment.value_or(
        e.parameters.GetOneBool("skipuniformenvironment", true));
    s.emissionWavelengths = options.emissionWavelengths.value_or(Choice(
        e, "wavelengthsampling", "emission",
        [](std::string_view v) -> std::optional<bool> {
            if (v == "emission" || v == "visible") return v == "emission";
            return std::nullopt;
        },
        "\"emission\" or \"visible\""));
    s.lightSelection =
        options.lightSelection.value_or(Choice(e, "lightsampler", "bvh", ParseLightSelection,
                                               "\"bvh\", \"power\", \"uniform\" or \"area\""));
    return s;
}

}  // namespace kiln
