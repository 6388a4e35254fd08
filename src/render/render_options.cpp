#include "render/render_options.h"

namespace kiln {

std::optional<LightStrategy> ParseLightStrategy(std::string_view name) {
    if (name == "mis") return LightStrategy::MIS;
    if (name == "light") return LightStrategy::LightOnly;
    if (name == "bsdf") return LightStrategy::BSDFOnly;
    return std::nullopt;
}

std::optional<LightSelection> ParseLightSelection(std::string_view name) {
    if (name == "bvh") return LightSelection::BVH;
    if (name == "power") return LightSelection::Power;
    if (name == "uniform") return LightSelection::Uniform;
    if (name == "area") return LightSelection::Area;
    return std::nullopt;
}

std::optional<bool> ParseEmitterPowerSampling(std::string_view name) {
    if (name == "power") return true;
    if (name == "shape") return false;
    return std::nullopt;
}

std::optional<bool> ParseMediumEmissionSampling(std::string_view name) {
    if (name == "sampled") return true;
    if (name == "tracked") return false;
    return std::nullopt;
}

std::string RenderOptionsKey(const RenderOptions& o) {
    auto optional = [](const auto& v, auto text) { return v ? std::string(text(*v)) : ""; };
    std::string key;
    key += "emission=" + optional(o.emission, [](EmissionModel m) { return EmissionModelName(m); });
    key += ";layeredmis=" + std::string(o.layeredMIS == LayeredMIS::PbrtV4 ? "pbrt-v4" : "kiln");
    key += ";volpath=" + std::string(o.genericVolumes ? "1" : "0");
    key += ";stokes=" + optional(o.stokes, [](bool b) { return b ? "1" : "0"; });
    key += ";lightsampler=" + optional(o.lightSelection, [](LightSelection s) {
               const char* names[] = {"bvh", "power", "uniform", "area"};
               return names[int(s)];
           });
    key += ";strategy=" + optional(o.strategy, [](LightStrategy s) {
               const char* names[] = {"mis", "light", "bsdf"};
               return names[int(s)];
           });
    key += ";emittersampling=" +
           optional(o.emitterPowerSampling, [](bool b) { return b ? "power" : "shape"; });
    key += ";mediumemission=" +
           optional(o.mediumEmissionSampling, [](bool b) { return b ? "sampled" : "tracked"; });
    key += ";glasswindows=" + optional(o.glassWindows, [](bool b) { return b ? "1" : "0"; });
    key += ";exactmediumemission=" +
           optional(o.exactMediumEmission, [](bool b) { return b ? "1" : "0"; });
    key +=
        ";weightabsorption=" + optional(o.weightAbsorption, [](bool b) { return b ? "1" : "0"; });
    key += ";collisionlightsampling=" +
           optional(o.collisionLightSampling, [](bool b) { return b ? "1" : "0"; });
    key +=
        ";splitdielectrics=" + optional(o.splitDielectrics, [](bool b) { return b ? "1" : "0"; });
    key += ";skipuniformenvironment=" +
           optional(o.skipUniformEnvironment, [](bool b) { return b ? "1" : "0"; });
    key += ";reconstruction=" +
           optional(o.spreadSamples, [](bool b) { return b ? "spread" : "importance"; });
    key += ";wavelengthsampling=" +
           optional(o.emissionWavelengths, [](bool b) { return b ? "emission" : "visible"; });
    key += ";wavelengths=" + optional(o.singleWavelength, [](bool b) { return b ? "1" : "4"; });
    return key;
}

}  // namespace kiln
