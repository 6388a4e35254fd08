// Light samplers: choose one light for next-event estimation (pbrt-v4's UniformLightSampler and
// PowerLightSampler). The sample's p is the discrete probability of the chosen light.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/base/sampling.h"
#include "lights/light.h"

namespace kiln {

struct SampledLight {
    const Light* light;
    Float p;  // probability of choosing this light
};

// Every light with probability 1 / n.
class UniformLightSampler {
  public:
    // The span's elements must stay alive at fixed addresses while the sampler is used.
    explicit UniformLightSampler(std::span<const Light> lights) : lights(lights) {}

    std::optional<SampledLight> Sample(Float u) const;
    std::optional<SampledLight> Sample(const LightSampleContext&, Float u) const {
        return Sample(u);
    }
    // 0 for a light not in the span.
    Float PMF(const Light* light) const;
    Float PMF(const LightSampleContext&, const Light* light) const { return PMF(light); }

  private:
    std::span<const Light> lights;
};

// Probability proportional to emitted power averaged over the visible wavelengths (pbrt-v4:
// Phi / pdf at the 4 wavelengths SampleVisible(0.5) gives); uniform if every light has zero
// power. Sampling is O(1) through an alias table. Distant and infinite lights must have been
// preprocessed before the sampler is built (their power depends on the scene's size).
class PowerLightSampler {
  public:
    // The span's elements must stay alive at fixed addresses while the sampler is used.
    explicit PowerLightSampler(std::span<const Light> lights);
    // Probability proportional to the given non-negative weights, one per light (e.g. area,
    // for comparisons); uniform if they are all zero.
    PowerLightSampler(std::span<const Light> lights, std::vector<Float> weights);

    std::optional<SampledLight> Sample(Float u) const;
    std::optional<SampledLight> Sample(const LightSampleContext&, Float u) const {
        return Sample(u);
    }
    // 0 for a light not in the span.
    Float PMF(const Light* light) const;
    Float PMF(const LightSampleContext&, const Light* light) const { return PMF(light); }

  private:
    std::span<const Light> lights;
    AliasTable aliasTable;
};

}  // namespace kiln
