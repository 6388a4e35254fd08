// Light samplers: choose one light for next-event estimation (pbrt-v4's UniformLightSampler and
// PowerLightSampler). The sample's p is the discrete probability of the chosen light.
#pragma once

#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "base/closed_set.h"
#include "base/sampling.h"
#include "lights/bvh_light_sampler.h"
#include "lights/light.h"

namespace kiln {

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

// Probability proportional to emitted power over the scene's wavelengths (Light::Power; pbrt-v4:
// Phi / pdf at the 4 wavelengths SampleVisible(0.5) gives); uniform if every light has zero
// power. Sampling is O(1) through an alias table. Distant and infinite lights must have been
// preprocessed before the sampler is built (their power depends on the scene's size).
class PowerLightSampler {
  public:
    // skipCovered: as BVHLightSampler's (lights BSDF sampling covers are never chosen).
    explicit PowerLightSampler(std::span<const Light> lights, const SpectralRange& range = {},
                               bool skipCovered = false);
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

  private:
    AliasTable aliasTable;
};

// The light sampler a scene uses (closed set): pbrt-v4's "bvh" (default), "power" and
// "uniform", and kiln's "area" (a PowerLightSampler over the lights' areas).
class LightSampler : public ClosedSet<BVHLightSampler, PowerLightSampler, UniformLightSampler> {
  public:
    using ClosedSet::ClosedSet;
    std::optional<SampledLight> Sample(const LightSampleContext& ctx, Float u) const {
        return Dispatch([&](const auto& s) { return s.Sample(ctx, u); });
    }
    Float PMF(const LightSampleContext& ctx, int index) const {
        return Dispatch([&](const auto& s) { return s.PMF(ctx, index); });
    }
};

}  // namespace kiln
