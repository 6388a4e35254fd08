#include "lights/bvh_light_sampler.h"

#include <algorithm>

#include "lights/light_sampler.h"

namespace kiln {

namespace {

constexpr uint64_t kNotInTree = ~uint64_t(0);
// Below this depth splits minimise pbrt-v4's cost; deeper ones are median splits, so the depth
// (and the bit trail) stays below 64 for any number of lights.
constexpr int kMaxCostDepth = 32;

Float SurfaceArea(const Bounds3f& b) {
    Vector3f d = b.Diagonal();
    return 2 * (d.x * d.y + d.x * d.z + d.y * d.z);
}

// Bucket of a centroid along dim
int Bucket(const Bounds3f& centroids, Point3f pc, int dim, int nBuckets) {
    Float extent = centroids.pMax[dim] - centroids.pMin[dim];
    int b = int(nBuckets * ((pc[dim] - centroids.pMin[dim]) / extent));
    return std::clamp(b, 0, nBuckets - 1);
}

}  // namespace

BVHLightSampler::BVHLightSampler(std::span<const Light> lights, const SpectralRange& range,
                                 bool skipCovered)
    : bitTrails(lights.size(), kNotInTree), infinite(lights.size(), false) {
    std::vector<std::pair<int, LightBounds>> bounded;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (skipCovered && lights[i].CoveredByBSDFSampling()) continue;
        std::optional<LightBounds> lb = lights[i].Bounds(range);
        if (!lb) {
            infiniteLights.push_back(int(i));
            infinite[i] = true;
        } else if (lb->phi > 0) {
            lb->Finish();
            bounded.push_back({int(i), *lb});
        }
    }
    if (!bounded.empty()) Build(bounded, 0, int(bounded.size()), 0, 0);
}

Float BVHLightSampler::Cost(const LightBounds& b, const Bounds3f& bounds, int dim) {
    // Solid-angle measure of the emission directions (pbrt-v4's M_omega)
    Float thetaO = SafeACos(b.cosTheta_o), thetaE = SafeACos(b.cosTheta_e);
    Float thetaW = std::min<Float>(thetaO + thetaE, Pi);
    Float sinThetaO = SafeSqrt(1 - Sqr(b.cosTheta_o));
    Float mOmega =
        2 * Pi * (1 - b.cosTheta_o) + Pi / 2 *
                                          (2 * thetaW * sinThetaO - std::cos(thetaO - 2 * thetaW) -
                                           2 * thetaO * sinThetaO + b.cosTheta_o);
    Vector3f d = bounds.Diagonal();
    Float kr = std::max({d.x, d.y, d.z}) / std::max(d[dim], Float(1e-30));
    return b.phi * mOmega * kr * SurfaceArea(b.bounds);
}

std::pair<int, LightBounds> BVHLightSampler::Build(std::vector<std::pair<int, LightBounds>>& lights,
                                                   int start, int end, uint64_t bitTrail,
                                                   int depth) {
    if (end - start == 1) {
        int nodeIndex = int(nodes.size());
        nodes.push_back(Node{lights[size_t(start)].second, lights[size_t(start)].first, true});
        bitTrails[size_t(lights[size_t(start)].first)] = bitTrail;
        return {nodeIndex, lights[size_t(start)].second};
    }
    // Split dimension and position by pbrt-v4's cost over 12 buckets per axis
    Bounds3f bounds, centroids;
    for (int i = start; i < end; ++i) {
        bounds = Union(bounds, lights[size_t(i)].second.bounds);
        centroids = Union(centroids, lights[size_t(i)].second.Centroid());
    }
    constexpr int nBuckets = 12;
    Float minCost = Infinity;
    int bestBucket = -1, bestDim = -1;
    for (int dim = 0; dim < 3 && depth < kMaxCostDepth; ++dim) {
        if (centroids.pMax[dim] == centroids.pMin[dim]) continue;
        LightBounds buckets[nBuckets];
        for (int i = start; i < end; ++i) {
            int b = Bucket(centroids, lights[size_t(i)].second.Centroid(), dim, nBuckets);
            buckets[b] = Union(buckets[b], lights[size_t(i)].second);
        }
        for (int i = 0; i < nBuckets - 1; ++i) {
            LightBounds b0, b1;
            for (int j = 0; j <= i; ++j) b0 = Union(b0, buckets[j]);
            for (int j = i + 1; j < nBuckets; ++j) b1 = Union(b1, buckets[j]);
            Float cost = Cost(b0, bounds, dim) + Cost(b1, bounds, dim);
            if (i > 0 && cost > 0 && cost < minCost) {
                minCost = cost;
                bestBucket = i;
                bestDim = dim;
            }
        }
    }
    int mid = (start + end) / 2;
    if (bestDim >= 0) {
        auto* first = lights.data() + start;
        auto* pmid = std::partition(first, lights.data() + end, [&](const auto& l) {
            return Bucket(centroids, l.second.Centroid(), bestDim, nBuckets) <= bestBucket;
        });
        mid = int(pmid - lights.data());
        if (mid == start || mid == end) mid = (start + end) / 2;
    } else {
        // Median along the widest centroid extent
        Vector3f d = centroids.Diagonal();
        int dim = d.x > d.y && d.x > d.z ? 0 : (d.y > d.z ? 1 : 2);
        std::nth_element(lights.data() + start, lights.data() + mid, lights.data() + end,
                         [&](const auto& a, const auto& b) {
                             return a.second.Centroid()[dim] < b.second.Centroid()[dim];
                         });
    }
    int nodeIndex = int(nodes.size());
    nodes.push_back(Node{});
    auto child0 = Build(lights, start, mid, bitTrail, depth + 1);
    auto child1 = Build(lights, mid, end, bitTrail | (uint64_t(1) << depth), depth + 1);
    LightBounds lb = Union(child0.second, child1.second);
    lb.Finish();
    nodes[size_t(nodeIndex)] = Node{lb, child1.first, false};
    return {nodeIndex, lb};
}

std::optional<SampledLight> BVHLightSampler::Sample(const LightSampleContext& ctx, Float u) const {
    Float pInfinite =
        Float(infiniteLights.size()) / Float(infiniteLights.size() + (nodes.empty() ? 0 : 1));
    if (u < pInfinite) {
        u /= pInfinite;
        int n = int(infiniteLights.size());
        int index = std::min(int(u * n), n - 1);
        return SampledLight{infiniteLights[size_t(index)], pInfinite / n};
    }
    if (nodes.empty()) return {};
    u = std::min<Float>((u - pInfinite) / (1 - pInfinite), OneMinusEpsilon);
    int nodeIndex = 0;
    Float pmf = 1 - pInfinite;
    while (true) {
        const Node& node = nodes[size_t(nodeIndex)];
        if (node.leaf) {
            if (nodeIndex > 0 || node.bounds.Importance(ctx.p, ctx.ns) > 0)
                return SampledLight{node.childOrLight, pmf};
            return {};
        }
        Float c0 = nodes[size_t(nodeIndex + 1)].bounds.Importance(ctx.p, ctx.ns);
        Float c1 = nodes[size_t(node.childOrLight)].bounds.Importance(ctx.p, ctx.ns);
        if (c0 == 0 && c1 == 0) return {};
        Float p0 = c0 / (c0 + c1);
        if (u < p0) {
            nodeIndex = nodeIndex + 1;
            u = std::min<Float>(u / p0, OneMinusEpsilon);
            pmf *= p0;
        } else {
            nodeIndex = node.childOrLight;
            u = std::min<Float>((u - p0) / (1 - p0), OneMinusEpsilon);
            pmf *= c1 / (c0 + c1);  // as PMF computes it
        }
    }
}

Float BVHLightSampler::PMF(const LightSampleContext& ctx, int index) const {
    if (index < 0 || size_t(index) >= bitTrails.size()) return 0;
    Float pInfinite =
        Float(infiniteLights.size()) / Float(infiniteLights.size() + (nodes.empty() ? 0 : 1));
    if (infinite[size_t(index)]) return pInfinite / Float(infiniteLights.size());
    uint64_t bitTrail = bitTrails[size_t(index)];
    if (bitTrail == kNotInTree) return 0;
    Float pmf = 1 - pInfinite;
    int nodeIndex = 0;
    while (true) {
        const Node& node = nodes[size_t(nodeIndex)];
        if (node.leaf) {
            // A lone light at the root is chosen only where it matters (as Sample)
            if (nodeIndex == 0 && !(node.bounds.Importance(ctx.p, ctx.ns) > 0)) return 0;
            return node.childOrLight == index ? pmf : 0;
        }
        Float c0 = nodes[size_t(nodeIndex + 1)].bounds.Importance(ctx.p, ctx.ns);
        Float c1 = nodes[size_t(node.childOrLight)].bounds.Importance(ctx.p, ctx.ns);
        if (c0 == 0 && c1 == 0) return 0;
        pmf *= ((bitTrail & 1) ? c1 : c0) / (c0 + c1);
        nodeIndex = (bitTrail & 1) ? node.childOrLight : nodeIndex + 1;
        bitTrail >>= 1;
    }
}

}  // namespace kiln
