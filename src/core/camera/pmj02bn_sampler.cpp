// PMJ02BNSampler implementation.
#include "core/camera/pmj02bn_sampler.h"

#include <stdexcept>

namespace kiln {

PMJ02BNSampler::PMJ02BNSampler(int samplesPerPixel, int seed)
    : samplesPerPixel(samplesPerPixel), seed(seed) {
    if (samplesPerPixel < 1 || samplesPerPixel > kPMJ02Samples)
        throw std::invalid_argument("PMJ02BNSampler: samples per pixel out of range");
    // Tile side T = 2^(8 - log4 spp4) with spp4 the next power of 4: T^2 spp4 = 65536.
    int log4 = 0;
    while ((1 << (2 * log4)) < samplesPerPixel) ++log4;
    int log2Tile = 8 - log4;
    tileSize = 1 << log2Tile;
    auto samples =
        std::make_shared<std::vector<Point2f>>(size_t(tileSize) * tileSize * samplesPerPixel);
    std::vector<int> stored(size_t(tileSize) * tileSize, 0);
    for (const FixedPoint2& p : PMJ02Set(0)) {
        // Pixel from the first log2Tile bits; position inside it from the rest (exact).
        uint32_t px = log2Tile ? p[0] >> (32 - log2Tile) : 0;
        uint32_t py = log2Tile ? p[1] >> (32 - log2Tile) : 0;
        size_t pixelOffset = px + size_t(py) * tileSize;
        if (stored[pixelOffset] == samplesPerPixel) continue;  // spp not a power of 4
        uint32_t fx = p[0] << log2Tile, fy = p[1] << log2Tile;
        (*samples)[pixelOffset * samplesPerPixel + size_t(stored[pixelOffset]++)] = {
            FixedToFloat(fx), FixedToFloat(fy)};
    }
    for (int n : stored)
        if (n != samplesPerPixel) throw std::logic_error("PMJ02BNSampler: pixel tile not filled");
    pixelSamples = std::move(samples);
}

Point2f PMJ02BNSampler::Get2D() {
    int index = sampleIndex;
    int set = dimension / 2;
    uint64_t hash = DimensionHash(dimension);
    if (set >= kPMJ02Sets)
        index =
            PermutationElement(uint32_t(sampleIndex), uint32_t(samplesPerPixel), uint32_t(hash));
    Point2f u = PMJ02Sample(set, index);
    u.x += Offset(hash);
    u.y += Offset(DimensionHash(dimension + 1));
    if (u.x >= 1) u.x -= 1;
    if (u.y >= 1) u.y -= 1;
    dimension += 2;
    return {std::min(u.x, OneMinusEpsilon), std::min(u.y, OneMinusEpsilon)};
}

}  // namespace kiln
