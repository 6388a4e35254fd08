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

Float PMJ02BNSampler::PixelOffset(int d) const {
    if (d >= kCachedDimensions) return ComputePixelOffset(d);
    if (cacheGeneration[size_t(d)] != generation) {
        cachedOffset[size_t(d)] = ComputePixelOffset(d);
        cacheGeneration[size_t(d)] = generation;
    }
    return cachedOffset[size_t(d)];
}

Float PMJ02BNSampler::ComputePixelOffset(int d) const {
    uint64_t key = Hash(d, seed, pixel.x >> 8, pixel.y >> 8);
    uint32_t morton = uint32_t(EncodeMorton2(uint32_t(pixel.x) & 255, uint32_t(pixel.y) & 255));
    uint32_t permuted = 0;
    for (int i = 7; i >= 0; --i) {
        uint32_t digit = (morton >> (2 * i)) & 3;
        uint64_t higher = uint64_t(morton >> (2 * i + 2));
        // Keyed by the block (the digits above) and the digit's level.
        int p = int((MixBits(key ^ (higher << 8) ^ uint64_t(i)) >> 24) % 24);
        permuted |= uint32_t(kBase4Permutations[p][digit]) << (2 * i);
    }
    // The 16 permuted bits reversed into the top half; the low half from the hash.
    uint32_t v = ReverseBits32(permuted) | uint32_t(MixBits(key ^ (uint64_t(morton) << 32)) >> 48);
    return FixedToFloat(v);
}

Point2f PMJ02BNSampler::Get2D() {
    int index = sampleIndex;
    int set = dimension / 2;
    if (set >= kPMJ02Sets)
        index = PermutationElement(uint32_t(sampleIndex), uint32_t(samplesPerPixel),
                                   uint32_t(DimensionHash(dimension)));
    Point2f u = PMJ02Sample(set, index);
    u.x += PixelOffset(dimension);
    u.y += PixelOffset(dimension + 1);
    if (u.x >= 1) u.x -= 1;
    if (u.y >= 1) u.y -= 1;
    dimension += 2;
    return {std::min(u.x, OneMinusEpsilon), std::min(u.y, OneMinusEpsilon)};
}

}  // namespace kiln
