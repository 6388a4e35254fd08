// Light samplers: choose one light for next-event estimation (pbrt-v4's UniformLightSampler and
// PowerLightSampler). The sample's p is the discrete probability of the chosen light.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/base/sampling.h"
#include "lights/light.h"

namespace kiln {

// A light chosen by index into the list the sampler was built for.
struct SampledLight {
    int index;
    Float p;  // probability of choosing this light
};

// Every light with probability 1 / n.
class UniformLightSampler {
  public:
    explicit UniformLightSampler(size_t lightCount) : count(int(lightCount)) {}

    std::optional<SampledLight> Sample(Float u) const;
    std::optional<SampledLight> Sample(const LightSampleContext&, Float u) const {
        return Sample(u);
    }
    // 0 for an index out of range.
    Float PMF(int index) const;
    Float PMF(const LightSampleContext&, int index) const { return PMF(index); }

  private:
    int count;
};

// Probability proportional to emitted power averaged over the visible wavelengths (pbrt-v4:
// Phi / pdf at the 4 wavelengths SampleVisible(0.5) gives); uniform if every light has zero
// power. Sampling is O(1) through an alias table. Distant and infinite lights must have been
// preprocessed before the sampler is built (their power depends on the scene's size).
class PowerLightSampler {
  public:
    explicit PowerLightSampler(std::span<const Light> lights);
    // Probability proportional to the given non-negative weights, one per light (e.g. area,
    // for comparisons); uniform if they are all zero.
    explicit PowerLightSampler(std::vector<Float> weights);

    std::optional<SampledLight> Sample(Float u) const;
    std::optional<SampledLight> Sample(const LightSampleContext&, Float u) const {
        return Sample(u);
    }
    // 0 for an index out of range.
    Float PMF(int index) const;
    Float PMF(const LightSampleContext&, int index) const { return PMF(index); }

    // A light's selection weight: its power over 360-830 nm (pbrt-v4: Phi / pdf averaged over
    // the four wavelengths SampleVisible(0.5) gives), 0 if not finite.
    static Float Power(const Light& light);

  private:
    AliasTable aliasTable;
};

}  // namespace kiln
