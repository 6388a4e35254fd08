// BVHLightSampler: pbrt-v4's default light sampler ("bvh", Sec. 12.6.3). Lights with spatial
// bounds are organised in a bounding volume hierarchy over their LightBounds (position, power
// and normal cone; thermal emitters with their temperature-dependent power, one leaf per hot
// triangle); a light is chosen by descending the tree with probabilities proportional to each
// child's importance at the receiving point, so nearby and bright emitters get the samples.
// Infinite and distant lights are chosen uniformly with probability n_inf / (n_inf + 1)
// (lights left out by skipCovered not counted).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lights/light.h"
#include "lights/light_bounds.h"

namespace kiln {

class BVHLightSampler {
  public:
    // Lights of zero power (Light::Bounds().phi) are never chosen.
    // range: the scene's wavelengths, over which each light's power is estimated (Light::Power)
    // skipCovered: for estimators that sample lights with an incomplete PDF, which draw
    // nothing from lights BSDF sampling covers (Light::CoveredByBSDFSampling): those are then
    // never chosen either, and their share of the samples goes to lights that can use it.
    explicit BVHLightSampler(std::span<const Light> lights, const SpectralRange& range = {},
                             bool skipCovered = false);

    std::optional<SampledLight> Sample(const LightSampleContext& ctx, Float u) const;
    // Probability that Sample(ctx, .) chooses light `index` (0 for lights of zero power).
    Float PMF(const LightSampleContext& ctx, int index) const;

  private:
    struct Node {
        LightBounds bounds;
        int childOrLight = -1;  // interior: second child's index; leaf: the light's index
        bool leaf = false;
    };
    std::pair<int, LightBounds> Build(std::vector<std::pair<int, LightBounds>>& lights, int start,
                                      int end, uint64_t bitTrail, int depth);
    static Float Cost(const LightBounds& b, const Bounds3f& bounds, int dim);

    std::vector<int> infiniteLights;
    std::vector<Node> nodes;
    // Per light: the path from the root (bit d: second child at depth d); ~0u when not in the
    // tree
    std::vector<uint64_t> bitTrails;
    std::vector<bool> infinite;
};

}  // namespace kiln
