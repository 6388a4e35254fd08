// Sampler implementations (pbrt-v4 semantics).
#include "core/camera/samplers.h"

namespace kiln {

// StratifiedSampler
uint64_t StratifiedSampler::DimensionHash() const {
    return MixBits((uint64_t(uint32_t(pixel.x)) << 48) ^ (uint64_t(uint32_t(pixel.y)) << 32) ^
                   (uint64_t(dimension) << 16) ^ uint64_t(uint32_t(seed)));
}

Float StratifiedSampler::Get1D() {
    int stratum = PermutationElement(sampleIndex, SamplesPerPixel(), uint32_t(DimensionHash()));
    ++dimension;
    Float delta = jitter ? rng.UniformFloat() : 0.5f;
    return std::min((stratum + delta) / SamplesPerPixel(), OneMinusEpsilon);
}

Point2f StratifiedSampler::Get2D() {
    int stratum = PermutationElement(sampleIndex, SamplesPerPixel(), uint32_t(DimensionHash()));
    dimension += 2;
    int x = stratum % xPixelSamples, y = stratum / xPixelSamples;
    Float dx = jitter ? rng.UniformFloat() : 0.5f;
    Float dy = jitter ? rng.UniformFloat() : 0.5f;
    return {std::min((x + dx) / xPixelSamples, OneMinusEpsilon),
            std::min((y + dy) / yPixelSamples, OneMinusEpsilon)};
}

// PaddedSobolSampler
uint64_t PaddedSobolSampler::DimensionHash() const {
    return MixBits((uint64_t(uint32_t(pixel.x)) << 48) ^ (uint64_t(uint32_t(pixel.y)) << 32) ^
                   (uint64_t(dimension) << 16) ^ uint64_t(uint32_t(seed)));
}

Float PaddedSobolSampler::Get1D() {
    uint64_t hash = DimensionHash();
    int index = PermutationElement(sampleIndex, samplesPerPixel, uint32_t(hash));
    ++dimension;
    return SobolSample(uint64_t(index), 0, randomize, uint32_t(hash >> 32));
}

Point2f PaddedSobolSampler::Get2D() {
    uint64_t hash = DimensionHash();
    int index = PermutationElement(sampleIndex, samplesPerPixel, uint32_t(hash));
    dimension += 2;
    return {SobolSample(uint64_t(index), 0, randomize, uint32_t(hash)),
            SobolSample(uint64_t(index), 1, randomize, uint32_t(hash >> 32))};
}

// ZSobolSampler
ZSobolSampler::ZSobolSampler(int samplesPerPixel, Point2i fullResolution,
                             RandomizeStrategy randomize, int seed)
    : randomize(randomize), seed(seed) {
    log2SamplesPerPixel = Log2Int(uint64_t(RoundUpPow2(std::max(1, samplesPerPixel))));
    int res = RoundUpPow2(std::max({fullResolution.x, fullResolution.y, 1}));
    int log4SamplesPerPixel = (log2SamplesPerPixel + 1) / 2;
    nBase4Digits = Log2Int(uint64_t(res)) + log4SamplesPerPixel;
}

uint64_t ZSobolSampler::PermutedDigits(int firstDigit, int lastDigit) const {
    // Permute each full base-4 digit by a permutation chosen from the digits above it, so the
    // permutation is consistent within every subtree of the Morton hierarchy.
    bool pow2Samples = log2SamplesPerPixel & 1;
    uint64_t dimensionBits = 0x55555555ULL * uint64_t(dimension);
    uint64_t sampleIndex = 0;
    for (int i = firstDigit; i >= lastDigit; --i) {
        int digitShift = 2 * i - (pow2Samples ? 1 : 0);
        int digit = int((mortonIndex >> digitShift) & 3);
        uint64_t higherDigits = mortonIndex >> (digitShift + 2);
        int p = int((MixBits(higherDigits ^ dimensionBits) >> 24) % 24);
        digit = kBase4Permutations[p][digit];
        sampleIndex |= uint64_t(digit) << digitShift;
    }
    return sampleIndex;
}

uint64_t ZSobolSampler::GetSampleIndex() const {
    bool pow2Samples = log2SamplesPerPixel & 1;
    int lastDigit = pow2Samples ? 1 : 0;
    // Digits i >= log4SamplesPerPixel lie above the sample number (their shift is at least
    // log2SamplesPerPixel), so they and the digits above them come from the pixel alone.
    int log4SamplesPerPixel = (log2SamplesPerPixel + 1) / 2;
    int firstLow = std::max(log4SamplesPerPixel, lastDigit) - 1;
    uint64_t high;
    if (dimension < kCachedDimensions && cacheGeneration[dimension] == generation) {
        high = cachedHighDigits[dimension];
    } else {
        // The pixel's lowest digit, and those above it from the 2x2 block's cache
        int pixelLow = firstLow + 1;
        if (dimension < kCachedDimensions && pixelLow + 1 <= nBase4Digits - 1) {
            uint64_t key = mortonIndex >> (2 * (pixelLow + 1) - (pow2Samples ? 1 : 0));
            if (blockKey[dimension] != key) {
                blockDigits[dimension] = PermutedDigits(nBase4Digits - 1, pixelLow + 1);
                blockKey[dimension] = key;
            }
            high = blockDigits[dimension] | PermutedDigits(pixelLow, pixelLow);
        } else {
            high = PermutedDigits(nBase4Digits - 1, pixelLow);
        }
        if (dimension < kCachedDimensions) {
            cachedHighDigits[dimension] = high;
            cacheGeneration[dimension] = generation;
        }
    }
    uint64_t sampleIndex = high | PermutedDigits(firstLow, lastDigit);
    // An odd power of two leaves one base-2 digit, flipped at random.
    if (pow2Samples) {
        uint64_t digit = mortonIndex & 1;
        sampleIndex |=
            digit ^ (MixBits((mortonIndex >> 1) ^ (0x55555555ULL * uint64_t(dimension))) & 1);
    }
    return sampleIndex;
}

Float ZSobolSampler::Get1D() {
    uint64_t sampleIndex = GetSampleIndex();
    ++dimension;
    uint32_t sampleHash = uint32_t(MixBits(uint64_t(dimension) ^ uint64_t(uint32_t(seed))));
    return SobolSample(sampleIndex, 0, randomize, sampleHash);
}

Point2f ZSobolSampler::Get2D() {
    uint64_t sampleIndex = GetSampleIndex();
    dimension += 2;
    uint64_t bits = MixBits(uint64_t(dimension) ^ uint64_t(uint32_t(seed)));
    return {SobolSample(sampleIndex, 0, randomize, uint32_t(bits)),
            SobolSample(sampleIndex, 1, randomize, uint32_t(bits >> 32))};
}

}  // namespace kiln
