#include "lights/light_sampler.h"

#include <numeric>
#include <vector>

namespace kiln {

namespace {

// Index of light in lights, or -1 if it is not one of its elements.
int IndexOf(std::span<const Light> lights, const Light* light) {
    if (lights.empty() || light < lights.data() || light >= lights.data() + lights.size())
        return -1;
    return int(light - lights.data());
}

}  // namespace

// UniformLightSampler
std::optional<SampledLight> UniformLightSampler::Sample(Float u) const {
    if (lights.empty()) return {};
    int n = int(lights.size());
    int i = std::min(int(u * n), n - 1);
    return SampledLight{&lights[i], Float(1) / n};
}

Float UniformLightSampler::PMF(const Light* light) const {
    return IndexOf(lights, light) < 0 ? 0 : Float(1) / lights.size();
}

// PowerLightSampler
PowerLightSampler::PowerLightSampler(std::span<const Light> lights) : lights(lights) {
    if (lights.empty()) return;
    // Power averaged over the visible range: Monte Carlo with the visible-wavelength density
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    std::vector<Float> power;
    power.reserve(lights.size());
    for (const Light& light : lights) {
        Float p = SafeDiv(light.Phi(lambda), lambda.PDF()).Average();
        power.push_back(std::isfinite(p) && p > 0 ? p : 0);
    }
    if (std::accumulate(power.begin(), power.end(), 0.0) == 0)
        std::fill(power.begin(), power.end(), Float(1));
    aliasTable = AliasTable(power);
}

PowerLightSampler::PowerLightSampler(std::span<const Light> lights, std::vector<Float> weights)
    : lights(lights) {
    if (lights.empty()) return;
    weights.resize(lights.size(), 0);
    for (Float& w : weights) w = std::isfinite(w) && w > 0 ? w : 0;
    if (std::accumulate(weights.begin(), weights.end(), 0.0) == 0)
        std::fill(weights.begin(), weights.end(), Float(1));
    aliasTable = AliasTable(weights);
}

std::optional<SampledLight> PowerLightSampler::Sample(Float u) const {
    if (lights.empty()) return {};
    Float pmf = 0;
    int i = aliasTable.Sample(u, &pmf);
    return SampledLight{&lights[i], pmf};
}

Float PowerLightSampler::PMF(const Light* light) const {
    int i = IndexOf(lights, light);
    return i < 0 ? 0 : aliasTable.PMF(i);
}

}  // namespace kiln
