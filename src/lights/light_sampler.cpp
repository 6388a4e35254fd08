#include "lights/light_sampler.h"

#include <numeric>
#include <vector>

namespace kiln {

// UniformLightSampler
std::optional<SampledLight> UniformLightSampler::Sample(Float u) const {
    if (count == 0) return {};
    int i = std::min(int(u * count), count - 1);
    return SampledLight{i, Float(1) / count};
}

Float UniformLightSampler::PMF(int index) const {
    return index < 0 || index >= count ? 0 : Float(1) / count;
}

// PowerLightSampler
PowerLightSampler::PowerLightSampler(std::span<const Light> lights, const SpectralRange& range,
                                     bool skipCovered) {
    std::vector<Float> power;
    power.reserve(lights.size());
    for (const Light& light : lights) power.push_back(light.Power(range));
    *this = PowerLightSampler(std::move(power));
    if (!skipCovered || aliasTable.Size() == 0) return;
    // The others keep their weights (uniform if none has power); none left: no light at all
    std::vector<Float> weights;
    bool any = false;
    for (size_t i = 0; i < lights.size(); ++i) {
        bool skip = lights[i].CoveredByBSDFSampling();
        weights.push_back(skip ? 0 : aliasTable.PMF(int(i)));
        any |= !skip;
    }
    if (!any) {
        aliasTable = AliasTable();
        return;
    }
    if (std::accumulate(weights.begin(), weights.end(), 0.0) == 0)
        for (size_t i = 0; i < lights.size(); ++i)
            weights[i] = lights[i].CoveredByBSDFSampling() ? 0 : 1;
    aliasTable = AliasTable(weights);
}

PowerLightSampler::PowerLightSampler(std::vector<Float> weights) {
    if (weights.empty()) return;
    for (Float& w : weights) w = std::isfinite(w) && w > 0 ? w : 0;
    if (std::accumulate(weights.begin(), weights.end(), 0.0) == 0)
        std::fill(weights.begin(), weights.end(), Float(1));
    aliasTable = AliasTable(weights);
}

std::optional<SampledLight> PowerLightSampler::Sample(Float u) const {
    if (aliasTable.Size() == 0) return {};
    Float pmf = 0;
    int i = aliasTable.Sample(u, &pmf);
    return SampledLight{i, pmf};
}

Float PowerLightSampler::PMF(int index) const {
    return index < 0 || index >= int(aliasTable.Size()) ? 0 : aliasTable.PMF(index);
}

}  // namespace kiln
