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

}  // namespace kiln
